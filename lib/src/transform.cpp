#include "lcmtf/transform.hpp"

#include <algorithm>
#include <cmath>

namespace lcmtf {

Eigen::Isometry3d Transform::toIsometry() const {
  Eigen::Isometry3d isometry = Eigen::Isometry3d::Identity();
  isometry.linear() = rotation.toRotationMatrix();
  isometry.translation() = translation;
  return isometry;
}

Transform Transform::fromIsometry(const Eigen::Isometry3d& isometry) {
  return Transform(isometry.translation(),
                   Eigen::Quaterniond(Eigen::Matrix3d(isometry.linear())).normalized());
}

bool Transform::isApprox(const Transform& other, double tolerance) const {
  return (translation - other.translation).norm() <= tolerance &&
         angularDistance(rotation, other.rotation) <= tolerance;
}

namespace {
// The angle between two unit quaternions as 4-vectors, half the rotation angle between them.
// 2*atan2(|a-b|, |a+b|) stays accurate for tiny angles, where acos(a.b) does not.
double arcAngle(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return 2.0 * std::atan2((a - b).norm(), (a + b).norm());
}
}  // namespace

double angularDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Vector4d bc =
      a.coeffs().dot(b.coeffs()) < 0.0 ? Eigen::Vector4d(-b.coeffs()) : b.coeffs();
  return 2.0 * arcAngle(a.coeffs(), bc);
}

namespace {

// Taylor coefficients of asin(s)^2 in powers of y = s^2, and of sin(u)/u in powers of u^2.
constexpr double kAsinSquared[] = {1.0,
                                   0.3333333333333333,
                                   0.17777777777777778,
                                   0.11428571428571428,
                                   0.08126984126984127,
                                   0.06156806156806157,
                                   0.04871319157033443,
                                   0.03978243978243978,
                                   0.03328204112517838,
                                   0.028377319275152094,
                                   0.02456910759753428,
                                   0.02154247840073658,
                                   0.019089950090498877};
constexpr double kSinc[] = {1.0,
                            -0.16666666666666666,
                            0.008333333333333333,
                            -0.0001984126984126984,
                            2.7557319223985893e-06,
                            -2.505210838544172e-08,
                            1.6059043836821613e-10,
                            -7.647163731819816e-13,
                            2.8114572543455206e-15};

// How many leading terms of each series are exact to double precision, for y = sin^2(arc/2)
// up to a limit: 5 and 5 up to an arc of 0.063 rad (1e-3), 13 and 9 up to 0.5 rad (0.0612).
constexpr double kShortSeriesLimit = 1e-3;
constexpr double kLongSeriesLimit = 0.0612;

template <std::size_t Terms, std::size_t N, std::size_t I = 0>
inline double horner(const double (&coefficients)[N], double x) {
  static_assert(Terms <= N);
  if constexpr (I + 1 == Terms) {
    return coefficients[I];
  } else {
    return coefficients[I] + x * horner<Terms, N, I + 1>(coefficients, x);
  }
}

// sin(w * arc) / sin(arc) for both weights, from y = sin^2(arc / 2).
template <std::size_t AsinTerms, std::size_t SincTerms>
inline void seriesWeights(double y, double& weight_a, double& weight_b) {
  const double arc_squared = 4.0 * y * horner<AsinTerms>(kAsinSquared, y);
  const double inverse_sinc = 1.0 / horner<SincTerms>(kSinc, arc_squared);
  weight_a *= horner<SincTerms>(kSinc, weight_a * weight_a * arc_squared) * inverse_sinc;
  weight_b *= horner<SincTerms>(kSinc, weight_b * weight_b * arc_squared) * inverse_sinc;
}

}  // namespace

Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double ratio) {
  if (ratio == 0.0) return a;
  Eigen::Vector4d bc = b.coeffs();
  if (a.coeffs().dot(bc) < 0.0) bc = -bc;
  if (ratio == 1.0) return Eigen::Quaterniond(bc);

  // The weights are sin(w * arc) / sin(arc) for w = 1 - ratio and w = ratio. Samples close in
  // time are close in rotation, so the series (no libm calls) serve nearly every lookup.
  double weight_a = 1.0 - ratio;
  double weight_b = ratio;
  const double y = 0.25 * (a.coeffs() - bc).squaredNorm();
  if (y <= kShortSeriesLimit) {
    seriesWeights<5, 5>(y, weight_a, weight_b);
  } else if (y <= kLongSeriesLimit) {
    seriesWeights<13, 9>(y, weight_a, weight_b);
  } else {
    const double arc = arcAngle(a.coeffs(), bc);
    const double inverse_sine = 1.0 / std::sin(arc);
    weight_a = std::sin(weight_a * arc) * inverse_sine;
    weight_b = std::sin(weight_b * arc) * inverse_sine;
  }
  Eigen::Quaterniond result(weight_a * a.coeffs() + weight_b * bc);
  result.normalize();
  return result;
}

Transform interpolate(const Transform& a, const Transform& b, double ratio) {
  if (ratio == 0.0) return a;
  if (ratio == 1.0) return b;
  return Transform(a.translation + ratio * (b.translation - a.translation),
                   slerp(a.rotation, b.rotation, ratio));
}

}  // namespace lcmtf
