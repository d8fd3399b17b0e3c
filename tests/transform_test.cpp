#include "lcmtf/transform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>
#include <vector>

namespace lcmtf {

// How GoogleTest shows a sample: by its values, where its own printer would show the object's
// bytes, padding included, which memcheck reports as read before written.
void PrintTo(const Transform& value, std::ostream* out) {
  *out << "translation [" << value.translation.transpose() << "] rotation xyzw ["
       << value.rotation.coeffs().transpose() << "]";
}

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-12;

Eigen::Quaterniond axisAngle(double angle, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// Random transforms plus the corner cases that break naive formulas.
std::vector<Transform> sampleTransforms() {
  std::vector<Transform> samples{
      Transform::identity(),
      Transform(Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond::Identity()),
      Transform(Eigen::Vector3d::Zero(), axisAngle(kPi, Eigen::Vector3d::UnitX())),
      Transform(Eigen::Vector3d(-4, 0.5, 9), axisAngle(kPi - 1e-9, Eigen::Vector3d(1, 1, 0))),
      Transform(Eigen::Vector3d(1e4, -1e4, 3), axisAngle(1e-10, Eigen::Vector3d::UnitZ())),
  };
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector3d translation(coordinate(random), coordinate(random), coordinate(random));
    samples.emplace_back(translation, Eigen::Quaterniond::UnitRandom());
  }
  return samples;
}

void expectSameTransform(const Transform& actual, const Transform& expected, double tolerance) {
  EXPECT_LE((actual.translation - expected.translation).norm(), tolerance)
      << "translation " << actual.translation.transpose() << " vs "
      << expected.translation.transpose();
  EXPECT_LE(angularDistance(actual.rotation, expected.rotation), tolerance)
      << "rotation " << actual.rotation.coeffs().transpose() << " vs "
      << expected.rotation.coeffs().transpose();
}

class TransformProperties : public ::testing::TestWithParam<Transform> {};

TEST_P(TransformProperties, ComposeWithInverseIsIdentity) {
  const Transform& a_T_b = GetParam();
  expectSameTransform(a_T_b * a_T_b.inverse(), Transform::identity(), 1e-11);
  expectSameTransform(a_T_b.inverse() * a_T_b, Transform::identity(), 1e-11);
}

TEST_P(TransformProperties, InverseOfInverseIsItself) {
  expectSameTransform(GetParam().inverse().inverse(), GetParam(), 1e-11);
}

TEST_P(TransformProperties, ComposeMatchesEigenIsometryProduct) {
  const Transform& a_T_b = GetParam();
  const Transform b_T_c(Eigen::Vector3d(0.3, -2, 5), axisAngle(0.7, Eigen::Vector3d(1, -2, 3)));
  const Eigen::Isometry3d expected = a_T_b.toIsometry() * b_T_c.toIsometry();
  expectSameTransform(a_T_b * b_T_c, Transform::fromIsometry(expected), 1e-11);
}

TEST_P(TransformProperties, ApplyingComposedEqualsApplyingTwice) {
  const Transform& a_T_b = GetParam();
  const Transform b_T_c(Eigen::Vector3d(-1, 4, 0.25), axisAngle(2.1, Eigen::Vector3d(0, 1, 1)));
  const Eigen::Vector3d point_in_c(0.5, -7, 2);
  EXPECT_LE(((a_T_b * b_T_c) * point_in_c - a_T_b * (b_T_c * point_in_c)).norm(), 1e-10);
  EXPECT_LE((a_T_b * point_in_c - a_T_b.toIsometry() * point_in_c).norm(), 1e-10);
}

TEST_P(TransformProperties, ComposeIsAssociative) {
  const Transform& a = GetParam();
  const Transform b(Eigen::Vector3d(1, 1, 1), axisAngle(1.0, Eigen::Vector3d::UnitY()));
  const Transform c(Eigen::Vector3d(0, -3, 2), axisAngle(-2.5, Eigen::Vector3d(1, 0, 1)));
  expectSameTransform((a * b) * c, a * (b * c), 1e-10);
}

TEST_P(TransformProperties, RotateIgnoresTranslation) {
  const Transform& a_T_b = GetParam();
  const Eigen::Vector3d direction(0, 0, 1);
  EXPECT_LE((a_T_b.rotate(direction) - a_T_b.rotation.toRotationMatrix() * direction).norm(),
            kTolerance);
}

TEST_P(TransformProperties, RotationMatrixIsTheQuaternionsRotation) {
  const Transform& a_T_b = GetParam();
  EXPECT_LE((a_T_b.rotationMatrix() - a_T_b.rotation.toRotationMatrix()).cwiseAbs().maxCoeff(),
            kTolerance);
}

TEST_P(TransformProperties, IsometryRoundTrip) {
  expectSameTransform(Transform::fromIsometry(GetParam().toIsometry()), GetParam(), 1e-12);
}

TEST_P(TransformProperties, InterpolationHitsBothEndsExactly) {
  const Transform& a = GetParam();
  const Transform b(Eigen::Vector3d(5, 6, 7), axisAngle(1.2, Eigen::Vector3d(3, 2, 1)));
  const Transform start = interpolate(a, b, 0.0);
  const Transform end = interpolate(a, b, 1.0);
  EXPECT_EQ(start.translation, a.translation);
  EXPECT_EQ(start.rotation.coeffs(), a.rotation.coeffs());
  EXPECT_EQ(end.translation, b.translation);
  EXPECT_EQ(end.rotation.coeffs(), b.rotation.coeffs());
}

TEST_P(TransformProperties, SlerpKeepsUnitLengthAndConstantAngularSpeed) {
  const Eigen::Quaterniond a = GetParam().rotation;
  const Eigen::Quaterniond b = axisAngle(2.9, Eigen::Vector3d(-1, 0.5, 2)) * a;
  const double total = angularDistance(a, b);
  for (double ratio = 0.0; ratio <= 1.0; ratio += 1.0 / 16) {
    const Eigen::Quaterniond q = slerp(a, b, ratio);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15) << "ratio " << ratio;
    EXPECT_NEAR(angularDistance(a, q), ratio * total, 1e-12) << "ratio " << ratio;
    EXPECT_NEAR(angularDistance(q, b), (1.0 - ratio) * total, 1e-12) << "ratio " << ratio;
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, TransformProperties, ::testing::ValuesIn(sampleTransforms()),
                         [](const auto& sample) {
                           return "sample" + std::to_string(sample.index);
                         });

TEST(Transform, RotationMatrixOfANormalizedQuarterTurnHasExactZeros) {
  // 1/sqrt(2) rounds so that |q|^2 is not exactly 1; the matrix's zeros must stay exact.
  const Transform quarter_turn(Eigen::Vector3d::Zero(),
                               Eigen::Quaterniond(1, 0, 0, 1).normalized());
  Eigen::Matrix3d expected;
  expected << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_EQ(quarter_turn.rotationMatrix(), expected);
}

TEST(Transform, RotationMatrixOfAnUnnormalizedQuaternionIsOrthonormal) {
  const Eigen::Quaterniond unit = axisAngle(0.7, Eigen::Vector3d(1, -2, 3));
  const Transform scaled(Eigen::Vector3d::Zero(), Eigen::Quaterniond(3.0 * unit.coeffs()));
  EXPECT_LE((scaled.rotationMatrix() - unit.toRotationMatrix()).cwiseAbs().maxCoeff(), kTolerance);
}

TEST(Transform, DefaultIsIdentity) {
  const Transform t;
  EXPECT_EQ(t.translation, Eigen::Vector3d::Zero());
  EXPECT_EQ(t.rotation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

TEST(Transform, AppliesRotationThenTranslation) {
  const Transform parent_T_child(Eigen::Vector3d(1, 0, 0),
                                 axisAngle(kPi / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d point_in_parent = parent_T_child * Eigen::Vector3d(1, 0, 0);
  EXPECT_LE((point_in_parent - Eigen::Vector3d(1, 1, 0)).norm(), kTolerance);
  EXPECT_LE((parent_T_child.inverse() * point_in_parent - Eigen::Vector3d(1, 0, 0)).norm(),
            kTolerance);
}

TEST(Transform, ComposeOrderNamesCancel) {
  const Transform map_T_odom(Eigen::Vector3d(10, 0, 0), Eigen::Quaterniond::Identity());
  const Transform odom_T_base(Eigen::Vector3d(0, 0, 0),
                              axisAngle(kPi / 2, Eigen::Vector3d::UnitZ()));
  const Transform map_T_base = map_T_odom * odom_T_base;
  EXPECT_LE((map_T_base * Eigen::Vector3d(1, 0, 0) - Eigen::Vector3d(10, 1, 0)).norm(), kTolerance);
}

TEST(Slerp, TakesTheShortestArc) {
  const Eigen::Quaterniond a = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond b = axisAngle(3 * kPi / 2, Eigen::Vector3d::UnitZ());  // = -90 degrees
  const Eigen::Quaterniond halfway = slerp(a, b, 0.5);
  EXPECT_LE(angularDistance(halfway, axisAngle(-kPi / 4, Eigen::Vector3d::UnitZ())), kTolerance);
  const Eigen::Quaterniond negated(-b.coeffs());
  EXPECT_LE(angularDistance(slerp(a, negated, 0.5), halfway), kTolerance);
}

TEST(Slerp, MatchesEigenSlerp) {
  const Eigen::Quaterniond a = axisAngle(0.3, Eigen::Vector3d(1, 2, 3));
  const Eigen::Quaterniond b = axisAngle(-2.0, Eigen::Vector3d(-3, 1, 0));
  for (double ratio : {0.1, 0.25, 0.5, 0.9}) {
    EXPECT_LE(angularDistance(slerp(a, b, ratio), a.slerp(ratio, b)), 1e-12) << ratio;
  }
}

// The series used for nearby rotations and libm used for distant ones must agree with the
// closed form on both sides of the switch between them.
TEST(Slerp, MatchesClosedFormAcrossAllAngles) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Quaterniond a = axisAngle(0.4, Eigen::Vector3d(0, 1, 1));
  for (double turn = 1e-9; turn < 3.1; turn *= 1.07) {
    const Eigen::Quaterniond b = axisAngle(turn, axis) * a;
    for (double ratio : {0.013, 0.25, 0.5, 0.77, 0.999}) {
      const Eigen::Quaterniond expected = axisAngle(ratio * turn, axis) * a;
      const Eigen::Quaterniond q = slerp(a, b, ratio);
      EXPECT_LE(angularDistance(q, expected), 4e-15) << "turn " << turn << " ratio " << ratio;
      EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    }
  }
}

TEST(Slerp, NearlyIdenticalRotationsStayAccurate) {
  const Eigen::Quaterniond a = axisAngle(1.0, Eigen::Vector3d::UnitX());
  const Eigen::Quaterniond b = axisAngle(1.0 + 1e-11, Eigen::Vector3d::UnitX());
  const Eigen::Quaterniond q = slerp(a, b, 0.5);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_LE(angularDistance(q, axisAngle(1.0 + 0.5e-11, Eigen::Vector3d::UnitX())), 1e-15);
}

TEST(Slerp, HalfTurnApartStaysUnitAndHalfway) {
  const Eigen::Quaterniond a = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond b = axisAngle(kPi, Eigen::Vector3d::UnitY());
  const Eigen::Quaterniond q = slerp(a, b, 0.5);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_NEAR(angularDistance(a, q), kPi / 2, 1e-12);
}

TEST(Interpolate, TranslationIsLinear) {
  const Transform a(Eigen::Vector3d(0, 0, 0), Eigen::Quaterniond::Identity());
  const Transform b(Eigen::Vector3d(2, -4, 8), axisAngle(1.0, Eigen::Vector3d::UnitZ()));
  const Transform quarter = interpolate(a, b, 0.25);
  EXPECT_LE((quarter.translation - Eigen::Vector3d(0.5, -1, 2)).norm(), kTolerance);
  EXPECT_LE(angularDistance(quarter.rotation, axisAngle(0.25, Eigen::Vector3d::UnitZ())),
            kTolerance);
}

TEST(AngularDistance, TreatsNegatedQuaternionAsSameRotation) {
  const Eigen::Quaterniond q = axisAngle(0.8, Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(angularDistance(q, Eigen::Quaterniond(-q.coeffs())), 0.0);
  EXPECT_NEAR(angularDistance(q, Eigen::Quaterniond::Identity()), 0.8, 1e-15);
}

TEST(Transform, IsApproxUsesMetresAndRadians) {
  const Transform a(Eigen::Vector3d(1, 2, 3), axisAngle(0.5, Eigen::Vector3d::UnitZ()));
  Transform b = a;
  b.translation.x() += 1e-7;
  EXPECT_TRUE(a.isApprox(b, 1e-6));
  EXPECT_FALSE(a.isApprox(b, 1e-8));
  b = a;
  b.rotation = axisAngle(0.5 + 1e-7, Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(a.isApprox(b, 1e-6));
  EXPECT_FALSE(a.isApprox(b, 1e-8));
}

}  // namespace
}  // namespace lcmtf
