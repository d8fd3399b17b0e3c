// lcmtf's doTransform against tf2_geometry_msgs' on the same data: finite, infinite and NaN
// coordinates, under rotations with and without exact zeros in their matrices.
#include <gtest/gtest.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "lcmtf/do_transform.hpp"

namespace lcmtf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Quarter and half turns have exact zeros in their matrices, where 0 * inf is NaN; the random
// rotations have none.
std::vector<Transform> sampleTransforms() {
  std::vector<Transform> samples{
      Transform(Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond::Identity()),
      Transform(Eigen::Vector3d(-1, 0.5, 2), Eigen::Quaterniond(1, 0, 0, 1).normalized()),
      Transform(Eigen::Vector3d(0, 0, 0), Eigen::Quaterniond(1, 1, 0, 0).normalized()),
      Transform(Eigen::Vector3d(4, -2, 1), Eigen::Quaterniond(1, 0, -1, 0).normalized()),
      Transform(Eigen::Vector3d(1, 1, 1), Eigen::Quaterniond(0, 0, 0, 1)),
      Transform(Eigen::Vector3d(0, 3, 0), Eigen::Quaterniond(1, 1, 1, 1).normalized()),
  };
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  for (int i = 0; i < 20; ++i) {
    samples.emplace_back(
        Eigen::Vector3d(coordinate(random), coordinate(random), coordinate(random)),
        Eigen::Quaterniond::UnitRandom());
  }
  return samples;
}

// Finite vectors, then every placement of one or two non-finite coordinates.
std::vector<Eigen::Vector3d> sampleVectors() {
  std::vector<Eigen::Vector3d> samples{Eigen::Vector3d(0.3, -2, 7), Eigen::Vector3d(1e300, 1, 0)};
  for (const double bad : {kInf, -kInf, kNaN}) {
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d one(0.5, -1.5, 2.5);
      one[i] = bad;
      samples.push_back(one);
      for (const double other : {kInf, -kInf}) {
        Eigen::Vector3d two = one;
        two[(i + 1) % 3] = other;
        samples.push_back(two);
      }
    }
  }
  return samples;
}

template <class Xyz>
Xyz toXyz(const Eigen::Vector3d& v) {
  Xyz message;
  message.x = v.x();
  message.y = v.y();
  message.z = v.z();
  return message;
}

geometry_msgs::Quaternion toTf2(const Eigen::Quaterniond& q) {
  return tf2::toMsg(tf2::Quaternion(q.x(), q.y(), q.z(), q.w()));
}

geometry_msgs::TransformStamped toTf2(const Transform& transform) {
  geometry_msgs::TransformStamped message;
  message.transform.translation = toXyz<geometry_msgs::Vector3>(transform.translation);
  message.transform.rotation = toTf2(transform.rotation);
  return message;
}

template <class Xyz>
Eigen::Vector3d fromXyz(const Xyz& message) {
  return Eigen::Vector3d(message.x, message.y, message.z);
}

// Both NaN, equal (infinities with their sign), or finite and within rounding of each other.
bool agrees(double lcmtf_value, double tf2_value) {
  if (std::isnan(lcmtf_value) || std::isnan(tf2_value)) {
    return std::isnan(lcmtf_value) && std::isnan(tf2_value);
  }
  if (lcmtf_value == tf2_value) return true;
  return std::isfinite(lcmtf_value) && std::isfinite(tf2_value) &&
         std::abs(lcmtf_value - tf2_value) <= 1e-12 * std::max(1.0, std::abs(tf2_value));
}

template <class Matrix>
testing::AssertionResult agrees(const Matrix& lcmtf_value, const Matrix& tf2_value) {
  for (Eigen::Index i = 0; i < lcmtf_value.size(); ++i) {
    if (!agrees(lcmtf_value(i), tf2_value(i))) {
      return testing::AssertionFailure() << "lcmtf\n" << lcmtf_value << "\ntf2\n" << tf2_value;
    }
  }
  return testing::AssertionSuccess();
}

class Tf2DoTransformAgreement : public ::testing::TestWithParam<Transform> {
 protected:
  const Transform& target_T_source = GetParam();
  const geometry_msgs::TransformStamped tf2_transform = toTf2(GetParam());
};

TEST_P(Tf2DoTransformAgreement, PointsAgreeInEveryFormForFiniteInfiniteAndNaNCoordinates) {
  const std::vector<Eigen::Vector3d> points = sampleVectors();
  Eigen::Matrix3Xd cloud(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    cloud.col(static_cast<Eigen::Index>(i)) = points[i];
  const Eigen::Matrix3Xd moved_cloud = transformed(target_T_source, cloud);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    SCOPED_TRACE(testing::Message() << "point " << p.transpose());
    geometry_msgs::Point tf2_point;
    tf2::doTransform(toXyz<geometry_msgs::Point>(p), tf2_point, tf2_transform);
    const Eigen::Vector3d expected = fromXyz(tf2_point);
    EXPECT_TRUE(agrees(transformed(target_T_source, p), expected));
    EXPECT_TRUE(agrees(Eigen::Vector3d(moved_cloud.col(static_cast<Eigen::Index>(i))), expected));

    geometry_msgs::Pose tf2_pose;
    geometry_msgs::Pose pose_in;
    pose_in.position = toXyz<geometry_msgs::Point>(p);
    pose_in.orientation.w = 1.0;
    tf2::doTransform(pose_in, tf2_pose, tf2_transform);
    const Transform pose =
        transformed(target_T_source, Transform(p, Eigen::Quaterniond::Identity()));
    EXPECT_TRUE(agrees(pose.translation, fromXyz(tf2_pose.position)));
  }
}

TEST_P(Tf2DoTransformAgreement, VectorsAndForcesAgreeForFiniteInfiniteAndNaNCoordinates) {
  for (const Eigen::Vector3d& v : sampleVectors()) {
    SCOPED_TRACE(testing::Message() << "vector " << v.transpose());
    geometry_msgs::Vector3 tf2_vector;
    tf2::doTransform(toXyz<geometry_msgs::Vector3>(v), tf2_vector, tf2_transform);
    EXPECT_TRUE(agrees(transformed(target_T_source, Direction{v}).value, fromXyz(tf2_vector)));

    geometry_msgs::Wrench wrench_in;
    wrench_in.force = toXyz<geometry_msgs::Vector3>(v);
    geometry_msgs::Wrench tf2_wrench;
    tf2::doTransform(wrench_in, tf2_wrench, tf2_transform);
    EXPECT_TRUE(
        agrees(transformed(target_T_source, Wrench{v, {}}).force, fromXyz(tf2_wrench.force)));
  }
}

// tf2 rotates a wrench's torque only; lcmtf adds the lever arm p x (R f) as well.
TEST_P(Tf2DoTransformAgreement, TorqueIsTf2sPlusTheLeverArm) {
  const Eigen::Vector3d force(0.3, -2, 7);
  const Eigen::Vector3d torque(-1, 4, 0.5);
  geometry_msgs::Wrench wrench_in;
  wrench_in.force = toXyz<geometry_msgs::Vector3>(force);
  wrench_in.torque = toXyz<geometry_msgs::Vector3>(torque);
  geometry_msgs::Wrench tf2_wrench;
  tf2::doTransform(wrench_in, tf2_wrench, tf2_transform);
  const Wrench moved = transformed(target_T_source, Wrench{force, torque});
  const Eigen::Vector3d lever_arm = target_T_source.translation.cross(fromXyz(tf2_wrench.force));
  EXPECT_TRUE(agrees(moved.torque, Eigen::Vector3d(fromXyz(tf2_wrench.torque) + lever_arm)));
}

TEST_P(Tf2DoTransformAgreement, OrientationsAgree) {
  std::vector<Eigen::Quaterniond> orientations{
      Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0.1, -0.7, 0.7, 0.1).normalized(),
      Eigen::Quaterniond(kNaN, 0, 0, 0), Eigen::Quaterniond(kInf, 0, 0, 0),
      Eigen::Quaterniond(1, kInf, 0, 0)};
  for (const Eigen::Quaterniond& q : orientations) {
    SCOPED_TRACE(testing::Message() << "orientation " << q.coeffs().transpose());
    const geometry_msgs::Quaternion q_in = toTf2(q);
    geometry_msgs::Quaternion tf2_q;
    tf2::doTransform(q_in, tf2_q, tf2_transform);
    const Eigen::Quaterniond moved = transformed(target_T_source, q);
    EXPECT_TRUE(agrees(moved.coeffs(), Eigen::Vector4d(tf2_q.x, tf2_q.y, tf2_q.z, tf2_q.w)));

    // tf2's pose form goes through rotation matrices, which turn a non-finite orientation
    // wholly NaN and may flip the sign of a finite one; lcmtf's pose form is its quaternion
    // form.
    geometry_msgs::Pose pose_in;
    pose_in.orientation = q_in;
    geometry_msgs::Pose tf2_pose;
    tf2::doTransform(pose_in, tf2_pose, tf2_transform);
    const Eigen::Quaterniond tf2_pose_q(tf2_pose.orientation.w, tf2_pose.orientation.x,
                                        tf2_pose.orientation.y, tf2_pose.orientation.z);
    const Transform pose = transformed(target_T_source, Transform(Eigen::Vector3d::Zero(), q));
    EXPECT_TRUE(agrees(pose.rotation.coeffs(), moved.coeffs()));
    if (q.coeffs().allFinite()) {
      EXPECT_LE(angularDistance(pose.rotation, tf2_pose_q), 1e-12);
    } else {
      EXPECT_FALSE(tf2_pose_q.coeffs().allFinite());
    }
  }
}

using Covariance = Eigen::Matrix<double, 6, 6>;

Covariance transformedByTf2(const Covariance& covariance,
                            const geometry_msgs::TransformStamped& transform) {
  geometry_msgs::PoseWithCovarianceStamped in;
  in.pose.pose.orientation.w = 1.0;
  for (int i = 0; i < 36; ++i)
    in.pose.covariance[static_cast<std::size_t>(i)] = covariance(i / 6, i % 6);
  geometry_msgs::PoseWithCovarianceStamped out;
  tf2::doTransform(in, out, transform);
  Covariance result;
  for (int i = 0; i < 36; ++i)
    result(i / 6, i % 6) = out.pose.covariance[static_cast<std::size_t>(i)];
  return result;
}

TEST_P(Tf2DoTransformAgreement, CovariancesAgreeWithFiniteInfiniteAndNaNBlocks) {
  const Covariance root = Covariance::Random();
  const Covariance finite = root * root.transpose();
  Covariance infinite_rotation = finite;
  infinite_rotation.bottomRightCorner(3, 3).setIdentity();
  infinite_rotation.bottomRightCorner(3, 3) *= kInf;
  infinite_rotation.topRightCorner(3, 3).setZero();
  infinite_rotation.bottomLeftCorner(3, 3).setZero();
  Covariance nan_entry = finite;
  nan_entry(1, 1) = kNaN;
  for (const Covariance& covariance : {finite, infinite_rotation, nan_entry}) {
    SCOPED_TRACE(testing::Message() << "covariance\n" << covariance);
    const PoseWithCovariance moved =
        transformed(target_T_source, PoseWithCovariance{Transform(), covariance});
    EXPECT_TRUE(agrees(moved.covariance, transformedByTf2(covariance, tf2_transform)));
  }
}

INSTANTIATE_TEST_SUITE_P(Rotations, Tf2DoTransformAgreement,
                         ::testing::ValuesIn(sampleTransforms()), [](const auto& sample) {
                           return "sample" + std::to_string(sample.index);
                         });

}  // namespace
}  // namespace lcmtf
