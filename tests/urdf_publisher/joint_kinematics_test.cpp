// Every transform published for the shared real robots, in several joint configurations,
// against the test's own forward kinematics from the URDF's origins and axes.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "joint_state_helpers.hpp"
#include "lcmtf/buffer_core.hpp"
#include "lcmtf/message_conversions.hpp"
#include "lcmtf_urdf/joint_state_processor.hpp"
#include "lcmtf_urdf/robot_model.hpp"
#include "support/buffer_core_helpers.hpp"
#include "urdf_reference.hpp"

namespace lcmtf::urdf {
namespace {

using lcmtf_test::jointState;
using lcmtf_test::near;
using lcmtf_test::ReferenceJoint;
using lcmtf_test::ReferenceRobot;
using Positions = std::map<std::string, double>;

constexpr double kTolerance = 1e-9;
constexpr std::int64_t kStamp = 1'700'000'000'000'000;

std::string sharedRobot(const std::string& file) {
  return std::string(LCMTF_SHARED_URDF_DIR) + "/" + file;
}

struct Configuration {
  std::string label;
  Positions positions;
};

// Rest, both limits, and random positions within the limits; continuous joints also far
// beyond one turn either way.
std::vector<Configuration> configurations(const ReferenceRobot& robot) {
  std::vector<Configuration> result{{"zero", {}}, {"lower limits", {}}, {"upper limits", {}}};
  std::mt19937 random(7);
  for (int k = 0; k < 4; ++k) result.push_back({"random " + std::to_string(k), {}});
  for (const ReferenceJoint& joint : robot.joints()) {
    if (!joint.driven()) continue;
    const double lower = joint.has_limits ? joint.lower : -12.0;
    const double upper = joint.has_limits ? joint.upper : 12.0;
    result[0].positions[joint.name] = 0.0;
    result[1].positions[joint.name] = lower;
    result[2].positions[joint.name] = upper;
    for (std::size_t k = 3; k < result.size(); ++k) {
      result[k].positions[joint.name] =
          std::uniform_real_distribution<double>(lower, upper)(random);
    }
  }
  return result;
}

class RealRobotKinematics : public testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    path_ = sharedRobot(GetParam());
    if (!std::filesystem::exists(path_)) {
      GTEST_SKIP() << path_ << " is absent: the shared robots are not on this machine";
    }
  }
  std::string path_;
};

TEST_P(RealRobotKinematics, EveryPublishedTransformEqualsTheReferencePose) {
  const ReferenceRobot reference(path_);
  const RobotModel robot = loadRobotModel(path_);
  std::size_t movable = 0;
  for (const ReferenceJoint& joint : reference.joints()) movable += joint.movable() ? 1 : 0;

  for (const Configuration& configuration : configurations(reference)) {
    SCOPED_TRACE(configuration.label);
    JointStateProcessor processor(robot);
    const tf_message_t* batch = processor.process(jointState(kStamp, configuration.positions));
    ASSERT_NE(batch, nullptr);
    EXPECT_EQ(batch->transforms.size(), movable);
    for (const transform_t& published : batch->transforms) {
      const ReferenceJoint& joint = reference.jointToChild(published.child_frame);
      EXPECT_EQ(published.parent_frame, joint.parent);
      EXPECT_EQ(published.utime, kStamp);
      const Eigen::Isometry3d expected =
          ReferenceRobot::parentTChild(joint, reference.positionOf(joint, configuration.positions));
      EXPECT_TRUE(near(fromMessage(published).transform, expected, kTolerance)) << joint.name;
    }
  }
}

TEST_P(RealRobotKinematics, EveryFixedJointIsPublishedAsItsOrigin) {
  const ReferenceRobot reference(path_);
  const std::vector<TransformStamped> statics =
      fixedJointTransforms(loadRobotModel(path_), "", fromUtime(kStamp));
  std::size_t fixed = 0;
  for (const ReferenceJoint& joint : reference.joints()) fixed += joint.type == "fixed" ? 1 : 0;
  EXPECT_EQ(statics.size(), fixed);
  for (const TransformStamped& published : statics) {
    const ReferenceJoint& joint = reference.jointToChild(published.child_frame);
    EXPECT_EQ(joint.type, "fixed");
    EXPECT_EQ(published.parent_frame, joint.parent);
    EXPECT_TRUE(near(published.transform, ReferenceRobot::parentTChild(joint, 0.0), kTolerance))
        << joint.name;
  }
}

TEST_P(RealRobotKinematics, LookupsFromTheRootToEveryLinkEqualTheReferenceChain) {
  const ReferenceRobot reference(path_);
  const RobotModel robot = loadRobotModel(path_);
  for (const Configuration& configuration : configurations(reference)) {
    SCOPED_TRACE(configuration.label);
    BufferCore buffer;
    ASSERT_EQ(buffer.setTransforms(fixedJointTransforms(robot, ""), "test", true),
              robot.fixed_joints.size());
    JointStateProcessor processor(robot);
    for (const transform_t& published :
         processor.process(jointState(kStamp, configuration.positions))->transforms) {
      ASSERT_TRUE(buffer.setTransform(fromMessage(published), "test"));
    }
    for (const std::string& link : reference.links()) {
      EXPECT_TRUE(near(buffer.lookupTransform(reference.root(), link, fromUtime(kStamp)).transform,
                       reference.rootTLink(link, configuration.positions), kTolerance))
          << link;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SharedRobots, RealRobotKinematics,
                         testing::Values("r2d2_flexible.urdf", "ur5.urdf", "panda.urdf",
                                         "unitree_g1_29dof.urdf"),
                         [](const testing::TestParamInfo<const char*>& robot) {
                           const std::string file = robot.param;
                           return file.substr(0, file.find('.'));
                         });

TEST(ExampleRobotKinematics, TheDemoRobotsGripperFingersMirrorEachOther) {
  const std::string path = EXAMPLE_URDF;
  const ReferenceRobot reference(path);
  const RobotModel robot = loadRobotModel(path);
  JointStateProcessor processor(robot);
  Positions positions;
  for (const ReferenceJoint& joint : reference.joints()) {
    if (joint.driven()) positions[joint.name] = joint.has_limits ? 0.7 * joint.upper : 1.0;
  }
  const tf_message_t* batch = processor.process(jointState(kStamp, positions));
  ASSERT_NE(batch, nullptr);
  std::map<std::string, Transform> by_child;
  for (const transform_t& published : batch->transforms) {
    by_child[published.child_frame] = fromMessage(published).transform;
  }
  ASSERT_EQ(by_child.count("gripper_right_finger_link"), 1u);
  // 0.7 * 0.04 to the left, mirrored to the right, each 0.01 off the middle.
  EXPECT_NEAR(by_child["gripper_left_finger_link"].translation.y(), 0.01 + 0.028, kTolerance);
  EXPECT_NEAR(by_child["gripper_right_finger_link"].translation.y(), -0.01 - 0.028, kTolerance);
  for (const ReferenceJoint& joint : reference.joints()) {
    if (!joint.movable()) continue;
    EXPECT_TRUE(near(by_child[joint.child],
                     ReferenceRobot::parentTChild(joint, reference.positionOf(joint, positions)),
                     kTolerance))
        << joint.name;
  }
}

}  // namespace
}  // namespace lcmtf::urdf
