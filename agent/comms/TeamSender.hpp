// Robot code: sends our SPL standard message at most every 1/rate_hz s
// (default 5 Hz, the SPL limit per robot). Called from the Perception thread
// (30 Hz); the caller fills the message's content, the sender sets the team
// and player numbers and decides whether this call sends.
#pragma once

#include <cstdint>

#include "agent/comms/SplMessage.hpp"
#include "agent/comms/TeamTransport.hpp"

namespace agent::comms {

class TeamSender {
 public:
  TeamSender(int team, int player, double rate_hz = 5.0);

  // True if the time has come (now_us - last send >= the period): then
  // serialises `content` with our team/player numbers and sends it.
  bool maybeSend(TeamTransport& transport, int64_t now_us, const SplMessage& content);
  // The same in two halves, for a caller that sends later (the robot
  // program puts the team outbox on its transport after the Perception
  // modules): the bytes to send if the time has come (empty otherwise; the
  // period restarts either way), then whether the transport took them.
  std::vector<uint8_t> nextPacket(int64_t now_us, const SplMessage& content);
  void recordSend(bool accepted) { ++(accepted ? sent_ : failed_); }
  bool due(int64_t now_us) const { return !tried_ || now_us - last_sent_us_ >= period_us_; }

  int64_t sent() const { return sent_; }
  int64_t failed() const { return failed_; }   // transport refused (e.g. outbox full)

 private:
  int team_, player_;
  int64_t period_us_;
  int64_t last_sent_us_ = 0;
  bool tried_ = false;
  int64_t sent_ = 0, failed_ = 0;
};

}  // namespace agent::comms
