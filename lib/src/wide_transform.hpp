#pragma once

// Transforms held in four-lane vectors while a lookup composes them: the quaternion product as
// four products of whole vectors, and a translation's rotation as two cross products of whole
// vectors. Eigen composes a rotation two lanes at a time with shuffles between the halves, and
// a chain of compositions waits on each one's longer latency. In the path products and the
// anchors of interpolation batches, this took 3-15 % off every lookup row of buffer_core_bench
// (pr2's random ones 202 -> 190 ns, its latest ones 200 -> 186, wide's latest ones 79 -> 67).
//
// For functions compiled twice (LCMTF_WIDE_VECTORS) only: everything here inlines into them,
// so each copy has the instructions of its own target. Four-lane values never cross a call.

#include <cstdint>
#include <cstring>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// Four lanes of doubles, one register wide where the processor has AVX2.
using Four = double __attribute__((vector_size(4 * sizeof(double))));
using FourBits = std::int64_t __attribute__((vector_size(4 * sizeof(double))));

[[gnu::always_inline]] inline Four loadFour(const double* values) {
  Four four;
  std::memcpy(&four, values, sizeof four);
  return four;
}

[[gnu::always_inline]] inline void storeFour(double* values, Four four) {
  std::memcpy(values, &four, sizeof four);
}

/// A transform as two vectors: the translation (x, y, z, 0) and the rotation's coefficients
/// (x, y, z, w).
struct WideTransform {
  Four translation;
  Four rotation;
};

/// `four` with its fourth lane zeroed, bit for bit.
[[gnu::always_inline]] inline Four firstThree(Four four) {
  constexpr FourBits kFirstThree = {-1, -1, -1, 0};
  return reinterpret_cast<Four>(reinterpret_cast<FourBits>(four) & kFirstThree);
}

/// `transform` in lanes. The translation's fourth lane is zeroed: a stored sample keeps its
/// stamp in the bytes after the translation, and an integer read as a double is denormal,
/// which some processors multiply slowly.
[[gnu::always_inline]] inline WideTransform widened(const Transform& transform) {
  static_assert(sizeof(Transform) == 8 * sizeof(double), "translation, padding, rotation");
  const auto* bytes = reinterpret_cast<const unsigned char*>(&transform);
  Four translation;
  std::memcpy(&translation, bytes, sizeof translation);
  return WideTransform{firstThree(translation), loadFour(transform.rotation.coeffs().data())};
}

/// Writes `wide` to `out`, leaving the bytes after its translation alone: for a lookup's
/// answer, which its caller reads field by field. (Writing them too made lookups 1-6 % slower
/// in buffer_core_bench.)
[[gnu::always_inline]] inline void narrowInto(const WideTransform& wide, Transform& out) {
  double translation[4];
  storeFour(translation, wide.translation);
  out.translation = Eigen::Vector3d(translation[0], translation[1], translation[2]);
  storeFour(out.rotation.coeffs().data(), wide.rotation);
}

/// Writes `wide` to `out` whole, the translation's fourth lane into the bytes after it: for a
/// value read back as whole vectors, which the processor then forwards from the two stores
/// rather than waiting for them to reach the cache. For the interpolated values of a lookup's
/// path, 1-3 % off the lookups of buffer_core_bench on pr2 and wide.
[[gnu::always_inline]] inline void storeWide(const WideTransform& wide, Transform& out) {
  storeFour(reinterpret_cast<double*>(&out), wide.translation);
  storeFour(out.rotation.coeffs().data(), wide.rotation);
}

/// The lanes of `four` in the order the indices give.
template <int A, int B, int C, int D>
[[gnu::always_inline]] inline Four shuffled(Four four) {
#if defined(__clang__) || __GNUC__ >= 12
  return __builtin_shufflevector(four, four, A, B, C, D);
#else
  return __builtin_shuffle(four, FourBits{A, B, C, D});
#endif
}

/// Lane `I` of `four` in every lane.
template <int I>
[[gnu::always_inline]] inline Four lane(Four four) {
  return shuffled<I, I, I, I>(four);
}

/// a x b in the first three lanes.
[[gnu::always_inline]] inline Four cross(Four a, Four b) {
  return shuffled<1, 2, 0, 3>(a) * shuffled<2, 0, 1, 3>(b) -
         shuffled<2, 0, 1, 3>(a) * shuffled<1, 2, 0, 3>(b);
}

/// q v q* for a unit quaternion q, as compose.hpp's rotated().
[[gnu::always_inline]] inline Four rotatedWide(Four q, Four v) {
  const Four twice_cross = 2.0 * cross(q, v);
  return v + lane<3>(q) * twice_cross + cross(q, twice_cross);
}

/// The sum of the four lanes, in every lane.
[[gnu::always_inline]] inline Four lanesSummed(Four four) {
  const Four pairs = four + shuffled<1, 0, 3, 2>(four);
  return pairs + shuffled<2, 3, 0, 1>(pairs);
}

/// rotatedWide() for a q known last, as a path's product so far is: (2w^2 - 1) v + 2 (q.v) q +
/// 2w (q x v), whose terms wait on q side by side, where rotatedWide()'s second cross product
/// waits on its first. Five instructions more; in the path products, wide's deepest lookups of
/// buffer_core_bench 4-6 % faster, the other lookups within their spread. For v with a zero
/// fourth lane, as a widened() translation has; so has the result.
[[gnu::always_inline]] inline Four rotatedByLastKnown(Four q, Four v) {
  const Four w = lane<3>(q);
  const Four twice_w = w + w;
  const Four twice_vector = firstThree(q + q);
  const Four along_v = (twice_w * w - 1.0) * v + twice_w * cross(q, v);
  return along_v + lanesSummed(q * v) * twice_vector;
}

/// The quaternion product a b. Each lane of a multiplies b's coefficients, reordered and
/// signed: b's side is ready before a chain's product so far, which then waits on four
/// multiplications, two of them at once, and one addition.
[[gnu::always_inline]] inline Four quaternionProduct(Four a, Four b) {
  const Four for_x = shuffled<3, 2, 1, 0>(b) * Four{1.0, -1.0, 1.0, -1.0};
  const Four for_y = shuffled<2, 3, 0, 1>(b) * Four{1.0, 1.0, -1.0, -1.0};
  const Four for_z = shuffled<1, 0, 3, 2>(b) * Four{-1.0, 1.0, 1.0, -1.0};
  return (lane<3>(a) * b + lane<0>(a) * for_x) + (lane<1>(a) * for_y + lane<2>(a) * for_z);
}

/// The conjugate of a quaternion: the inverse rotation of a unit one.
[[gnu::always_inline]] inline Four conjugate(Four q) { return q * Four{-1.0, -1.0, -1.0, 1.0}; }

/// above * below.
[[gnu::always_inline]] inline WideTransform composedWide(const WideTransform& above,
                                                         const WideTransform& below) {
  return WideTransform{rotatedWide(above.rotation, below.translation) + above.translation,
                       quaternionProduct(above.rotation, below.rotation)};
}

/// composedWide() where above's rotation is known last.
[[gnu::always_inline]] inline WideTransform composedUnderLastKnown(const WideTransform& above,
                                                                   const WideTransform& below) {
  return WideTransform{rotatedByLastKnown(above.rotation, below.translation) + above.translation,
                       quaternionProduct(above.rotation, below.rotation)};
}

}  // namespace lcmtf::detail
