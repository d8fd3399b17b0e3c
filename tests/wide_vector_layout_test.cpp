// Programs built with AVX (-mavx2, -march=native) see Eigen's quaternions aligned to 32 bytes,
// a library built for plain x86-64 to 16: both must still agree on the layout of every struct
// they pass each other, or each reads the other's fields at the wrong offsets.
#include <gtest/gtest.h>

#include <cstddef>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/geometry_types.hpp"
#include "wide_vector_client/wide_vector_client.hpp"

namespace lcmtf::test {
namespace {

bool processorHasWideVectors() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

TEST(WideVectorLayout, PublicStructsHaveTheSameLayoutWithAndWithoutAvx) {
  if (!processorHasWideVectors()) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  const Layout wide = layoutSeenWithWideVectors();
  EXPECT_EQ(wide.transform_size, sizeof(Transform));
  EXPECT_EQ(wide.transform_alignment, alignof(Transform));
  EXPECT_EQ(wide.transform_rotation_offset, offsetof(Transform, rotation));
  EXPECT_EQ(wide.stamped_size, sizeof(TransformStamped));
  EXPECT_EQ(wide.stamped_alignment, alignof(TransformStamped));
  EXPECT_EQ(wide.stamped_transform_offset, offsetof(TransformStamped, transform));
  EXPECT_EQ(wide.pose_with_covariance_size, sizeof(PoseWithCovariance));
  EXPECT_EQ(wide.pose_with_covariance_covariance_offset, offsetof(PoseWithCovariance, covariance));
}

TEST(WideVectorLayout, TransformsSetAndLookedUpFromAvxCodeKeepTheirValues) {
  if (!processorHasWideVectors()) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  const TransformStamped result = lookupWithWideVectors();
  // map_T_odom at 0.25 s: a quarter of the way in translation and in angle about z.
  const Transform map_T_odom({1.5, 0, 0},
                             Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ())));
  const Transform odom_T_base({0, 0, 0.5},
                              Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())));
  EXPECT_EQ(result.parent_frame, "map");
  EXPECT_EQ(result.child_frame, "base_link");
  EXPECT_EQ(toUtime(result.stamp), 250'000);
  EXPECT_TRUE(result.transform.isApprox(map_T_odom * odom_T_base, 1e-12))
      << "translation " << result.transform.translation.transpose() << ", rotation "
      << result.transform.rotation.coeffs().transpose();
}

}  // namespace
}  // namespace lcmtf::test
