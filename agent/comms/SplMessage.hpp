// The SPL standard message of 2017 (struct version 6) as plain C++ values,
// and its wire form as bytes.
//
// Wire layout (little-endian, the NAO's x86; the C struct's natural
// alignment, which puts every field on its own boundary without padding
// until the end). Offsets in bytes:
//    0 header[4]            "SPL "
//    4 version   uint8      6
//    5 playerNum int8       1..5
//    6 teamNum   int8       team number
//    7 fallen    int8       1 fallen, 0 can play
//    8 pose      float[3]   x mm, y mm, theta rad (field frame, own goal at -x)
//   20 walkingTo float[2]   mm, field frame
//   28 shootingTo float[2]  mm, field frame
//   36 ballAge   float      s since the ball was last seen, -1 = never
//   40 ball      float[2]   mm, robot-relative (x forward, y left)
//   48 ballVel   float[2]   mm/s, robot-relative
//   56 suggestion int8[5]   per teammate (player number - 1)
//   61 intention int8
//   62 averageWalkSpeed int16   mm/s
//   64 maxKickDistance  int16   mm
//   66 currentPositionConfidence int8  percent
//   67 currentSideConfidence     int8  percent
//   68 numOfDataBytes   uint16
//   70 data[780]             the team's own bytes (only numOfDataBytes sent)
// sizeof(the C struct) = 852 (850 rounded up to float alignment).
//
// A packet on the wire is the 70-byte head plus numOfDataBytes of data
// (serialise() writes exactly that); parse() also accepts the padded whole
// struct, as a team sending sizeof(struct) would produce.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace agent::comms {

constexpr char kSplHeader[4] = {'S', 'P', 'L', ' '};
constexpr uint8_t kSplVersion = 6;
constexpr int kSplMaxPlayers = 5;        // suggestion[] entries; player numbers 1..5
constexpr size_t kSplDataSize = 780;     // bytes in the free data area
constexpr size_t kSplHeadBytes = 70;     // everything before data[]
constexpr size_t kSplMaxPacketBytes = 852;  // sizeof the C struct (padded)

// One message. Units as on the wire (mm, mm/s, rad, s, percent).
struct SplMessage {
  int player = 1;          // 1..kSplMaxPlayers
  int team = 0;            // team number (int8 on the wire: 0..127)
  bool fallen = false;
  float pose_x = 0, pose_y = 0, pose_theta = 0;    // mm, mm, rad; field frame
  float walking_to_x = 0, walking_to_y = 0;        // mm; field frame
  float shooting_to_x = 0, shooting_to_y = 0;      // mm; field frame
  float ball_age = -1;                             // s; -1 = never seen
  float ball_x = 0, ball_y = 0;                    // mm; robot-relative
  float ball_vel_x = 0, ball_vel_y = 0;            // mm/s; robot-relative
  std::array<int8_t, kSplMaxPlayers> suggestion{{-1, -1, -1, -1, -1}};
  int8_t intention = 0;
  int16_t average_walk_speed = -1;                 // mm/s
  int16_t max_kick_distance = -1;                  // mm
  int8_t position_confidence = -1;                 // percent 0..100, -1 unknown
  int8_t side_confidence = -1;                     // percent 0..100, -1 unknown
  std::vector<uint8_t> data;                       // the robot code's own bytes, <= kSplDataSize

  bool operator==(const SplMessage& o) const;
};

enum class ParseError {
  None = 0,
  TooShort,       // fewer bytes than the head, or than head + numOfDataBytes
  TooLong,        // more bytes than the C struct holds
  BadHeader,      // not "SPL "
  BadVersion,     // not 6
  BadDataSize,    // numOfDataBytes > kSplDataSize
  BadPlayer,      // player number outside 1..5
  BadTeam,        // negative team number
  BadFallen,      // fallen not 0 or 1
  NonFinite,      // a float field is NaN or infinite
};
const char* parseErrorName(ParseError e);

struct ParseResult {
  ParseError error = ParseError::None;
  SplMessage message;  // valid only when ok()
  bool ok() const { return error == ParseError::None; }
};

// Bytes of `m` (kSplHeadBytes + m.data.size()). Values outside the wire
// types' ranges are a programming error: throws std::invalid_argument
// (data longer than kSplDataSize, player outside 1..5, team outside 0..127).
std::vector<uint8_t> serialise(const SplMessage& m);

// Never throws and never reads outside [bytes, bytes + size).
ParseResult parse(const uint8_t* bytes, size_t size);
inline ParseResult parse(const std::vector<uint8_t>& b) { return parse(b.data(), b.size()); }

}  // namespace agent::comms
