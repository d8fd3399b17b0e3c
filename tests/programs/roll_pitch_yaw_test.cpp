#include "lcmtf/programs/roll_pitch_yaw.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lcmtf::programs {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Rz(yaw) Ry(pitch) Rx(roll) written out from the elementary rotation matrices.
Eigen::Matrix3d fixedAxesMatrix(double roll, double pitch, double yaw) {
  Eigen::Matrix3d rx, ry, rz;
  rx << 1, 0, 0, 0, std::cos(roll), -std::sin(roll), 0, std::sin(roll), std::cos(roll);
  ry << std::cos(pitch), 0, std::sin(pitch), 0, 1, 0, -std::sin(pitch), 0, std::cos(pitch);
  rz << std::cos(yaw), -std::sin(yaw), 0, std::sin(yaw), std::cos(yaw), 0, 0, 0, 1;
  return rz * ry * rx;
}

TEST(RollPitchYaw, QuaternionIsYawThenPitchThenRollAboutFixedAxes) {
  for (double roll : {-2.9, -0.4, 0.0, 1.1}) {
    for (double pitch : {-1.2, 0.0, 0.3, 1.5}) {
      for (double yaw : {-3.0, 0.0, 0.7, 2.2}) {
        const Eigen::Quaterniond q = toQuaternion({roll, pitch, yaw});
        EXPECT_NEAR(q.norm(), 1.0, 1e-15);
        EXPECT_LT((q.toRotationMatrix() - fixedAxesMatrix(roll, pitch, yaw)).cwiseAbs().maxCoeff(),
                  1e-14)
            << roll << " " << pitch << " " << yaw;
      }
    }
  }
}

TEST(RollPitchYaw, AnglesRoundTripAwayFromGimbalLock) {
  for (double roll = -3.1; roll < 3.14; roll += 0.37) {
    for (double pitch = -1.55; pitch < 1.56; pitch += 0.31) {
      for (double yaw = -3.1; yaw < 3.14; yaw += 0.41) {
        const RollPitchYaw angles = toRollPitchYaw(toQuaternion({roll, pitch, yaw}));
        EXPECT_NEAR(angles.roll, roll, 1e-9);
        EXPECT_NEAR(angles.pitch, pitch, 1e-9);
        EXPECT_NEAR(angles.yaw, yaw, 1e-9);
      }
    }
  }
}

TEST(RollPitchYaw, GimbalLockGivesTheSameRotationWithYawZero) {
  for (double pitch : {kPi / 2, -kPi / 2}) {
    for (double roll : {-1.0, 0.2, 2.5}) {
      for (double yaw : {-0.7, 0.0, 1.3}) {
        const Eigen::Quaterniond q = toQuaternion({roll, pitch, yaw});
        const RollPitchYaw angles = toRollPitchYaw(q);
        EXPECT_NEAR(angles.pitch, pitch, 1e-7);
        EXPECT_EQ(angles.yaw, 0.0);
        EXPECT_LT(q.angularDistance(toQuaternion(angles)), 1e-7) << roll << " " << yaw;
      }
    }
  }
}

TEST(RollPitchYaw, QuarterTurnAboutZIsYaw) {
  const RollPitchYaw angles =
      toRollPitchYaw(Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ())));
  EXPECT_NEAR(angles.roll, 0.0, 1e-15);
  EXPECT_NEAR(angles.pitch, 0.0, 1e-15);
  EXPECT_NEAR(angles.yaw, kPi / 2, 1e-15);
}

TEST(RollPitchYaw, NonUnitQuaternionIsReadAsItsRotation) {
  const Eigen::Quaterniond scaled(Eigen::Vector4d(toQuaternion({0.1, 0.2, 0.3}).coeffs() * 3.0));
  const RollPitchYaw angles = toRollPitchYaw(scaled);
  EXPECT_NEAR(angles.roll, 0.1, 1e-12);
  EXPECT_NEAR(angles.pitch, 0.2, 1e-12);
  EXPECT_NEAR(angles.yaw, 0.3, 1e-12);
}

}  // namespace
}  // namespace lcmtf::programs
