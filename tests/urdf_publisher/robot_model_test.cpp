// Reading a URDF into the model the publisher works from, and every way a URDF is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "lcmtf_urdf/robot_model.hpp"
#include "lcmtf_urdf/robot_summary.hpp"

namespace lcmtf::urdf {
namespace {

using testing::HasSubstr;

// A robot of two links joined by `joint_xml` (its <parent>/<child> added), plus `extra`.
std::string twoLinks(const std::string& joint_attributes, const std::string& joint_body,
                     const std::string& extra = "") {
  return "<robot name='r'><link name='a'/><link name='b'/>" + extra + "<joint name='j' " +
         joint_attributes + "><parent link='a'/><child link='b'/>" + joint_body +
         "</joint></robot>";
}

std::string refusal(const std::string& urdf) {
  try {
    parseRobotModel(urdf, "test.urdf");
  } catch (const UrdfError& e) {
    return e.what();
  }
  return "accepted";
}

std::string chainOfMimics(const std::string& mimics) {
  return "<robot name='r'><link name='a'/><link name='b'/><link name='c'/><link name='d'/>"
         "<joint name='j1' type='continuous'><parent link='a'/><child link='b'/></joint>"
         "<joint name='j2' type='continuous'><parent link='b'/><child link='c'/>" +
         mimics +
         "<joint name='j3' type='prismatic'><parent link='c'/><child link='d'/>"
         "<limit lower='-1' upper='1' effort='1' velocity='1'/>" +
         "</joint></robot>";
}

TEST(RobotModel, TheExampleRobotHasItsLinksJointsAndMimicFinger) {
  const RobotModel robot = loadRobotModel(EXAMPLE_URDF);
  EXPECT_EQ(robot.name, "mobile_manipulator");
  EXPECT_EQ(robot.source, EXAMPLE_URDF);
  EXPECT_EQ(robot.root_link, "odom");
  EXPECT_EQ(robot.links.size(), 26u);
  EXPECT_EQ(robot.movable_joints.size(), 15u);
  EXPECT_EQ(robot.fixed_joints.size(), 10u);
  EXPECT_TRUE(robot.unsupported_joints.empty());
  const MovableJoint* finger = robot.findMovableJoint("gripper_right_finger_joint");
  ASSERT_NE(finger, nullptr);
  ASSERT_TRUE(finger->resolved_mimic);
  EXPECT_EQ(finger->resolved_mimic->leader, "gripper_left_finger_joint");
  EXPECT_EQ(finger->resolved_mimic->multiplier, -1.0);
  EXPECT_EQ(finger->motion, JointMotion::kPrismatic);
  EXPECT_THAT(robot.urdf, HasSubstr("<robot name=\"mobile_manipulator\">"));
}

TEST(RobotModel, JointsComeInTreeOrderParentsBeforeChildren) {
  const RobotModel robot = loadRobotModel(EXAMPLE_URDF);
  EXPECT_EQ(robot.links.front(), "odom");
  std::vector<std::string> seen{robot.root_link};
  for (std::size_t i = 1; i < robot.links.size(); ++i) {
    std::string parent;
    for (const MovableJoint& joint : robot.movable_joints) {
      if (joint.child_link == robot.links[i]) parent = joint.parent_link;
    }
    for (const FixedJoint& joint : robot.fixed_joints) {
      if (joint.child_link == robot.links[i]) parent = joint.parent_link;
    }
    EXPECT_NE(std::find(seen.begin(), seen.end(), parent), seen.end())
        << robot.links[i] << " comes before its parent " << parent;
    seen.push_back(robot.links[i]);
  }
}

TEST(RobotModel, AxesAreNormalizedAndAbsentOnesPointAlongX) {
  const RobotModel scaled =
      parseRobotModel(twoLinks("type='continuous'", "<axis xyz='0 3 4'/>"), "t");
  EXPECT_TRUE(scaled.movable_joints[0].axis.isApprox(Eigen::Vector3d(0, 0.6, 0.8), 1e-15));
  const RobotModel absent = parseRobotModel(twoLinks("type='continuous'", ""), "t");
  EXPECT_EQ(absent.movable_joints[0].axis, Eigen::Vector3d::UnitX());
}

TEST(RobotModel, ContinuousJointsHaveNoLimitsRevoluteAndPrismaticDo) {
  const std::string limit = "<limit lower='-0.5' upper='1.5' effort='1' velocity='1'/>";
  EXPECT_FALSE(parseRobotModel(twoLinks("type='continuous'", limit), "t").movable_joints[0].limits);
  const RobotModel revolute = parseRobotModel(twoLinks("type='revolute'", limit), "t");
  ASSERT_TRUE(revolute.movable_joints[0].limits);
  EXPECT_EQ(revolute.movable_joints[0].limits->lower, -0.5);
  EXPECT_EQ(revolute.movable_joints[0].limits->upper, 1.5);
}

TEST(RobotModel, MimicWithoutMultiplierOrOffsetMeansOneAndZero) {
  const RobotModel robot = parseRobotModel(chainOfMimics("<mimic joint='j1'/></joint>"), "t");
  const MovableJoint* j2 = robot.findMovableJoint("j2");
  ASSERT_TRUE(j2 && j2->resolved_mimic);
  EXPECT_EQ(j2->resolved_mimic->leader, "j1");
  EXPECT_EQ(j2->resolved_mimic->multiplier, 1.0);
  EXPECT_EQ(j2->resolved_mimic->offset, 0.0);
}

TEST(RobotModel, MimicChainsResolveToTheJointAtTheirHead) {
  // j3 = 3 * j2 - 1 and j2 = 2 * j1 + 0.5, so j3 = 6 * j1 + 0.5.
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/><link name='d'/>"
      "<joint name='j1' type='continuous'><parent link='a'/><child link='b'/></joint>"
      "<joint name='j2' type='continuous'><parent link='b'/><child link='c'/>"
      "<mimic joint='j1' multiplier='2' offset='0.5'/></joint>"
      "<joint name='j3' type='continuous'><parent link='c'/><child link='d'/>"
      "<mimic joint='j2' multiplier='3' offset='-1'/></joint></robot>";
  const RobotModel robot = parseRobotModel(urdf, "t");
  const MovableJoint* j3 = robot.findMovableJoint("j3");
  ASSERT_TRUE(j3 && j3->resolved_mimic);
  EXPECT_EQ(j3->resolved_mimic->leader, "j1");
  EXPECT_DOUBLE_EQ(j3->resolved_mimic->multiplier, 6.0);
  EXPECT_DOUBLE_EQ(j3->resolved_mimic->offset, 0.5);
  EXPECT_EQ(j3->mimic->leader, "j2");
}

TEST(RobotModel, AMimicChainAsLongAsTheLinkLimitResolvesEveryJointToItsHead) {
  // j(k) = j(k-1) + 1 down a chain of 9,999 joints: each joint is resolved once, where walking
  // up from every joint anew would take over a minute.
  std::string urdf = "<robot name='r'><link name='l0'/>";
  constexpr int kJoints = 9'999;
  for (int k = 1; k <= kJoints; ++k) {
    const std::string n = std::to_string(k);
    urdf += "<link name='l" + n + "'/><joint name='j" + n + "' type='continuous'><parent link='l" +
            std::to_string(k - 1) + "'/><child link='l" + n + "'/>" +
            (k > 1 ? "<mimic joint='j" + std::to_string(k - 1) + "' offset='1'/>" : "") +
            "</joint>";
  }
  const RobotModel robot = parseRobotModel(urdf + "</robot>", "t");
  const MovableJoint* last = robot.findMovableJoint("j" + std::to_string(kJoints));
  ASSERT_TRUE(last && last->resolved_mimic);
  EXPECT_EQ(last->resolved_mimic->leader, "j1");
  EXPECT_EQ(last->resolved_mimic->multiplier, 1.0);
  EXPECT_EQ(last->resolved_mimic->offset, kJoints - 1.0);
}

TEST(RobotModel, FloatingAndPlanarJointsAreListedApartAndNotMovable) {
  const RobotModel floating = parseRobotModel(twoLinks("type='floating'", ""), "t");
  ASSERT_EQ(floating.unsupported_joints.size(), 1u);
  EXPECT_EQ(floating.unsupported_joints[0].type, "floating");
  EXPECT_TRUE(floating.movable_joints.empty());
  const RobotModel planar = parseRobotModel(twoLinks("type='planar'", ""), "t");
  ASSERT_EQ(planar.unsupported_joints.size(), 1u);
  EXPECT_EQ(planar.unsupported_joints[0].type, "planar");
}

TEST(RobotModel, SummaryTellsHowToPublishAFloatingJointYourself) {
  const RobotModel robot = parseRobotModel(twoLinks("type='floating'", ""), "t");
  const std::string summary = describeRobot(robot, "r1/");
  EXPECT_THAT(summary, HasSubstr("floating joint 'j' (r1/a -> r1/b) is not published"));
  EXPECT_THAT(summary, HasSubstr("Publish r1/a_T_r1/b on TF yourself"));
}

TEST(RobotModel, SummaryListsEveryJointWithItsFramesAndMimic) {
  const std::string summary = describeRobot(loadRobotModel(EXAMPLE_URDF), "", true);
  EXPECT_THAT(summary, HasSubstr("joints set by joint states: 14, mimic joints following them: 1, "
                                 "fixed joints published once as static transforms: 10"));
  EXPECT_THAT(summary, HasSubstr("prismatic gripper_right_finger_joint: gripper_base_link -> "
                                 "gripper_right_finger_link, axis [0 1 0], limits [-0.04, 0], "
                                 "follows -1 * gripper_left_finger_joint + 0"));
  EXPECT_THAT(summary,
              HasSubstr("fixed camera_optical_joint: camera_link -> camera_optical_frame"));
}

TEST(RobotModel, MissingFileIsRefusedNamingTheFile) {
  EXPECT_THAT(refusal(""), HasSubstr("empty"));
  try {
    loadRobotModel("/nonexistent/robot.urdf");
    FAIL() << "accepted a missing file";
  } catch (const UrdfError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/robot.urdf: cannot open: No such file or directory");
  }
}

TEST(RobotModel, ADirectoryIsRefusedNamingIt) {
  const std::string directory = testing::TempDir();
  try {
    loadRobotModel(directory);
    FAIL() << "accepted a directory";
  } catch (const UrdfError& e) {
    EXPECT_THAT(e.what(), HasSubstr(directory + ": cannot read"));
  }
}

TEST(RobotModel, XmlErrorIsRefusedNamingTheFileAndTheProblem) {
  const std::string path = testing::TempDir() + "/broken_xml.urdf";
  std::ofstream(path) << "<robot name='r'>\n  <link name='a'>\n</robot>\n";
  try {
    loadRobotModel(path);
    FAIL() << "accepted broken XML";
  } catch (const UrdfError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": malformed XML at line 3, column 1: Error reading end tag.");
  }
  std::remove(path.c_str());
  EXPECT_THAT(refusal("<robot name='r'><link name='a'>"), HasSubstr("test.urdf: malformed XML"));
  EXPECT_EQ(refusal("not xml at all"),
            "test.urdf: not XML: a URDF starts with '<', this starts with 'not xml at all'");
  EXPECT_EQ(refusal(std::string("\x7f"
                                "ELF\x02\x01",
                                6)),
            "test.urdf: not XML: a URDF starts with '<', this starts with '\\x7fELF\\x02\\x01'");
  EXPECT_THAT(refusal("<html/>"), HasSubstr("Could not find the 'robot' element"));
}

// The XML readers stop at the first NUL byte, so the rest of the text would be dropped unread.
TEST(RobotModel, NulByteIsRefusedAtItsPlaceRatherThanEndingTheText) {
  EXPECT_EQ(refusal(twoLinks("type='fixed'", "") + std::string("\n\0<junk", 7)),
            "test.urdf: not XML: a NUL byte at line 2, column 1 (XML text has none)");
  EXPECT_EQ(refusal(std::string("<robot name='r'>\n  <li\0nk name='a'/></robot>", 44)),
            "test.urdf: not XML: a NUL byte at line 2, column 6 (XML text has none)");
}

TEST(RobotModel, Utf16IsRefusedAskingForUtf8) {
  const std::string refused =
      "test.urdf: the text is UTF-16 or UTF-32, which TinyXML cannot read; save the URDF as UTF-8";
  EXPECT_EQ(refusal(std::string("\xFF\xFE<\0r\0o\0", 8)), refused);
  EXPECT_EQ(refusal(std::string("<\0r\0o\0", 6)), refused);
  EXPECT_EQ(refusal(std::string("\0<\0r", 4)), refused);
}

TEST(RobotModel, TwoRootsAreRefused) {
  EXPECT_THAT(refusal("<robot name='r'><link name='a'/><link name='b'/></robot>"),
              HasSubstr("test.urdf: invalid URDF: Failed to find root link: Two root links found"));
}

TEST(RobotModel, ZeroAxisIsRefusedNamingTheJoint) {
  EXPECT_EQ(
      refusal(twoLinks("type='continuous'", "<axis xyz='0 0 0'/>")),
      "test.urdf: joint 'j' has a zero axis (0 0 0): it cannot say which way the joint moves");
  EXPECT_THAT(refusal(twoLinks("type='prismatic'",
                               "<axis xyz='0 0 1e-300'/>"
                               "<limit lower='0' upper='1' effort='1' velocity='1'/>")),
              HasSubstr("joint 'j' has a zero axis"));
}

TEST(RobotModel, LowerLimitAboveUpperIsRefused) {
  EXPECT_EQ(
      refusal(twoLinks("type='revolute'", "<limit lower='1' upper='-1' effort='1' velocity='1'/>")),
      "test.urdf: joint 'j' has its lower limit 1 above its upper limit -1");
}

TEST(RobotModel, RevoluteJointWithoutLimitsIsRefused) {
  EXPECT_THAT(refusal(twoLinks("type='revolute'", "")),
              HasSubstr("Joint [j] is of type REVOLUTE but it does not specify limits"));
}

TEST(RobotModel, LinkWithTwoParentJointsIsRefused) {
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/>"
      "<joint name='j' type='fixed'><parent link='a'/><child link='b'/></joint>"
      "<joint name='k' type='fixed'><parent link='a'/><child link='b'/></joint></robot>";
  EXPECT_EQ(refusal(urdf), "test.urdf: link 'b' is the child of two joints, 'j' and 'k'");
}

TEST(RobotModel, LinksInALoopAwayFromTheRootAreRefused) {
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
      "<joint name='j' type='fixed'><parent link='b'/><child link='c'/></joint>"
      "<joint name='k' type='fixed'><parent link='c'/><child link='b'/></joint></robot>";
  EXPECT_EQ(refusal(urdf), "test.urdf: joints 'j' (b -> c), 'k' (c -> b) form a loop");
}

TEST(RobotModel, LoopOfJointsWithoutARootIsRefusedNamingThem) {
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
      "<joint name='ab' type='fixed'><parent link='a'/><child link='b'/></joint>"
      "<joint name='bc' type='continuous'><parent link='b'/><child link='c'/></joint>"
      "<joint name='ca' type='fixed'><parent link='c'/><child link='a'/></joint></robot>";
  EXPECT_EQ(refusal(urdf),
            "test.urdf: joints 'ab' (a -> b), 'bc' (b -> c), 'ca' (c -> a) form a loop");
}

TEST(RobotModel, EmptyJointNameIsRefused) {
  EXPECT_EQ(refusal("<robot name='r'><link name='a'/><link name='b'/><joint name='' "
                    "type='fixed'><parent link='a'/><child link='b'/></joint></robot>"),
            "test.urdf: a joint has an empty name");
}

TEST(RobotModel, LinksThatAreTheSameFrameAreRefused) {
  EXPECT_EQ(refusal("<robot name='r'><link name='/b'/><link name='b'/><joint name='j' "
                    "type='fixed'><parent link='/b'/><child link='b'/></joint></robot>"),
            "test.urdf: links '/b' and 'b' are the same frame 'b' (frame names drop one leading "
            "'/')");
  EXPECT_EQ(refusal("<robot name='r'><link name='/'/><link name='b'/><joint name='j' "
                    "type='fixed'><parent link='/'/><child link='b'/></joint></robot>"),
            "test.urdf: link '/' names no frame (frame names drop one leading '/')");
}

TEST(RobotModel, ALinkNameListenersWouldRefuseIsRefused) {
  const auto withChild = [](const std::string& child) {
    return "<robot name='r'><link name='a'/><link name='" + child +
           "'/><joint name='j' type='fixed'><parent link='a'/><child link='" + child +
           "'/></joint></robot>";
  };
  EXPECT_EQ(refusal(withChild(std::string(256, 'l'))), "accepted");
  EXPECT_EQ(refusal(withChild(std::string(257, 'l'))),
            "test.urdf: link '" + std::string(60, 'l') +
                "...' is 257 bytes long: listeners refuse a batch with a name "
                "longer than 256 bytes");
}

TEST(RobotModel, RobotAndJointNamesListenersWouldRefuseAreRefused) {
  const std::string longer(257, 'n');
  EXPECT_THAT(refusal("<robot name='" + longer + "'><link name='a'/></robot>"),
              HasSubstr("test.urdf: robot name 'nnn"));
  EXPECT_THAT(refusal("<robot name='r'><link name='a'/><link name='b'/><joint name='" + longer +
                      "' type='continuous'><parent link='a'/><child link='b'/></joint></robot>"),
              HasSubstr("test.urdf: joint 'nnn"));
}

TEST(RobotModel, AFramePrefixThatMakesALinkNameTooLongIsRefused) {
  const RobotModel robot = parseRobotModel(twoLinks("type='fixed'", ""), "test.urdf");
  EXPECT_NO_THROW(requireSendableNames(robot, std::string(255, 'p')));
  try {
    requireSendableNames(robot, std::string(256, 'p'));
    ADD_FAILURE() << "accepted";
  } catch (const UrdfError& e) {
    EXPECT_THAT(e.what(), HasSubstr("test.urdf: frame prefix and link 'ppp"));
    EXPECT_THAT(e.what(), HasSubstr("is 257 bytes long"));
  }
}

TEST(RobotModel, MimicOfAnUnknownJointIsRefused) {
  EXPECT_EQ(refusal(chainOfMimics("<mimic joint='nothing'/></joint>")),
            "test.urdf: joint 'j2' mimics 'nothing', which is not a joint of the robot");
}

TEST(RobotModel, MimicOfAFixedJointIsRefused) {
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
      "<joint name='f' type='fixed'><parent link='a'/><child link='b'/></joint>"
      "<joint name='m' type='continuous'><parent link='b'/><child link='c'/>"
      "<mimic joint='f'/></joint></robot>";
  EXPECT_EQ(refusal(urdf), "test.urdf: joint 'm' mimics 'f', a fixed joint, which has no position");
}

TEST(RobotModel, MimicCycleIsRefusedNamingEveryJointInIt) {
  const std::string urdf =
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/><link name='d'/>"
      "<joint name='j1' type='continuous'><parent link='a'/><child link='b'/>"
      "<mimic joint='j3'/></joint>"
      "<joint name='j2' type='continuous'><parent link='b'/><child link='c'/>"
      "<mimic joint='j1'/></joint>"
      "<joint name='j3' type='continuous'><parent link='c'/><child link='d'/>"
      "<mimic joint='j2'/></joint></robot>";
  EXPECT_EQ(refusal(urdf), "test.urdf: mimic joints form a loop: j1 -> j3 -> j2 -> j1");
}

TEST(RobotModel, JointMimickingItselfIsACycle) {
  EXPECT_EQ(refusal(chainOfMimics("<mimic joint='j2'/></joint>")),
            "test.urdf: mimic joints form a loop: j2 -> j2");
}

TEST(RobotModel, MimicChainThatOverflowsIsRefused) {
  std::string urdf = "<robot name='r'><link name='l0'/>";
  for (int i = 1; i <= 4; ++i) {
    const std::string n = std::to_string(i);
    urdf += "<link name='l" + n + "'/><joint name='j" + n + "' type='continuous'><parent link='l" +
            std::to_string(i - 1) + "'/><child link='l" + n + "'/>" +
            (i > 1 ? "<mimic joint='j" + std::to_string(i - 1) + "' multiplier='1e200'/>" : "") +
            "</joint>";
  }
  EXPECT_THAT(
      refusal(urdf + "</robot>"),
      HasSubstr("the mimic chain from joint 'j3' to 'j1' multiplies out to a value beyond"));
}

}  // namespace
}  // namespace lcmtf::urdf
