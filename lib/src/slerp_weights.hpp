#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <limits>

namespace lcmtf::detail {

// Slerp of unit quaternions a and b (b already on a's side of the sphere) is
// weight_a * a + weight_b * b with weight = sin(w * arc) / sin(arc), w = 1 - ratio and ratio.
// The weights come from y = |a - b|^2 / 4 = sin^2(arc / 2); series serve small arcs with no
// libm calls, since samples close in time are close in rotation.

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

// Taylor coefficients of u/sin(u) in powers of u^2, so that short arcs need no division.
constexpr double kInverseSinc[] = {1.0,
                                   0.16666666666666666,
                                   0.019444444444444445,
                                   0.00205026455026455,
                                   0.0002099867724867725,
                                   2.1336045641601196e-05};

// How many leading terms of each series are exact to double precision, for y up to a limit:
// 5 and 5 up to an arc of 0.063 rad (y = 1e-3), 13 and 9 up to 0.5 rad (y = 0.0612).
constexpr double kShortSeriesLimit = 1e-3;
constexpr double kLongSeriesLimit = 0.0612;

// For a double, or for GCC vectors of doubles (several series evaluated at once).
template <std::size_t Terms, std::size_t N, std::size_t I = 0, class Value>
[[gnu::always_inline]] inline Value horner(const double (&coefficients)[N], Value x) {
  static_assert(Terms <= N);
  if constexpr (I + 1 == Terms) {
    return Value{} + coefficients[I];
  } else {
    return coefficients[I] + x * horner<Terms, N, I + 1>(coefficients, x);
  }
}

/// arc / sin(arc) from the squared arc, by the short series (arc_squared <= 4.01e-3, which
/// y <= kShortSeriesLimit gives): the first omitted term is below 3e-17. By pairs of terms
/// (Estrin's scheme), three operations deep where Horner's rule takes four: every interpolated
/// rotation waits on this once the arc has loaded (1 % off wide's deepest lookups in
/// buffer_core_bench).
template <class Value>
[[gnu::always_inline]] inline Value shortInverseSinc(Value arc_squared) {
  const Value x = arc_squared;
  const Value x2 = x * x;
  const Value low = kInverseSinc[0] + kInverseSinc[1] * x;
  const Value high = (kInverseSinc[2] + kInverseSinc[3] * x) + kInverseSinc[4] * x2;
  return low + high * x2;
}

/// The squared arc, from y, by the short series (y <= kShortSeriesLimit).
inline double shortArcSquared(double y) { return 4.0 * y * horner<5>(kAsinSquared, y); }

/// One weight, w * sin(w * arc) / (w * arc), by the short series; `inverse_sinc` is
/// arc / sin(arc). The series by pairs of terms (Estrin's scheme), three operations deep where
/// Horner's rule takes four, and w * inverse_sinc formed alongside: the weights wait on the
/// time's ratio, and every interpolated value on them (up to 3 % off the lookups of
/// buffer_core_bench on pr2 and wide).
template <class Value>
[[gnu::always_inline]] inline Value shortSeriesWeight(Value w, Value arc_squared,
                                                      Value inverse_sinc) {
  const Value x = w * w * arc_squared;
  const Value x2 = x * x;
  const Value low = kSinc[0] + kSinc[1] * x;
  const Value high = (kSinc[2] + kSinc[3] * x) + kSinc[4] * x2;
  return (low + high * x2) * (w * inverse_sinc);
}

/// What interpolation from rotation `a` to `b` needs to know of the arc between them on the
/// sphere (half the angle between the rotations), worked out once per pair of samples: its
/// square, negative when `b` must be negated to lie on `a`'s side of the sphere, or NaN when
/// the arc is too long for the short series.
inline double signedArcSquared(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const double dot = a.coeffs().dot(b.coeffs());
  const Eigen::Vector4d far_side = dot < 0.0 ? Eigen::Vector4d(-b.coeffs()) : b.coeffs();
  const double y = 0.25 * (a.coeffs() - far_side).squaredNorm();
  if (!(y <= kShortSeriesLimit)) return std::numeric_limits<double>::quiet_NaN();
  return std::copysign(shortArcSquared(y), dot);
}

/// Turns weight_a = 1 - ratio and weight_b = ratio into the slerp weights, for any y.
inline void slerpWeights(double y, double& weight_a, double& weight_b) {
  if (y <= kShortSeriesLimit) {
    const double arc_squared = shortArcSquared(y);
    const double inverse_sinc = shortInverseSinc(arc_squared);
    weight_a = shortSeriesWeight(weight_a, arc_squared, inverse_sinc);
    weight_b = shortSeriesWeight(weight_b, arc_squared, inverse_sinc);
  } else if (y <= kLongSeriesLimit) {
    const double arc_squared = 4.0 * y * horner<13>(kAsinSquared, y);
    const double inverse_sinc = 1.0 / horner<9>(kSinc, arc_squared);
    weight_a *= horner<9>(kSinc, weight_a * weight_a * arc_squared) * inverse_sinc;
    weight_b *= horner<9>(kSinc, weight_b * weight_b * arc_squared) * inverse_sinc;
  } else {
    // 2 asin(sqrt(y)), written so that it stays accurate up to half a turn.
    const double arc = 2.0 * std::atan2(std::sqrt(y), std::sqrt(1.0 - y));
    const double inverse_sine = 1.0 / std::sin(arc);
    weight_a = std::sin(weight_a * arc) * inverse_sine;
    weight_b = std::sin(weight_b * arc) * inverse_sine;
  }
}

}  // namespace lcmtf::detail
