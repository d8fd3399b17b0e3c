#include "lcmtf/do_transform.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "lcmtf/buffer.hpp"

namespace lcmtf {
namespace {

using testing::HasSubstr;

constexpr double kTolerance = 1e-12;

Transform randomTransform(std::mt19937_64& random) {
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  return Transform(Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random)),
                   Eigen::Quaterniond::UnitRandom());
}

Eigen::Vector3d randomVector(std::mt19937_64& random) {
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  return Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random));
}

// Each case: two random transforms a_T_b and b_T_c and a random value in c.
class DoTransformProperties : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    random.seed(static_cast<std::uint64_t>(GetParam()));
    a_T_b = randomTransform(random);
    b_T_c = randomTransform(random);
  }
  std::mt19937_64 random;
  Transform a_T_b;
  Transform b_T_c;
};

TEST_P(DoTransformProperties, PointRoundTripsAndComposes) {
  const Eigen::Vector3d p = randomVector(random);
  EXPECT_LE((transformed(b_T_c.inverse(), transformed(b_T_c, p)) - p).norm(), kTolerance);
  EXPECT_LE((transformed(a_T_b * b_T_c, p) - transformed(a_T_b, transformed(b_T_c, p))).norm(),
            1e-11);
  EXPECT_LE((transformed(b_T_c, p) - b_T_c.toIsometry() * p).norm(), 1e-11);
}

TEST_P(DoTransformProperties, DirectionIsOnlyRotated) {
  const Direction d{randomVector(random)};
  EXPECT_LE((transformed(b_T_c.inverse(), transformed(b_T_c, d)).value - d.value).norm(),
            kTolerance);
  EXPECT_LE((transformed(a_T_b * b_T_c, d).value - transformed(a_T_b, transformed(b_T_c, d)).value)
                .norm(),
            1e-11);
  EXPECT_LE((transformed(b_T_c, d).value - b_T_c.rotation.toRotationMatrix() * d.value).norm(),
            1e-12);
}

TEST_P(DoTransformProperties, OrientationRoundTripsAndComposes) {
  const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
  EXPECT_LE(angularDistance(transformed(b_T_c.inverse(), transformed(b_T_c, q)), q), kTolerance);
  EXPECT_LE(
      angularDistance(transformed(a_T_b * b_T_c, q), transformed(a_T_b, transformed(b_T_c, q))),
      1e-11);
}

TEST_P(DoTransformProperties, PosesRoundTripAndCompose) {
  const Transform pose = randomTransform(random);
  EXPECT_TRUE(transformed(b_T_c.inverse(), transformed(b_T_c, pose)).isApprox(pose, 1e-11));
  EXPECT_TRUE(transformed(a_T_b * b_T_c, pose)
                  .isApprox(transformed(a_T_b, transformed(b_T_c, pose)), 1e-11));
  const Eigen::Isometry3d iso = pose.toIsometry();
  EXPECT_TRUE(transformed(b_T_c.inverse(), transformed(b_T_c, iso)).isApprox(iso, 1e-11));
  EXPECT_TRUE(transformed(b_T_c, iso).isApprox(b_T_c.toIsometry() * iso, 1e-11));
}

TEST_P(DoTransformProperties, CloudsMatchPointByPoint) {
  Eigen::Matrix3Xd matrix(3, 50);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 50; ++i) {
    points.push_back(randomVector(random));
    matrix.col(i) = points.back();
  }
  const Eigen::Matrix3Xd moved_matrix = transformed(b_T_c, matrix);
  const std::vector<Eigen::Vector3d> moved_points = transformed(b_T_c, points);
  const Eigen::Matrix3Xd back = transformed(b_T_c.inverse(), moved_matrix);
  const Eigen::Matrix3Xd twice = transformed(a_T_b, moved_matrix);
  const Eigen::Matrix3Xd once = transformed(a_T_b * b_T_c, matrix);
  ASSERT_EQ(moved_points.size(), points.size());
  for (int i = 0; i < 50; ++i) {
    const auto index = static_cast<std::size_t>(i);
    EXPECT_LE((moved_matrix.col(i) - transformed(b_T_c, points[index])).norm(), 1e-12);
    EXPECT_LE((moved_points[index] - transformed(b_T_c, points[index])).norm(), 1e-12);
    EXPECT_LE((back.col(i) - matrix.col(i)).norm(), 1e-11);
    EXPECT_LE((twice.col(i) - once.col(i)).norm(), 1e-11);
  }
}

TEST_P(DoTransformProperties, CloudInCallersMemoryMatchesTheReturnedCloud) {
  std::vector<double> xyz(3 * 20);
  for (double& coordinate : xyz) coordinate = randomVector(random).x();
  const Eigen::Map<const Eigen::Matrix3Xd> cloud(xyz.data(), 3, 20);
  std::vector<double> out(xyz.size());
  Eigen::Map<Eigen::Matrix3Xd> result(out.data(), 3, 20);
  transformCloud(b_T_c, cloud, result);
  EXPECT_EQ(result, transformed(b_T_c, Eigen::Matrix3Xd(cloud)));
}

TEST(DoTransform, CloudIntoResultOfAnotherSizeThrows) {
  const Eigen::Matrix3Xd cloud = Eigen::Matrix3Xd::Zero(3, 4);
  Eigen::Matrix3Xd result(3, 3);
  EXPECT_THROW(transformCloud(Transform(), cloud, result), std::invalid_argument);
}

TEST_P(DoTransformProperties, TwistRoundTripsComposesAndMatchesTheRigidBodyFormula) {
  const Twist twist{randomVector(random), randomVector(random)};
  const Twist back = transformed(b_T_c.inverse(), transformed(b_T_c, twist));
  EXPECT_LE((back.linear - twist.linear).norm(), 1e-11);
  EXPECT_LE((back.angular - twist.angular).norm(), 1e-11);
  const Twist twice = transformed(a_T_b, transformed(b_T_c, twist));
  const Twist once = transformed(a_T_b * b_T_c, twist);
  EXPECT_LE((twice.linear - once.linear).norm(), 1e-10);
  EXPECT_LE((twice.angular - once.angular).norm(), 1e-11);

  // The body point at b's origin sits at r = c_T_b.translation in c; its velocity there is
  // v + w x r in c, and rotating that into b gives the linear part of the result.
  const Eigen::Matrix3d R = b_T_c.rotation.toRotationMatrix();
  const Eigen::Vector3d r = b_T_c.inverse().translation;
  const Twist in_b = transformed(b_T_c, twist);
  EXPECT_LE((in_b.linear - R * (twist.linear + twist.angular.cross(r))).norm(), 1e-11);
  EXPECT_LE((in_b.angular - R * twist.angular).norm(), 1e-12);
}

TEST_P(DoTransformProperties, WrenchRoundTripsComposesAndMatchesTheMomentFormula) {
  const Wrench wrench{randomVector(random), randomVector(random)};
  const Wrench back = transformed(b_T_c.inverse(), transformed(b_T_c, wrench));
  EXPECT_LE((back.force - wrench.force).norm(), 1e-11);
  EXPECT_LE((back.torque - wrench.torque).norm(), 1e-10);
  const Wrench twice = transformed(a_T_b, transformed(b_T_c, wrench));
  const Wrench once = transformed(a_T_b * b_T_c, wrench);
  EXPECT_LE((twice.force - once.force).norm(), 1e-11);
  EXPECT_LE((twice.torque - once.torque).norm(), 1e-10);

  // Torque about b's origin: the torque about c's origin plus (c's origin - b's origin) x F,
  // everything in b's axes.
  const Eigen::Matrix3d R = b_T_c.rotation.toRotationMatrix();
  const Wrench in_b = transformed(b_T_c, wrench);
  EXPECT_LE((in_b.force - R * wrench.force).norm(), 1e-12);
  EXPECT_LE((in_b.torque - (R * wrench.torque + b_T_c.translation.cross(R * wrench.force))).norm(),
            1e-11);
}

TEST_P(DoTransformProperties, CovarianceIsRotatedAsJSigmaJTransposed) {
  Eigen::Matrix<double, 6, 6> root = Eigen::Matrix<double, 6, 6>::Random();
  const PoseWithCovariance pose{randomTransform(random), root * root.transpose()};
  const PoseWithCovariance moved = transformed(b_T_c, pose);

  Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      J(row, col) = b_T_c.rotation.toRotationMatrix()(row, col);
      J(row + 3, col + 3) = J(row, col);
    }
  }
  Eigen::Matrix<double, 6, 6> expected = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      for (int k = 0; k < 6; ++k) {
        for (int l = 0; l < 6; ++l) expected(i, j) += J(i, k) * pose.covariance(k, l) * J(j, l);
      }
    }
  }
  EXPECT_LE((moved.covariance - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_TRUE(moved.pose.isApprox(b_T_c * pose.pose, 1e-12));
  const PoseWithCovariance back = transformed(b_T_c.inverse(), moved);
  EXPECT_LE((back.covariance - pose.covariance).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LE((moved.covariance - moved.covariance.transpose()).cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Random, DoTransformProperties, ::testing::Range(1, 21));

TEST(DoTransform, TwistOfASpinningBodySeenFromAnOffsetFrame) {
  // A body spins at 1 rad/s about z with its centre still. Frame b's origin is 1 m along x
  // from the centre, so the body point there moves at 1 m/s along y.
  const Twist at_centre{Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1)};
  const Transform b_T_centre(Eigen::Vector3d(-1, 0, 0), Eigen::Quaterniond::Identity());
  const Twist at_b = transformed(b_T_centre, at_centre);
  EXPECT_LE((at_b.linear - Eigen::Vector3d(0, 1, 0)).norm(), kTolerance);
  EXPECT_LE((at_b.angular - Eigen::Vector3d(0, 0, 1)).norm(), kTolerance);
}

TEST(DoTransform, WrenchOfAWeightOnALeverArm) {
  // 10 N straight down at the tip of a 2 m arm along x: 20 N m about -y at the shoulder.
  const Wrench at_tip{Eigen::Vector3d(0, 0, -10), Eigen::Vector3d::Zero()};
  const Transform shoulder_T_tip(Eigen::Vector3d(2, 0, 0), Eigen::Quaterniond::Identity());
  const Wrench at_shoulder = transformed(shoulder_T_tip, at_tip);
  EXPECT_LE((at_shoulder.force - Eigen::Vector3d(0, 0, -10)).norm(), kTolerance);
  EXPECT_LE((at_shoulder.torque - Eigen::Vector3d(0, 20, 0)).norm(), kTolerance);
}

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Equal coordinate by coordinate, where two NaNs count as equal.
testing::AssertionResult sameCoordinates(const Eigen::Vector3d& actual,
                                         const Eigen::Vector3d& expected) {
  for (int i = 0; i < 3; ++i) {
    const bool both_nan = std::isnan(actual[i]) && std::isnan(expected[i]);
    if (!both_nan && actual[i] != expected[i]) {
      return testing::AssertionFailure()
             << "[" << actual.transpose() << "] is not [" << expected.transpose() << "]";
    }
  }
  return testing::AssertionSuccess();
}

// The same point through every form that moves a point, and every one that rotates a vector.
void expectEveryFormGives(const Transform& target_T_source, const Eigen::Vector3d& in,
                          const Eigen::Vector3d& expected_point,
                          const Eigen::Vector3d& expected_direction) {
  Eigen::Matrix3Xd cloud(3, 1);
  cloud.col(0) = in;
  const Transform pose(in, Eigen::Quaterniond::Identity());
  const Eigen::Isometry3d isometry{Eigen::Translation3d(in)};
  EXPECT_TRUE(sameCoordinates(transformed(target_T_source, in), expected_point));
  EXPECT_TRUE(sameCoordinates(target_T_source * in, expected_point));
  EXPECT_TRUE(sameCoordinates(transformed(target_T_source, cloud).col(0), expected_point));
  EXPECT_TRUE(sameCoordinates(transformed(target_T_source, std::vector<Eigen::Vector3d>{in})[0],
                              expected_point));
  EXPECT_TRUE(sameCoordinates(transformed(target_T_source, pose).translation, expected_point));
  EXPECT_TRUE(
      sameCoordinates(transformed(target_T_source, isometry).translation(), expected_point));
  EXPECT_TRUE(sameCoordinates(
      transformed(target_T_source, PoseWithCovariance{pose, {}}).pose.translation, expected_point));
  EXPECT_TRUE(
      sameCoordinates(transformed(target_T_source, Direction{in}).value, expected_direction));
  EXPECT_TRUE(sameCoordinates(target_T_source.rotate(in), expected_direction));
  EXPECT_TRUE(
      sameCoordinates(transformed(target_T_source, Wrench{in, {}}).force, expected_direction));
  EXPECT_TRUE(
      sameCoordinates(transformed(target_T_source, Twist{{}, in}).angular, expected_direction));
}

TEST(DoTransform, PointWithInfiniteCoordinateMatchesCloudForm) {
  // No entry of this rotation's matrix is zero: one infinite coordinate makes all three
  // infinite, with the signs of the first column.
  const Transform target_T_source(Eigen::Vector3d(1, 2, 3),
                                  Eigen::Quaterniond(0.5, 0.5, -0.1, 0.7).normalized());
  const Eigen::Vector3d signs = target_T_source.rotation.toRotationMatrix().col(0).cwiseSign();
  expectEveryFormGives(target_T_source, Eigen::Vector3d(kInf, 1, 2), kInf * signs, kInf * signs);
}

TEST(DoTransform, InfiniteCoordinateIsNaNWhereTheRotationMatrixHasAZero) {
  // A quarter turn about z from a normalized quaternion: R = [0 -1 0; 1 0 0; 0 0 1] with its
  // zeros exact, and 0 * inf is NaN.
  const Transform target_T_source(Eigen::Vector3d(1, 2, 3),
                                  Eigen::Quaterniond(1, 0, 0, 1).normalized());
  const Eigen::Vector3d in(kInf, 1, 2);
  expectEveryFormGives(target_T_source, in, Eigen::Vector3d(kNaN, kInf, kNaN),
                       Eigen::Vector3d(kNaN, kInf, kNaN));
}

TEST(DoTransform, NaNCoordinatePassesThroughEveryForm) {
  const Transform target_T_source(Eigen::Vector3d(1, 2, 3),
                                  Eigen::Quaterniond(0.5, 0.5, -0.1, 0.7).normalized());
  const Eigen::Vector3d all_nan(kNaN, kNaN, kNaN);
  expectEveryFormGives(target_T_source, Eigen::Vector3d(kNaN, 1, 2), all_nan, all_nan);
}

TEST(DoTransform, NaNInAWrenchPassesThroughTheLeverArm) {
  const Transform target_T_source(Eigen::Vector3d(2, 0, 0), Eigen::Quaterniond::Identity());
  const Eigen::Vector3d all_nan(kNaN, kNaN, kNaN);
  // A NaN force reaches the torque too, through the lever arm p x (R f).
  const Wrench bad_force = transformed(target_T_source, Wrench{all_nan, Eigen::Vector3d(1, 2, 3)});
  EXPECT_TRUE(sameCoordinates(bad_force.force, all_nan));
  EXPECT_TRUE(sameCoordinates(bad_force.torque, all_nan));
  // A NaN torque stays in the torque; the force is untouched.
  const Wrench bad_torque =
      transformed(target_T_source, Wrench{Eigen::Vector3d(0, 0, -10), all_nan});
  EXPECT_EQ(bad_torque.force, Eigen::Vector3d(0, 0, -10));
  EXPECT_TRUE(sameCoordinates(bad_torque.torque, all_nan));
}

TEST(DoTransform, CovarianceWithInfiniteRotationBlockKeepsPositionBlockFinite) {
  const Transform target_T_source(Eigen::Vector3d(1, 2, 3),
                                  Eigen::Quaterniond(0.5, 0.5, -0.1, 0.7).normalized());
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity();
  covariance.bottomRightCorner<3, 3>() *= kInf;
  const PoseWithCovariance moved =
      transformed(target_T_source, PoseWithCovariance{Transform(), covariance});
  const Eigen::Matrix3d position = moved.covariance.topLeftCorner<3, 3>();
  EXPECT_LE((position - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), kTolerance);
  EXPECT_EQ(moved.covariance.topRightCorner(3, 3), Eigen::Matrix3d::Zero());
  EXPECT_EQ(moved.covariance.bottomLeftCorner(3, 3), Eigen::Matrix3d::Zero());
  EXPECT_FALSE(moved.covariance.bottomRightCorner(3, 3).allFinite());
}

TEST(DoTransform, StampedResultTakesTheTransformsFrameAndStamp) {
  const TransformStamped map_T_camera{fromUtime(5'000'000), "map", "camera",
                                      Transform(Eigen::Vector3d(1, 2, 3), {1, 0, 0, 0})};
  const Stamped<Eigen::Vector3d> in{Eigen::Vector3d(1, 0, 0), "/camera", fromUtime(4'000'000)};
  const Stamped<Eigen::Vector3d> out = doTransform(in, map_T_camera);
  EXPECT_EQ(out.frame_id, "map");
  EXPECT_EQ(out.stamp, fromUtime(5'000'000));
  EXPECT_EQ(out.data, Eigen::Vector3d(2, 2, 3));
}

TEST(DoTransform, DataInAnotherFrameThanTheTransformIsRefused) {
  const TransformStamped map_T_camera{fromUtime(1), "map", "camera", Transform()};
  const Stamped<Direction> in{Direction{Eigen::Vector3d::UnitX()}, "lidar", fromUtime(1)};
  try {
    doTransform(in, map_T_camera);
    FAIL() << "expected InvalidArgumentException";
  } catch (const InvalidArgumentException& e) {
    EXPECT_THAT(e.what(), HasSubstr("'lidar'"));
    EXPECT_THAT(e.what(), HasSubstr("'camera'"));
  }
}

// The paper's example: an object seen by the camera 2 s ago; where is it now relative to the
// robot, given that the robot has moved since? odom does not move, so it carries the object
// across time.
TEST(BufferTransform, ObjectSeenTwoSecondsAgoIsFoundInTodaysBaseLink) {
  Buffer buffer;
  buffer.setTransform({TimePoint{}, "base_link", "camera",
                       Transform(Eigen::Vector3d(0.2, 0, 1.0), Eigen::Quaterniond::Identity())},
                      "test", true);
  // The robot drives along x at 0.5 m/s and turns about z at 0.25 rad/s.
  for (std::int64_t t = 0; t <= 4'000'000; t += 100'000) {
    const double seconds = toSeconds(Duration(t));
    buffer.setTransform({fromUtime(1'000'000'000 + t), "odom", "base_link",
                         Transform(Eigen::Vector3d(0.5 * seconds, 0, 0),
                                   Eigen::Quaterniond(Eigen::AngleAxisd(
                                       0.25 * seconds, Eigen::Vector3d::UnitZ())))},
                        "test");
  }
  const TimePoint seen = fromUtime(1'001'000'000);
  const TimePoint now = fromUtime(1'003'000'000);
  const Stamped<Eigen::Vector3d> object{Eigen::Vector3d(3, 0, 0), "camera", seen};
  const Stamped<Eigen::Vector3d> in_base_now = buffer.transform(object, "base_link", now, "odom");

  const auto odom_T_base = [](double seconds) {
    return Eigen::Translation3d(0.5 * seconds, 0, 0) *
           Eigen::AngleAxisd(0.25 * seconds, Eigen::Vector3d::UnitZ());
  };
  const Eigen::Vector3d in_odom = odom_T_base(1.0) * (Eigen::Vector3d(0.2, 0, 1.0) + object.data);
  const Eigen::Vector3d expected = odom_T_base(3.0).inverse() * in_odom;
  EXPECT_EQ(in_base_now.frame_id, "base_link");
  EXPECT_EQ(in_base_now.stamp, now);
  EXPECT_LE((in_base_now.data - expected).norm(), 1e-12);

  const Stamped<Eigen::Vector3d> in_base_then = buffer.transform(object, "base_link");
  EXPECT_LE((in_base_then.data - Eigen::Vector3d(3.2, 0, 1.0)).norm(), 1e-12);
}

TEST(BufferTransform, WaitsForTheDataWithATimeout) {
  Buffer buffer;
  const Stamped<Eigen::Vector3d> point{Eigen::Vector3d::Zero(), "camera", fromUtime(1'000'000)};
  EXPECT_THROW(buffer.transform(point, "map", std::chrono::milliseconds(20)), TimeoutException);
  EXPECT_THROW(buffer.transform(point, "map"), LookupException);
}

}  // namespace
}  // namespace lcmtf
