#include "lcmtf/programs/closest_names.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace lcmtf::programs {
namespace {

using testing::ElementsAre;

std::vector<std::string> pr2Frames() {
  std::vector<std::string> frames;
  for (const char* side : {"l_", "r_"}) {
    for (const char* part :
         {"shoulder_pan_link", "shoulder_lift_link", "upper_arm_roll_link", "upper_arm_link",
          "elbow_flex_link", "forearm_roll_link", "forearm_link", "wrist_flex_link",
          "wrist_roll_link", "gripper_palm_link", "gripper_tool_frame", "gripper_l_finger_link",
          "gripper_r_finger_link", "gripper_motor_accelerometer_link", "forearm_cam_frame",
          "forearm_cam_optical_frame"}) {
      frames.push_back(std::string(side) + part);
    }
  }
  for (const char* frame : {"base_footprint", "base_link", "odom_combined", "torso_lift_link",
                            "head_pan_link", "head_tilt_link", "head_plate_frame"}) {
    frames.push_back(frame);
  }
  return frames;
}

TEST(EditDistance, CountsInsertionsDeletionsReplacementsAndSwaps) {
  EXPECT_EQ(editDistance("camera", "camera", 5), 0u);
  EXPECT_EQ(editDistance("camra", "camera", 5), 1u);
  EXPECT_EQ(editDistance("gripper_tpc", "gripper_tcp", 5), 1u);
  EXPECT_EQ(editDistance("base", "bass", 5), 1u);
  EXPECT_EQ(editDistance("", "abc", 5), 3u);
  EXPECT_EQ(editDistance("map", "odom_combined", 2), 3u) << "beyond the limit: limit + 1";
}

TEST(ClosestNames, TheNameMeantComesFirstHoweverLongTheList) {
  const std::vector<std::string> frames = pr2Frames();
  EXPECT_THAT(closestNames("r_gripper_tool_frme", frames, 1), ElementsAre("r_gripper_tool_frame"));
  EXPECT_EQ(didYouMean("r_gripper_tool_frme", frames), " (did you mean 'r_gripper_tool_frame'?)");
  EXPECT_EQ(didYouMean("gripper_tpc", {"gripper_tcp", "base_link"}),
            " (did you mean 'gripper_tcp'?)");
  EXPECT_EQ(didYouMean("map", {"odom", "base_link"}), "");
}

TEST(ClosestNames, APartOfANameIsTakenAsMeaningIt) {
  EXPECT_EQ(didYouMean("palm", {"l_gripper_palm_link", "r_gripper_palm_link", "base_link"}),
            " (did you mean 'l_gripper_palm_link' or 'r_gripper_palm_link'?)");
}

TEST(ListOfNames, ShortListsAreSortedLongOnesShowTheClosest) {
  EXPECT_EQ(listOfNames("map", {"odom", "base"}), "base, odom");
  const std::string list = listOfNames("r_gripper_tool_frme", pr2Frames(), 3);
  EXPECT_EQ(list.substr(0, list.find(',')), "r_gripper_tool_frame");
  EXPECT_THAT(list, testing::EndsWith("... (the 3 closest of 39)"));
}

}  // namespace
}  // namespace lcmtf::programs
