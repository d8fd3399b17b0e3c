// The joint publisher's positions: which joints, at rest, held, and sweeping within limits.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lcmtf_urdf/joint_state_generator.hpp"

namespace lcmtf::urdf {
namespace {

using testing::Contains;
using testing::HasSubstr;
using testing::Not;

constexpr std::int64_t kStamp = 1'700'000'000'000'000;

class JointStateGeneratorTest : public testing::Test {
 protected:
  double positionOf(const joint_state_t& state, const std::string& joint) const {
    for (std::size_t i = 0; i < state.name.size(); ++i) {
      if (state.name[i] == joint) return state.position[i];
    }
    ADD_FAILURE() << "no joint " << joint;
    return NAN;
  }

  std::string heldRefusal(const std::string& joint, double position) const {
    JointStateGeneratorOptions options;
    options.held = {{joint, position}};
    try {
      JointStateGenerator generator(robot, options);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  }

  const RobotModel robot = loadRobotModel(EXAMPLE_URDF);
};

TEST_F(JointStateGeneratorTest, EveryMovableJointIsPublishedTheMimicJointsLast) {
  const JointStateGenerator generator(robot);
  EXPECT_EQ(generator.jointNames().size(), 15u);
  EXPECT_EQ(generator.mimicCount(), 1u);
  EXPECT_THAT(generator.jointNames(), Contains("gripper_left_finger_joint"));
  EXPECT_EQ(generator.jointNames().back(), "gripper_right_finger_joint");
  EXPECT_THAT(generator.jointNames(), Not(Contains("camera_joint")));
}

// As joint_state_publisher does: a mimic joint is published at the position its leader gives.
TEST_F(JointStateGeneratorTest, MimicJointsFollowTheirLeadersInEveryState) {
  JointStateGeneratorOptions options;
  options.sweep = true;
  const JointStateGenerator generator(robot, options);
  const auto index = [&](const std::string& name) {
    const auto& names = generator.jointNames();
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (double t : {0.0, 0.7, 3.1}) {
    const joint_state_t state = generator.stateAt(t, fromUtime(kStamp));
    const std::size_t left = index("gripper_left_finger_joint");
    const std::size_t right = index("gripper_right_finger_joint");
    EXPECT_EQ(state.position[right], -state.position[left]) << t;
    EXPECT_EQ(state.velocity[right], -state.velocity[left]) << t;
  }
}

TEST_F(JointStateGeneratorTest, StatesAreCompleteAndStamped) {
  const joint_state_t state = JointStateGenerator(robot).stateAt(1.0, fromUtime(kStamp));
  EXPECT_EQ(state.utime, kStamp);
  EXPECT_EQ(state.num_joints, 15);
  EXPECT_EQ(state.num_positions, 15);
  EXPECT_EQ(state.num_velocities, 15);
  EXPECT_EQ(state.num_efforts, 0);
  EXPECT_EQ(state.name.size(), 15u);
  EXPECT_EQ(state.position.size(), 15u);
  EXPECT_EQ(state.velocity.size(), 15u);
}

TEST_F(JointStateGeneratorTest, RestIsZeroOrTheMiddleOfLimitsThatExcludeZero) {
  const RobotModel panda_like = parseRobotModel(
      "<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
      "<joint name='inside' type='revolute'><parent link='a'/><child link='b'/>"
      "<limit lower='-1' upper='2' effort='1' velocity='1'/></joint>"
      "<joint name='outside' type='revolute'><parent link='b'/><child link='c'/>"
      "<limit lower='-3.0718' upper='-0.0698' effort='1' velocity='1'/></joint></robot>",
      "t");
  const joint_state_t state = JointStateGenerator(panda_like).stateAt(5.0, fromUtime(kStamp));
  EXPECT_EQ(positionOf(state, "inside"), 0.0);
  EXPECT_DOUBLE_EQ(positionOf(state, "outside"), 0.5 * (-3.0718 - 0.0698));
  for (double velocity : state.velocity) EXPECT_EQ(velocity, 0.0);
}

TEST_F(JointStateGeneratorTest, SweepStaysWithinLimitsAndCoversMostOfThem) {
  JointStateGeneratorOptions options;
  options.sweep = true;
  options.sweep_period = 2.0;
  const JointStateGenerator generator(robot, options);
  std::map<std::string, std::pair<double, double>> seen;
  for (int k = 0; k <= 2000; ++k) {
    const joint_state_t state = generator.stateAt(0.005 * k, fromUtime(kStamp));
    for (std::size_t i = 0; i < state.name.size(); ++i) {
      const MovableJoint& joint = *robot.findMovableJoint(state.name[i]);
      auto& [low, high] = seen.try_emplace(joint.name, INFINITY, -INFINITY).first->second;
      low = std::min(low, state.position[i]);
      high = std::max(high, state.position[i]);
      if (joint.limits) {
        ASSERT_GE(state.position[i], joint.limits->lower) << joint.name;
        ASSERT_LE(state.position[i], joint.limits->upper) << joint.name;
      }
    }
  }
  for (const auto& [name, range] : seen) {
    const MovableJoint& joint = *robot.findMovableJoint(name);
    if (joint.limits) {
      EXPECT_GT(range.second - range.first, 0.95 * (joint.limits->upper - joint.limits->lower))
          << name;
    } else {
      EXPECT_GT(range.second - range.first, 4 * M_PI) << name << " should turn round and round";
    }
  }
}

TEST_F(JointStateGeneratorTest, SweepIsSmoothAndItsVelocitiesAreTheDerivative) {
  JointStateGeneratorOptions options;
  options.sweep = true;
  const JointStateGenerator generator(robot, options);
  const double dt = 1e-4;
  for (double t : {0.0, 1.3, 7.9, 100.0}) {
    const joint_state_t before = generator.stateAt(t, fromUtime(kStamp));
    const joint_state_t after = generator.stateAt(t + dt, fromUtime(kStamp));
    for (std::size_t i = 0; i < before.name.size(); ++i) {
      const double mean_velocity = 0.5 * (before.velocity[i] + after.velocity[i]);
      EXPECT_NEAR((after.position[i] - before.position[i]) / dt, mean_velocity, 1e-6)
          << before.name[i] << " at " << t;
      EXPECT_NE(before.velocity[i], 0.0) << before.name[i] << " does not move";
    }
  }
}

TEST_F(JointStateGeneratorTest, HeldJointsStayPutWhileOthersSweep) {
  JointStateGeneratorOptions options;
  options.sweep = true;
  options.held = {{"elbow_joint", 1.25}, {"base_yaw_joint", -7.0}};
  const JointStateGenerator generator(robot, options);
  for (double t : {0.0, 0.7, 3.3}) {
    const joint_state_t state = generator.stateAt(t, fromUtime(kStamp));
    EXPECT_EQ(positionOf(state, "elbow_joint"), 1.25);
    EXPECT_EQ(positionOf(state, "base_yaw_joint"), -7.0);
  }
}

TEST_F(JointStateGeneratorTest, HoldingAJointThatCannotBeHeldIsRefused) {
  EXPECT_EQ(heldRefusal("nothing", 0.0),
            "robot 'mobile_manipulator' has no movable joint 'nothing'");
  EXPECT_EQ(heldRefusal("camera_joint", 0.0),
            "robot 'mobile_manipulator' has no movable joint 'camera_joint'");
  EXPECT_EQ(heldRefusal("gripper_right_finger_joint", -0.01),
            "joint 'gripper_right_finger_joint' is a mimic joint: it follows "
            "'gripper_left_finger_joint'");
  EXPECT_EQ(heldRefusal("elbow_joint", 3.0),
            "joint 'elbow_joint' cannot be held at 3, outside its limits [-2.6, 2.6]");
  EXPECT_THAT(heldRefusal("elbow_joint", NAN), HasSubstr("cannot be held at nan"));
}

TEST_F(JointStateGeneratorTest, NonPositiveSweepPeriodIsRefused) {
  JointStateGeneratorOptions options;
  options.sweep_period = 0.0;
  EXPECT_THROW(JointStateGenerator(robot, options), std::invalid_argument);
}

}  // namespace
}  // namespace lcmtf::urdf
