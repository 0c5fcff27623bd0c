// The libagent block of each rUNSWift release that targets the NAO V5, as
// the simulator serves it. The robot code's own block is the 2017 one
// (common/libagent/AgentShared.hpp); 2016 and 2018 differ only after the
// sonar commands (offsets from the public rUNSWift 2016, 2017 and 2018
// releases' AgentData.hpp, compiled on x86-64; i386 gives the same):
//
//   release  stiffen[3]  sayTexts[3][L]   standing  sizeof   names (simulation build)
//   2016     none        3164, L = 35     3269      3272     robot build only: bare, opened without O_CREAT
//   2017     3164        3176, L = 35     3281      3284     N = team x 11 + player
//   2018     3164        3176, L = 70     3386      3388     N = team x 6 + player
//
// Everything before offset 3164 (indices, sensors, buttons, joints, LEDs,
// sonar) is the same in all three. BodyHost runs one protocol over these
// structs (a template over the block type), not one copy per release.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/SharedNames.hpp"

namespace simswift::bridge {

enum class Release { R2016 = 2016, R2017 = 2017, R2018 = 2018 };

namespace release {
using common::libagent::ButtonPresses;
using common::libagent::JointValues;
using common::libagent::LedCommand;
using common::libagent::SensorValues;
using common::libagent::SonarMode;
using common::libagent::StiffenCommand;
constexpr int kSlots = common::libagent::kSlots;

// rUNSWift 2016: no stiffen requests.
struct AgentData2016 {
  volatile uint8_t sensors_read;
  volatile uint8_t sensors_latest;
  volatile uint8_t actuators_latest;
  volatile uint8_t actuators_read;
  SensorValues sensors[kSlots];
  ButtonPresses buttons[kSlots];
  JointValues joints[kSlots];
  LedCommand leds[kSlots];
  SonarMode sonar[kSlots];
  char sayTexts[kSlots][35];
  volatile bool standing;
};
static_assert(offsetof(AgentData2016, sonar) == 3152, "2016 sonar at 3152");
static_assert(offsetof(AgentData2016, sayTexts) == 3164, "2016 sayTexts at 3164");
static_assert(offsetof(AgentData2016, standing) == 3269, "2016 standing at 3269");
static_assert(sizeof(AgentData2016) == 3272, "the 2016 block is 3272 bytes");

using AgentData2017 = common::libagent::AgentData;
static_assert(offsetof(AgentData2017, stiffen) == 3164, "2017 stiffen at 3164");
static_assert(offsetof(AgentData2017, sayTexts) == 3176, "2017 sayTexts at 3176");
static_assert(offsetof(AgentData2017, standing) == 3281, "2017 standing at 3281");
static_assert(sizeof(AgentData2017) == 3284, "the 2017 block is 3284 bytes");

// rUNSWift 2018: say texts of 70 characters.
struct AgentData2018 {
  volatile uint8_t sensors_read;
  volatile uint8_t sensors_latest;
  volatile uint8_t actuators_latest;
  volatile uint8_t actuators_read;
  SensorValues sensors[kSlots];
  ButtonPresses buttons[kSlots];
  JointValues joints[kSlots];
  LedCommand leds[kSlots];
  SonarMode sonar[kSlots];
  StiffenCommand stiffen[kSlots];
  char sayTexts[kSlots][70];
  volatile bool standing;
};
static_assert(offsetof(AgentData2018, stiffen) == 3164, "2018 stiffen at 3164");
static_assert(offsetof(AgentData2018, sayTexts) == 3176, "2018 sayTexts at 3176");
static_assert(offsetof(AgentData2018, standing) == 3386, "2018 standing at 3386");
static_assert(sizeof(AgentData2018) == 3388, "the 2018 block is 3388 bytes");

// The part all three share ends where they start to differ.
static_assert(offsetof(AgentData2016, sonar) == offsetof(AgentData2017, sonar) &&
                  offsetof(AgentData2018, sonar) == offsetof(AgentData2017, sonar),
              "the releases share everything up to the sonar commands");

template <class Block>
constexpr bool hasStiffen() {
  return !std::is_same_v<Block, AgentData2016>;
}
template <class Block>
constexpr size_t sayLength() {
  return sizeof(Block::sayTexts[0]);
}

// Player numbers per team in the release's simulation-build name rule.
constexpr int kNameTeamFactor2018 = 6;  // rUNSWift 2018 MAX_NUM_PLAYERS
}  // namespace release

size_t blockSize(Release r);
int releaseYear(Release r);
// "2016", "2017", "2018" -> Release; false for anything else.
bool parseRelease(int year, Release* out);

// The release's names for one robot. 2016 has only the robot build (bare
// names); 2017 and 2018 have both (`bare` picks the robot build's).
common::libagent::RobotNames releaseNames(Release r, int team, int player, bool bare);

}  // namespace simswift::bridge
