// A LoLA server endpoint: the robot's side of one Unix stream socket. It
// listens at a path (LoLA's is /tmp/robocup), takes one client, and per
// cycle sends one 896-byte sensor packet and reads until the client's
// answer for that cycle (ActuatorDecoder.hpp says which maps make one).
//
// What happens when (docs/lola.md, "The server"):
// - no client: exchange() waits for one until the timeout (NoClient);
// - a new connection while one is open: the newest live one wins, the old
//   one is closed (a program restarted by hand reconnects at once); one
//   that has already hung up is closed and never replaces the client;
// - the socket is the server's while it holds the lock file beside it,
//   <socket>.lock (common/lock/PidLock.hpp): a second server, or `simswift
//   clean`, learns it is live from the lock, never by connecting;
// - the client closes its end: Disconnected; the next exchange() waits for
//   a new client, whose decoder starts afresh;
// - bad bytes or a map LoLA would not take: ProtocolError with the
//   decoder's message; the connection is closed (the stream cannot be
//   resynchronised), the client may reconnect;
// - the client stops reading: the packet is written whole or not at all
//   within the timeout; a client whose socket buffer stays full is closed
//   (Stalled), as rUNSWift notes LoLA ignores a client that stopped reading
//   until it reconnects.
// The timeout is wall-clock time: it decides only when to give up waiting,
// never what a cycle's answer is.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/lock/PidLock.hpp"
#include "sim/lola/ActuatorDecoder.hpp"
#include "sim/lola/SensorPacket.hpp"

namespace simswift::lola {

using Clock = std::chrono::steady_clock;

struct ServerError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Exchange {
  enum class Status {
    Answered,       // `command` holds the client's answer for this cycle
    NoClient,       // nobody connected within the timeout; no packet sent
    Timeout,        // packet sent, no complete answer within the timeout
    Disconnected,   // the client closed its end during this exchange
    ProtocolError,  // bad bytes from the client (`error`); connection closed
    Stalled,        // the client did not read: its buffer stayed full; connection closed
  };
  Status status = Status::NoClient;
  ActuatorCommand command;  // Answered only
  std::string error;        // ProtocolError, Stalled: why
  bool new_client = false;  // a client was accepted during this exchange
};
const char* toString(Exchange::Status status);

// The folder of the robots' sockets when a scenario names none
// (/tmp/simswift-lola/t<team>p<player>, sim/runner/Bodies.hpp). Every user
// shares it, as /tmp: it is made sticky and world-writable (01777), each
// socket and lock file in it belonging to the user whose run made it.
constexpr const char* kSharedSocketFolder = "/tmp/simswift-lola";

// Makes the folder `socket_path` lives in, if missing. The shared folder is
// made 01777 (mode set explicitly, whatever the umask; one this user owns
// with another mode, made by an older simswift, is set so); a shared folder
// that is no directory, or that another user owns with another mode, throws
// ServerError saying what to do. Other folders are made with the umask.
void makeSocketFolder(const std::string& socket_path);

// True if a live server serves the socket at `socket_path`: the socket is
// there and its server holds the lock beside it. Asked without connecting
// (`simswift attach` waits for it).
bool socketServed(const std::string& socket_path);

// LoLA sockets a killed run left among the entries of `folders` whose names
// start with `prefix`: removed (with their lock files), their paths
// returned. A live one, whose server holds the lock beside it, is left and
// never connected to (`simswift clean`).
std::vector<std::string> removeStaleSockets(const std::vector<std::string>& folders, const std::string& prefix);

class LolaServer {
 public:
  // Takes the lock beside `socket_path`, then binds and listens there (a
  // stale socket file there is replaced; any other file is refused). Throws
  // ServerError naming the path (and the live server's pid if it has one).
  explicit LolaServer(std::string socket_path, DecoderOptions decoder = {});
  ~LolaServer();  // closes both sockets and removes the socket file
  LolaServer(const LolaServer&) = delete;
  LolaServer& operator=(const LolaServer&) = delete;

  const std::string& path() const { return path_; }
  bool connected() const { return client_ >= 0; }
  int clientsAccepted() const { return accepted_; }

  // One cycle: accept a waiting client (the newest), send `packet`, read
  // until the cycle's answer. A client that answered ahead (its answer was
  // already decoded) gets the packet and that answer is returned at once.
  // A Timeout leaves the packet sent and unanswered: in lock-step the caller
  // goes on with awaitAnswer() (never a new exchange, whose packet would
  // take the late answer as its own and lag every later cycle by one).
  Exchange exchange(const PacketBytes& packet, std::chrono::milliseconds timeout);
  // Reads on for the answer to the packet sent last (after a Timeout).
  Exchange awaitAnswer(std::chrono::milliseconds timeout);

  // Accepts waiting connections without sending anything (newest wins).
  // true if a client is connected afterwards.
  bool acceptPending();
  // Closes the client's connection (the next exchange waits for a new one).
  void dropClient();

 private:
  void adopt(int fd);
  Exchange readAnswer(Exchange result, Clock::time_point deadline);
  std::string path_;
  int listener_ = -1;
  int client_ = -1;
  int accepted_ = 0;
  ActuatorDecoder decoder_;
  common::lock::PidLock lock_;  // <socket>.lock, held while this server lives
};

}  // namespace simswift::lola
