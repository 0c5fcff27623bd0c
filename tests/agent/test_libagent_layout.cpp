// AgentData is rUNSWift 2017's block byte for byte: the size and every
// field's offset as in rUNSWift 2017 release, robot/libagent (checked there by compiling the
// public release's declaration). If this fails, a team's unchanged robot
// program reads the wrong bytes.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <type_traits>

#include "common/libagent/AgentShared.hpp"
#include "common/libagent/CameraImages.hpp"
#include "common/libagent/SimExtension.hpp"

namespace al = common::libagent;

TEST(LibagentLayout, AgentDataIsThe2017BlockByteForByte) {
  EXPECT_EQ(sizeof(al::AgentData), 3284u);
  EXPECT_TRUE(std::is_standard_layout<al::AgentData>::value);
  EXPECT_EQ(offsetof(al::AgentData, sensors_read), 0u);
  EXPECT_EQ(offsetof(al::AgentData, sensors_latest), 1u);
  EXPECT_EQ(offsetof(al::AgentData, actuators_latest), 2u);
  EXPECT_EQ(offsetof(al::AgentData, actuators_read), 3u);
  EXPECT_EQ(offsetof(al::AgentData, sensors), 4u);
  EXPECT_EQ(offsetof(al::AgentData, buttons), 1888u);
  EXPECT_EQ(offsetof(al::AgentData, joints), 1892u);
  EXPECT_EQ(offsetof(al::AgentData, leds), 3092u);
  EXPECT_EQ(offsetof(al::AgentData, sonar), 3152u);
  EXPECT_EQ(offsetof(al::AgentData, stiffen), 3164u);
  EXPECT_EQ(offsetof(al::AgentData, sayTexts), 3176u);
  EXPECT_EQ(offsetof(al::AgentData, standing), 3281u);
  // Field sizes: 1-byte indices, three slots of each.
  EXPECT_EQ(sizeof(al::AgentData::sensors_latest), 1u);
  EXPECT_EQ(sizeof(al::AgentData::sensors), 3 * 628u);
  EXPECT_EQ(sizeof(al::AgentData::buttons), 3u);
  EXPECT_EQ(sizeof(al::AgentData::joints), 3 * 400u);
  EXPECT_EQ(sizeof(al::AgentData::leds), 3 * 20u);
  EXPECT_EQ(sizeof(al::AgentData::sonar), 12u);
  EXPECT_EQ(sizeof(al::AgentData::stiffen), 12u);
  EXPECT_EQ(sizeof(al::AgentData::sayTexts), 105u);
  EXPECT_EQ(sizeof(al::AgentData::standing), 1u);
}

TEST(LibagentLayout, SlotTypesMatchTheRelease) {
  // JointValues: angles, stiffnesses, temperatures, currents; 25 floats each.
  EXPECT_EQ(sizeof(al::JointValues), 400u);
  EXPECT_EQ(offsetof(al::JointValues, angles), 0u);
  EXPECT_EQ(offsetof(al::JointValues, stiffnesses), 100u);
  EXPECT_EQ(offsetof(al::JointValues, temperatures), 200u);
  EXPECT_EQ(offsetof(al::JointValues, currents), 300u);
  // SensorValues: joints, 37 sensors, 20 sonar echoes.
  EXPECT_EQ(sizeof(al::SensorValues), 628u);
  EXPECT_EQ(offsetof(al::SensorValues, joints), 0u);
  EXPECT_EQ(offsetof(al::SensorValues, sensors), 400u);
  EXPECT_EQ(offsetof(al::SensorValues, sonar), 548u);
  // LED: two 16-bit ear masks, then five RGB bool triples (19 bytes + 1 pad).
  EXPECT_EQ(sizeof(al::LedCommand), 20u);
  EXPECT_EQ(offsetof(al::LedCommand, left_ear), 0u);
  EXPECT_EQ(offsetof(al::LedCommand, right_ear), 2u);
  EXPECT_EQ(offsetof(al::LedCommand, left_eye), 4u);
  EXPECT_EQ(offsetof(al::LedCommand, right_eye), 7u);
  EXPECT_EQ(offsetof(al::LedCommand, chest), 10u);
  EXPECT_EQ(offsetof(al::LedCommand, left_foot), 13u);
  EXPECT_EQ(offsetof(al::LedCommand, right_foot), 16u);
  EXPECT_EQ(sizeof(al::Rgb), 3u);
  EXPECT_EQ(sizeof(al::ButtonPresses), 1u);
  EXPECT_EQ(sizeof(al::StiffenCommand), 4u);
  EXPECT_EQ(static_cast<int>(al::NONE), 0);
  EXPECT_EQ(static_cast<int>(al::STIFFEN), 1);
  EXPECT_EQ(al::kSayTextLength, 35);
}

// The slot orders the release uses (rUNSWift 2017 release, robot/libagent): a few landmarks.
TEST(LibagentLayout, JointAndSensorOrder) {
  namespace J = al::Joints;
  namespace S = al::Sensors;
  EXPECT_EQ(J::HeadYaw, 0);
  EXPECT_EQ(J::LHipYawPitch, 8);
  EXPECT_EQ(J::RHipRoll, 14);  // no RHipYawPitch slot
  EXPECT_EQ(J::RHand, 24);
  EXPECT_EQ(S::InertialSensor_AccZ, 2);
  EXPECT_EQ(S::LFoot_FSR_FrontLeft, 14);
  EXPECT_EQ(S::RFoot_FSR_FrontLeft, 20);
  EXPECT_EQ(S::ChestBoard_Button, 30);
  EXPECT_EQ(S::Battery_Charge, 34);
  EXPECT_EQ(S::US, 36);
}

// simswift's camera images block (not libagent's, but read the same way by a
// team's program): each camera's size, then the frame, then the buffers for
// the largest image (1280x960). A change here needs kExtensionVersion's bump.
TEST(LibagentLayout, CameraImagesHasASizePerCamera) {
  EXPECT_TRUE(std::is_standard_layout<al::CameraImages>::value);
  EXPECT_EQ(offsetof(al::CameraImages, magic), 0u);
  EXPECT_EQ(offsetof(al::CameraImages, size), 4u);
  EXPECT_EQ(sizeof(al::CameraImages::size), 16u);  // {width, height} x top, bottom
  EXPECT_EQ(offsetof(al::CameraImages, frame_index), 24u);
  EXPECT_EQ(offsetof(al::CameraImages, sim_time_us), 32u);
  EXPECT_EQ(offsetof(al::CameraImages, valid), 40u);
  EXPECT_EQ(offsetof(al::CameraImages, yuv422), 48u);
  EXPECT_EQ(offsetof(al::CameraImages, rgb), 48u + 2u * 1280 * 960 * 2);
  EXPECT_EQ(sizeof(al::CameraImages), 48u + 2u * 1280 * 960 * 5);
  EXPECT_EQ(al::kExtensionVersion, 5u);
  auto im = std::make_unique<al::CameraImages>();  // 12 MB: not on the stack
  im->size[0] = {1280, 960};
  im->size[1] = {640, 480};
  EXPECT_EQ(im->yuvBytes(0), 1280 * 960 * 2);
  EXPECT_EQ(im->rgbBytes(1), 640 * 480 * 3);
}
