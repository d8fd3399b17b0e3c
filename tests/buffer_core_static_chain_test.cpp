// BufferCore lookups through dynamic edges under chains of static edges, as those chains change.
#include <gtest/gtest.h>

#include <string>

#include "lcmtf/buffer_core.hpp"
#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::identical;
using lcmtf_test::isometry;
using lcmtf_test::near;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;

constexpr double kTolerance = 1e-12;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// world -static-> base -static-> mount -dynamic-> arm, the arm turning about z at 1 rad/s.
void buildArm(BufferCore& buffer) {
  putStatic(buffer, "world", "base", pose({1, 0, 0}, 0.5, kZ));
  putStatic(buffer, "base", "mount", pose({0, 2, 0.3}, -0.7, kX));
  for (int i = 0; i <= 4; ++i) put(buffer, "mount", "arm", at(i), pose({0.1 * i, 0, 0}, i, kZ));
}

Eigen::Isometry3d mountTArm(double t) { return isometry({0.1 * t, 0, 0}, t, kZ); }

TEST(BufferCoreStaticChain, DynamicEdgeUnderStaticChainsComposesWithTheChain) {
  BufferCore buffer;
  buildArm(buffer);
  const Eigen::Isometry3d world_T_mount =
      isometry({1, 0, 0}, 0.5, kZ) * isometry({0, 2, 0.3}, -0.7, kX);
  for (const double t : {0.0, 0.25, 1.5, 4.0}) {
    EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(t)).transform,
                     world_T_mount * mountTArm(t), kTolerance))
        << "t " << t;
    EXPECT_TRUE(near(buffer.lookupTransform("base", "arm", at(t)).transform,
                     isometry({0, 2, 0.3}, -0.7, kX) * mountTArm(t), kTolerance))
        << "t " << t;
    EXPECT_TRUE(near(buffer.lookupTransform("arm", "world", at(t)).transform,
                     (world_T_mount * mountTArm(t)).inverse(), kTolerance))
        << "t " << t;
  }
}

TEST(BufferCoreStaticChain, LookupInTheDirectParentGivesTheStoredSampleUnchanged) {
  BufferCore buffer;
  buildArm(buffer);
  const Transform sample({0.25, -0.5, 0.125}, Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5));
  put(buffer, "mount", "arm", at(5), sample);
  EXPECT_TRUE(identical(buffer.lookupTransform("mount", "arm", at(5)).transform, sample));
}

TEST(BufferCoreStaticChain, ChangingAStaticValueAboveADynamicEdgeChangesLookups) {
  BufferCore buffer;
  buildArm(buffer);
  putStatic(buffer, "world", "base", pose({-3, 1, 0}, 1.2, kY));
  const Eigen::Isometry3d world_T_mount =
      isometry({-3, 1, 0}, 1.2, kY) * isometry({0, 2, 0.3}, -0.7, kX);
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(2.5)).transform,
                   world_T_mount * mountTArm(2.5), kTolerance));
  // Samples stored after the change too.
  put(buffer, "mount", "arm", at(5), pose({0.5, 0, 0}, 5, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(4.5)).transform,
                   world_T_mount * mountTArm(4.5), kTolerance));
}

TEST(BufferCoreStaticChain, RedeclaringTheStaticChainUnderAnotherRootChangesLookups) {
  BufferCore buffer;
  buildArm(buffer);
  putStatic(buffer, "cart", "mount", pose({0, 0, 1}, 0.4, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("cart", "arm", at(1.5)).transform,
                   isometry({0, 0, 1}, 0.4, kZ) * mountTArm(1.5), kTolerance));
  std::string why;
  EXPECT_FALSE(buffer.canTransform("world", "arm", at(1.5), &why));
  EXPECT_NE(why.find("not connected"), std::string::npos) << why;
  EXPECT_TRUE(near(buffer.lookupTransform("base", "world", at(1.5)).transform,
                   isometry({1, 0, 0}, 0.5, kZ).inverse(), kTolerance));
}

TEST(BufferCoreStaticChain, StaticChainDeclaredAfterTheSamplesApplies) {
  BufferCore buffer;
  for (int i = 0; i <= 4; ++i) put(buffer, "mount", "arm", at(i), pose({0.1 * i, 0, 0}, i, kZ));
  putStatic(buffer, "world", "mount", pose({0, 0, 2}, 0.9, kX));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(3.5)).transform,
                   isometry({0, 0, 2}, 0.9, kX) * mountTArm(3.5), kTolerance));
}

TEST(BufferCoreStaticChain, StaticEdgeTurnedDynamicAboveADynamicEdge) {
  BufferCore buffer;
  buildArm(buffer);
  put(buffer, "base", "mount", at(1), pose({0, 0, 0.5}, 0.2, kY));
  put(buffer, "base", "mount", at(3), pose({0, 0, 0.5}, 0.6, kY));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(2)).transform,
                   isometry({1, 0, 0}, 0.5, kZ) * isometry({0, 0, 0.5}, 0.4, kY) * mountTArm(2),
                   kTolerance));
  EXPECT_TRUE(
      near(buffer.lookupTransform("mount", "arm", at(2)).transform, mountTArm(2), kTolerance));
  // And static again.
  putStatic(buffer, "base", "mount", pose({0, 2, 0.3}, -0.7, kX));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(2)).transform,
                   isometry({1, 0, 0}, 0.5, kZ) * isometry({0, 2, 0.3}, -0.7, kX) * mountTArm(2),
                   kTolerance));
}

TEST(BufferCoreStaticChain, SiblingsUnderOneStaticChainSeeEachOther) {
  BufferCore buffer;
  buildArm(buffer);
  for (int i = 0; i <= 4; ++i) put(buffer, "mount", "leg", at(i), pose({0, 0.2 * i, 0}, -i, kX));
  const Eigen::Isometry3d mount_T_leg = isometry({0, 0.2 * 1.5, 0}, -1.5, kX);
  EXPECT_TRUE(near(buffer.lookupTransform("leg", "arm", at(1.5)).transform,
                   mount_T_leg.inverse() * mountTArm(1.5), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("base", "leg", at(1.5)).transform,
                   isometry({0, 2, 0.3}, -0.7, kX) * mount_T_leg, kTolerance));
}

TEST(BufferCoreStaticChain, ReparentedDynamicEdgeUsesTheChainOfEachParent) {
  BufferCore buffer;
  buildArm(buffer);
  putStatic(buffer, "world", "table", pose({4, 0, 0.8}, 0, kZ));
  put(buffer, "table", "arm", at(6), pose({0, 0, 0}, 0, kZ));
  put(buffer, "table", "arm", at(7), pose({1, 0, 0}, 0, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(6.5)).transform,
                   isometry({4.5, 0, 0.8}, 0, kZ), kTolerance));
  const Eigen::Isometry3d world_T_mount =
      isometry({1, 0, 0}, 0.5, kZ) * isometry({0, 2, 0.3}, -0.7, kX);
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(2.5)).transform,
                   world_T_mount * mountTArm(2.5), kTolerance));
  putStatic(buffer, "world", "base", pose({0, 0, 0}, 0, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(2.5)).transform,
                   isometry({0, 2, 0.3}, -0.7, kX) * mountTArm(2.5), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(6.5)).transform,
                   isometry({4.5, 0, 0.8}, 0, kZ), kTolerance));
}

TEST(BufferCoreStaticChain, ExtrapolationErrorNamesTheEdgeItself) {
  BufferCore buffer;
  buildArm(buffer);
  std::string why;
  EXPECT_FALSE(buffer.canTransform("world", "arm", at(9), &why));
  EXPECT_NE(why.find("'mount' -> 'arm'"), std::string::npos) << why;
}

}  // namespace
}  // namespace lcmtf
