#include "common/lola/Slots.hpp"

#include "common/libagent/AgentShared.hpp"

namespace common::lola {

namespace S = libagent::Sensors;

const std::array<int, kNumFsrs> kFsrSlots{
    S::LFoot_FSR_FrontLeft, S::LFoot_FSR_FrontRight, S::LFoot_FSR_RearLeft, S::LFoot_FSR_RearRight,
    S::RFoot_FSR_FrontLeft, S::RFoot_FSR_FrontRight, S::RFoot_FSR_RearLeft, S::RFoot_FSR_RearRight,
};

// In Touch's order: chest button; head front, middle, rear; left foot
// bumper left, right; left hand back, left, right; right foot bumper left,
// right; right hand back, left, right.
const std::array<int, kNumTouch> kTouchSlots{
    S::ChestBoard_Button, S::Head_Touch_Front, S::Head_Touch_Middle, S::Head_Touch_Rear,
    S::LFoot_Bumper_Left, S::LFoot_Bumper_Right, kNoSensorSlot, kNoSensorSlot, kNoSensorSlot,
    S::RFoot_Bumper_Left, S::RFoot_Bumper_Right, kNoSensorSlot, kNoSensorSlot, kNoSensorSlot,
};

const std::array<int, kNumBattery> kBatterySlots{S::Battery_Charge, kNoSensorSlot, S::Battery_Current, kNoSensorSlot};

const std::array<int, 2> kSonarEchoes{0, libagent::kNumSonars / 2};

}  // namespace common::lola
