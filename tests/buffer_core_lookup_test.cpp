// BufferCore lookups: walking the tree, composing, interpolating, latest time, time travel.
#include "lcmtf/buffer_core.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::axisAngle;
using lcmtf_test::identical;
using lcmtf_test::isometry;
using lcmtf_test::near;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-12;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// world -> base -> arm -> hand, each edge a different rotation about a different axis.
struct Chain {
  Eigen::Isometry3d world_T_base = isometry({1, 2, 0}, 0.3, kZ);
  Eigen::Isometry3d base_T_arm = isometry({0, 0.5, 1.2}, -1.1, {1, 1, 0});
  Eigen::Isometry3d arm_T_hand = isometry({0.7, 0, 0}, 2.4, {0, 1, -2});

  explicit Chain(BufferCore& buffer, TimePoint stamp) {
    put(buffer, "world", "base", stamp, pose({1, 2, 0}, 0.3, kZ));
    put(buffer, "base", "arm", stamp, pose({0, 0.5, 1.2}, -1.1, {1, 1, 0}));
    put(buffer, "arm", "hand", stamp, pose({0.7, 0, 0}, 2.4, {0, 1, -2}));
  }
};

TEST(BufferCoreLookup, LookupAlongChainComposesEdgesFromTargetDownToSource) {
  BufferCore buffer;
  const Chain chain(buffer, at(1));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "hand", at(1)).transform,
                   chain.world_T_base * chain.base_T_arm * chain.arm_T_hand, kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("base", "hand", at(1)).transform,
                   chain.base_T_arm * chain.arm_T_hand, kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "arm", at(1)).transform,
                   chain.world_T_base * chain.base_T_arm, kTolerance));
}

TEST(BufferCoreLookup, LookupAgainstChainDirectionReturnsTheInverse) {
  BufferCore buffer;
  const Chain chain(buffer, at(1));
  EXPECT_TRUE(near(buffer.lookupTransform("hand", "world", at(1)).transform,
                   (chain.world_T_base * chain.base_T_arm * chain.arm_T_hand).inverse(),
                   kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("arm", "base", at(1)).transform,
                   chain.base_T_arm.inverse(), kTolerance));
}

TEST(BufferCoreLookup, LookupResultMapsPointsFromSourceIntoTarget) {
  BufferCore buffer;
  const Chain chain(buffer, at(1));
  const Eigen::Vector3d point_in_hand(0.1, -0.2, 0.3);
  const Transform world_T_hand = buffer.lookupTransform("world", "hand", at(1)).transform;
  const Eigen::Vector3d expected =
      chain.world_T_base * (chain.base_T_arm * (chain.arm_T_hand * point_in_hand));
  EXPECT_LE((world_T_hand * point_in_hand - expected).norm(), kTolerance);
}

TEST(BufferCoreLookup, LookupResultNamesTargetAsParentSourceAsChildAndRequestedStamp) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(2), pose({2, 0, 0}, 0, kZ));
  const TransformStamped result = buffer.lookupTransform("base", "world", at(1.25));
  EXPECT_EQ(result.parent_frame, "base");
  EXPECT_EQ(result.child_frame, "world");
  EXPECT_EQ(result.stamp, at(1.25));
}

TEST(BufferCoreLookup, LookupOfFrameInItselfIsIdentityAtTheRequestedTime) {
  BufferCore buffer;
  const Chain chain(buffer, at(1));
  const TransformStamped result = buffer.lookupTransform("arm", "arm", at(1));
  EXPECT_TRUE(identical(result.transform, Transform::identity()));
  EXPECT_EQ(result.parent_frame, "arm");
  EXPECT_EQ(result.child_frame, "arm");
  EXPECT_EQ(result.stamp, at(1));
}

TEST(BufferCoreLookup, StaticEdgeHasTheSameValueAtEveryTime) {
  BufferCore buffer;
  putStatic(buffer, "base", "laser", pose({0.3, 0, 0.2}, 0.5, kZ));
  const Eigen::Isometry3d expected = isometry({0.3, 0, 0.2}, 0.5, kZ);
  for (const TimePoint t : {kLatestTime, at(-1e6), at(0), at(123.456789), fromUtime(1)}) {
    EXPECT_TRUE(near(buffer.lookupTransform("base", "laser", t).transform, expected, kTolerance));
  }
}

TEST(BufferCoreLookup, LookupAcrossVShapedTreeGoesThroughTheSharedParent) {
  BufferCore buffer;
  put(buffer, "world", "left", at(1), pose({1, 0, 0}, 0.4, kZ));
  put(buffer, "world", "right", at(1), pose({0, -2, 1}, -0.9, kX));
  const Eigen::Isometry3d world_T_left = isometry({1, 0, 0}, 0.4, kZ);
  const Eigen::Isometry3d world_T_right = isometry({0, -2, 1}, -0.9, kX);
  EXPECT_TRUE(near(buffer.lookupTransform("left", "right", at(1)).transform,
                   world_T_left.inverse() * world_T_right, kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("right", "left", at(1)).transform,
                   world_T_right.inverse() * world_T_left, kTolerance));
}

// world -> base, base -> left_arm -> left_hand, base -> right_arm -> right_hand.
struct YTree {
  Eigen::Isometry3d world_T_base = isometry({5, 5, 0}, 1.0, kZ);
  Eigen::Isometry3d base_T_left_arm = isometry({0, 0.3, 1}, 0.2, kX);
  Eigen::Isometry3d left_arm_T_left_hand = isometry({0.6, 0, 0}, -0.7, kY);
  Eigen::Isometry3d base_T_right_arm = isometry({0, -0.3, 1}, -0.2, kX);
  Eigen::Isometry3d right_arm_T_right_hand = isometry({0.6, 0.1, 0}, 1.3, {1, 2, 3});

  YTree(BufferCore& buffer, TimePoint base_stamp, TimePoint arms_stamp) {
    put(buffer, "world", "base", base_stamp, pose({5, 5, 0}, 1.0, kZ));
    put(buffer, "base", "left_arm", arms_stamp, pose({0, 0.3, 1}, 0.2, kX));
    put(buffer, "left_arm", "left_hand", arms_stamp, pose({0.6, 0, 0}, -0.7, kY));
    put(buffer, "base", "right_arm", arms_stamp, pose({0, -0.3, 1}, -0.2, kX));
    put(buffer, "right_arm", "right_hand", arms_stamp, pose({0.6, 0.1, 0}, 1.3, {1, 2, 3}));
  }
  Eigen::Isometry3d base_T_left_hand() const { return base_T_left_arm * left_arm_T_left_hand; }
  Eigen::Isometry3d base_T_right_hand() const { return base_T_right_arm * right_arm_T_right_hand; }
};

TEST(BufferCoreLookup, LookupAcrossYShapedTreeGoesThroughTheCommonAncestor) {
  BufferCore buffer;
  const YTree tree(buffer, at(1), at(1));
  EXPECT_TRUE(near(buffer.lookupTransform("left_hand", "right_hand", at(1)).transform,
                   tree.base_T_left_hand().inverse() * tree.base_T_right_hand(), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("right_hand", "left_hand", at(1)).transform,
                   tree.base_T_right_hand().inverse() * tree.base_T_left_hand(), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "right_hand", at(1)).transform,
                   tree.world_T_base * tree.base_T_right_hand(), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("left_arm", "world", at(1)).transform,
                   (tree.world_T_base * tree.base_T_left_arm).inverse(), kTolerance));
}

TEST(BufferCoreLookup, LookupWalksOnlyToTheCommonAncestor) {
  BufferCore buffer;
  // world -> base has data only at t = 100; the arms only at t = 1.
  const YTree tree(buffer, at(100), at(1));
  EXPECT_TRUE(near(buffer.lookupTransform("left_hand", "right_hand", at(1)).transform,
                   tree.base_T_left_hand().inverse() * tree.base_T_right_hand(), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("base", "left_hand", at(1)).transform,
                   tree.base_T_left_hand(), kTolerance));
  EXPECT_THROW(buffer.lookupTransform("world", "left_hand", at(1)), PastExtrapolationException);
}

TEST(BufferCoreLookup, CompoundRotationsMatchEigenComposedExpectations) {
  // A random tree: every frame's parent is an earlier frame, every edge a random rotation about
  // a random axis and a random translation. world_T_frame is composed with Eigen alone.
  BufferCore buffer;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::string> names{"f0"};
  std::vector<Eigen::Isometry3d> root_T_frame{Eigen::Isometry3d::Identity()};
  for (std::size_t i = 1; i < 24; ++i) {
    const std::size_t parent = std::uniform_int_distribution<std::size_t>(0, i - 1)(random);
    const Eigen::Vector3d translation(3 * unit(random), 3 * unit(random), 3 * unit(random));
    const double angle = kPi * unit(random);
    const Eigen::Vector3d axis(unit(random), unit(random), unit(random));
    names.push_back("f" + std::to_string(i));
    put(buffer, names[parent], names[i], at(1), pose(translation, angle, axis));
    root_T_frame.push_back(root_T_frame[parent] * isometry(translation, angle, axis));
  }
  for (std::size_t target = 0; target < names.size(); ++target) {
    for (std::size_t source = 0; source < names.size(); ++source) {
      EXPECT_TRUE(near(buffer.lookupTransform(names[target], names[source], at(1)).transform,
                       root_T_frame[target].inverse() * root_T_frame[source], 1e-11))
          << names[source] << " in " << names[target];
    }
  }
}

TEST(BufferCoreLookup, CompoundRotationsAboutMixedAxesComposeInChainOrder) {
  // Rotations that do not commute: getting the order wrong moves the result by metres.
  BufferCore buffer;
  putStatic(buffer, "a", "b", pose({1, 0, 0}, kPi / 2, kZ));
  putStatic(buffer, "b", "c", pose({0, 1, 0}, kPi / 2, kX));
  putStatic(buffer, "c", "d", pose({0, 0, 1}, kPi / 2, kY));
  const Eigen::Isometry3d expected = isometry({1, 0, 0}, kPi / 2, kZ) *
                                     isometry({0, 1, 0}, kPi / 2, kX) *
                                     isometry({0, 0, 1}, kPi / 2, kY);
  const Transform a_T_d = buffer.lookupTransform("a", "d", kLatestTime).transform;
  EXPECT_TRUE(near(a_T_d, expected, kTolerance));
  // By hand: d's origin is c's (0,0,1) = b's (0,0,0) = a's (1,0,0); d's x axis is c's -z,
  // b's +y, a's -x.
  EXPECT_LE((a_T_d.translation - Eigen::Vector3d(1, 0, 0)).norm(), kTolerance);
  EXPECT_LE((a_T_d * Eigen::Vector3d(1, 0, 0)).norm(), kTolerance);
}

// ring_0 -> ring_1 -> ... -> ring_8: each link moves 1 m along its parent's x axis and turns
// 45 degrees about z, so the frames sit on a regular octagon and ring_8 lands on ring_0.
class RingOfEight : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i < 8; ++i) {
      put(buffer_, name(i), name(i + 1), at(1), pose({1, 0, 0}, kPi / 4, kZ));
    }
  }
  static std::string name(int i) { return "ring_" + std::to_string(i); }
  // ring_0_T_ring_i in closed form: heading i*45 degrees, position the sum of unit steps.
  static Eigen::Isometry3d ring0_T(int i) {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    for (int j = 0; j < i; ++j)
      position += Eigen::Vector3d(std::cos(j * kPi / 4), std::sin(j * kPi / 4), 0);
    Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
    result.translation() = position;
    result.linear() << std::cos(i * kPi / 4), -std::sin(i * kPi / 4), 0, std::sin(i * kPi / 4),
        std::cos(i * kPi / 4), 0, 0, 0, 1;
    return result;
  }
  BufferCore buffer_;
};

TEST_F(RingOfEight, ComposingAllEightLinksReturnsToTheStart) {
  EXPECT_TRUE(near(buffer_.lookupTransform("ring_0", "ring_8", at(1)).transform,
                   Eigen::Isometry3d::Identity(), kTolerance));
  EXPECT_TRUE(near(buffer_.lookupTransform("ring_8", "ring_0", at(1)).transform,
                   Eigen::Isometry3d::Identity(), kTolerance));
}

TEST_F(RingOfEight, OppositeFrameIsAcrossTheOctagonAndTurnedHalfWay) {
  const Transform ring0_T_ring4 = buffer_.lookupTransform("ring_0", "ring_4", at(1)).transform;
  EXPECT_LE((ring0_T_ring4.translation - Eigen::Vector3d(1, 1 + std::sqrt(2.0), 0)).norm(),
            kTolerance);
  EXPECT_LE(angularDistance(ring0_T_ring4.rotation, axisAngle(kPi, kZ)), kTolerance);
}

TEST_F(RingOfEight, EveryPairMatchesTheOctagonClosedForm) {
  for (int target = 0; target <= 8; ++target) {
    for (int source = 0; source <= 8; ++source) {
      EXPECT_TRUE(near(buffer_.lookupTransform(name(target), name(source), at(1)).transform,
                       ring0_T(target).inverse() * ring0_T(source), kTolerance))
          << name(source) << " in " << name(target);
    }
  }
}

TEST(BufferCoreLookup, LookupExactlyOnASampleReturnsThatSampleUnchanged) {
  BufferCore buffer;
  const Transform first({1.5, -2.25, 3}, Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5));
  const Transform second({-7, 0.125, 1}, Eigen::Quaterniond(0, 0, 1, 0));
  const Transform third({4, 4, 4}, Eigen::Quaterniond(1, 0, 0, 0));
  put(buffer, "world", "robot", at(1), first);
  put(buffer, "world", "robot", at(2), second);
  put(buffer, "world", "robot", at(3), third);
  EXPECT_TRUE(identical(buffer.lookupTransform("world", "robot", at(1)).transform, first));
  EXPECT_TRUE(identical(buffer.lookupTransform("world", "robot", at(2)).transform, second));
  EXPECT_TRUE(identical(buffer.lookupTransform("world", "robot", at(3)).transform, third));
}

TEST(BufferCoreLookup, LookupBetweenSamplesInterpolatesTranslationLinearly) {
  BufferCore buffer;
  put(buffer, "world", "robot", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "robot", at(3), pose({2, 4, -6}, 0, kZ));
  for (int step = 0; step <= 200; ++step) {
    const double ratio = step / 200.0;
    const Transform value = buffer.lookupTransform("world", "robot", at(1 + 2 * ratio)).transform;
    EXPECT_LE((value.translation - ratio * Eigen::Vector3d(2, 4, -6)).norm(), kTolerance)
        << "ratio " << ratio;
    EXPECT_LE(angularDistance(value.rotation, Eigen::Quaterniond::Identity()), kTolerance);
  }
  // A quarter of the way, to the microsecond.
  EXPECT_LE((buffer.lookupTransform("world", "robot", at(1.5)).transform.translation -
             Eigen::Vector3d(0.5, 1, -1.5))
                .norm(),
            kTolerance);
}

TEST(BufferCoreLookup, LookupBetweenSamplesSlerpsRotationAtConstantAngularRate) {
  // From 0.2 rad to 2.9 rad about one axis: slerp is that axis at the linearly mixed angle.
  BufferCore buffer;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  put(buffer, "world", "robot", at(10), pose({0, 0, 0}, 0.2, axis));
  put(buffer, "world", "robot", at(11), pose({0, 0, 0}, 2.9, axis));
  for (int micros = 0; micros <= 1'000'000; micros += 997) {
    const double ratio = micros / 1e6;
    const TimePoint t = at(10) + Duration(micros);
    const Transform value = buffer.lookupTransform("world", "robot", t).transform;
    EXPECT_TRUE(near(value, isometry({0, 0, 0}, 0.2 + 2.7 * ratio, axis), kTolerance))
        << "ratio " << ratio;
    EXPECT_NEAR(value.rotation.norm(), 1.0, 1e-15);
  }
}

TEST(BufferCoreLookup, SlerpTakesTheShortestArc) {
  // From +170 to -170 degrees yaw the short way is through 180, not through 0.
  BufferCore buffer;
  put(buffer, "world", "robot", at(1), pose({0, 0, 0}, 170 * kPi / 180, kZ));
  put(buffer, "world", "robot", at(2), pose({0, 0, 0}, -170 * kPi / 180, kZ));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "robot", at(1.5)).transform,
                   isometry({0, 0, 0}, kPi, kZ), kTolerance));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "robot", at(1.25)).transform,
                   isometry({0, 0, 0}, 175 * kPi / 180, kZ), kTolerance));
}

TEST(BufferCoreLookup, SlerpIgnoresTheSignOfTheQuaternion) {
  BufferCore buffer;
  const Eigen::Quaterniond start = axisAngle(0.4, kY);
  const Eigen::Quaterniond end = axisAngle(1.4, kY);
  put(buffer, "world", "robot", at(1), Transform({0, 0, 0}, start));
  put(buffer, "world", "robot", at(2), Transform({0, 0, 0}, Eigen::Quaterniond(-end.coeffs())));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "robot", at(1.3)).transform,
                   isometry({0, 0, 0}, 0.7, kY), kTolerance));
}

TEST(BufferCoreLookup, LookupInterpolatesEveryDynamicEdgeOnThePathAtTheSameTime) {
  // odom -> base drives along x at 1 m/s; base -> head turns about z at 0.5 rad/s.
  BufferCore buffer;
  for (int i = 0; i <= 10; ++i) {
    put(buffer, "odom", "base", at(i), pose({1.0 * i, 0, 0}, 0, kZ));
    put(buffer, "base", "head", at(i), pose({0, 0, 1}, 0.5 * i, kZ));
  }
  putStatic(buffer, "head", "camera", pose({0.1, 0, 0}, -kPi / 2, kX));
  for (std::int64_t micros = 0; micros <= 10'000'000; micros += 370'001) {
    const double t = static_cast<double>(micros) / 1e6;
    const Eigen::Isometry3d expected = isometry({t, 0, 0}, 0, kZ) *
                                       isometry({0, 0, 1}, 0.5 * t, kZ) *
                                       isometry({0.1, 0, 0}, -kPi / 2, kX);
    EXPECT_TRUE(near(buffer.lookupTransform("odom", "camera", at(t)).transform, expected, 1e-11))
        << "t " << t;
  }
}

// link_0 -> link_1 -> ... -> link_7, every edge moving: edge i slides along y at (i + 1) cm/s and
// turns about its own axis at 0.1 (i + 1) rad/s, sampled once a second from `first[i]` s to
// 10 s.
struct MovingChain {
  static constexpr int kEdges = 7;
  Eigen::Vector3d axes[kEdges] = {kX, kY, kZ, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};

  MovingChain(BufferCore& buffer, const int (&first)[kEdges]) {
    for (int edge = 0; edge < kEdges; ++edge) {
      for (int i = first[edge]; i <= 10; ++i) {
        const double t = i;
        put(buffer, name(edge), name(edge + 1), at(t), poseAt(edge, t));
      }
    }
  }
  static std::string name(int link) { return "link_" + std::to_string(link); }
  Transform poseAt(int edge, double t) const {
    return pose({0, 0.01 * (edge + 1) * t, 0}, 0.1 * (edge + 1) * t, axes[edge]);
  }
  // link_from's pose in link_to (to < from), each edge at time t.
  Eigen::Isometry3d expected(int to, int from, double t) const {
    Eigen::Isometry3d product = Eigen::Isometry3d::Identity();
    for (int edge = to; edge < from; ++edge) {
      product = product * isometry({0, 0.01 * (edge + 1) * t, 0}, 0.1 * (edge + 1) * t, axes[edge]);
    }
    return product;
  }
};

TEST(BufferCoreLookup, PathsOfFewAndOfManyDynamicEdgesInterpolateEveryEdge) {
  BufferCore buffer;
  const MovingChain chain(buffer, {0, 0, 0, 0, 0, 0, 0});
  const std::pair<int, int> pairs[] = {{0, 7}, {0, 2}, {3, 7}, {1, 6}, {6, 7}};
  for (const auto& [to, from] : pairs) {
    for (double t = 0.0; t <= 10.0; t += 0.73) {
      const Eigen::Isometry3d expected = chain.expected(to, from, t);
      EXPECT_TRUE(near(
          buffer.lookupTransform(MovingChain::name(to), MovingChain::name(from), at(t)).transform,
          expected, 1e-11))
          << to << " <- " << from << " at " << t;
      EXPECT_TRUE(near(
          buffer.lookupTransform(MovingChain::name(from), MovingChain::name(to), at(t)).transform,
          expected.inverse(), 1e-11))
          << from << " <- " << to << " at " << t;
    }
  }
}

TEST(BufferCoreLookup, AnEdgeWithoutDataAtTheTimeFailsPathsOfFewAndOfManyEdges) {
  // link_4 -> link_5 starts at 3 s; every other edge at 0 s.
  BufferCore buffer;
  const MovingChain chain(buffer, {0, 0, 0, 0, 3, 0, 0});
  for (const auto& [to, from] : {std::pair{0, 7}, std::pair{3, 6}, std::pair{4, 5}}) {
    for (const auto& [target, source] : {std::pair{to, from}, std::pair{from, to}}) {
      EXPECT_THROW(
          buffer.lookupTransform(MovingChain::name(target), MovingChain::name(source), at(2.5)),
          ExtrapolationException)
          << target << " <- " << source;
      EXPECT_TRUE(
          buffer.canTransform(MovingChain::name(target), MovingChain::name(source), at(3.5)))
          << target << " <- " << source;
    }
    EXPECT_TRUE(near(
        buffer.lookupTransform(MovingChain::name(to), MovingChain::name(from), at(3.5)).transform,
        chain.expected(to, from, 3.5), 1e-11));
  }
  // A path that leaves the late edge out has data from 0 s.
  EXPECT_TRUE(near(buffer.lookupTransform("link_0", "link_4", at(2.5)).transform,
                   chain.expected(0, 4, 2.5), 1e-11));
}

TEST(BufferCoreLookup, BracketingSamplesWithDifferentParentsUseTheOlderSampleUnchanged) {
  BufferCore buffer;
  putStatic(buffer, "world", "table", pose({2, 0, 0.8}, 0, kZ));
  putStatic(buffer, "world", "shelf", pose({-3, 1, 1.5}, kPi / 2, kZ));
  // Quaternions of exactly unit norm (w, x, y, z), so the stored samples are the given bits.
  const Transform on_table({0.1, 0.2, 0}, Eigen::Quaterniond(0.5, -0.5, 0.5, 0.5));
  const Transform on_shelf({0, 0, 0.05}, Eigen::Quaterniond(0, 0, 0, 1));
  put(buffer, "table", "cup", at(1), on_table);
  put(buffer, "shelf", "cup", at(2), on_shelf);
  for (const double t : {1.0, 1.000001, 1.5, 1.999999}) {
    const TransformStamped table_T_cup = buffer.lookupTransform("table", "cup", at(t));
    EXPECT_TRUE(identical(table_T_cup.transform, on_table)) << "t " << t;
    EXPECT_TRUE(near(buffer.lookupTransform("world", "cup", at(t)).transform,
                     isometry({2, 0, 0.8}, 0, kZ) * Eigen::Translation3d(0.1, 0.2, 0) *
                         Eigen::Quaterniond(0.5, -0.5, 0.5, 0.5),
                     kTolerance));
    std::string parent;
    ASSERT_TRUE(buffer.getParent("cup", at(t), parent));
    EXPECT_EQ(parent, "table");
  }
  EXPECT_TRUE(identical(buffer.lookupTransform("shelf", "cup", at(2)).transform, on_shelf));
  std::string parent;
  ASSERT_TRUE(buffer.getParent("cup", at(2), parent));
  EXPECT_EQ(parent, "shelf");
}

TEST(BufferCoreLookup, ObjectPickedUpFromTheTableFollowsTheGripper) {
  // The gripper moves along y at 0.1 m/s; at t = 5 it picks the object up off the table, and the
  // object then rides 0.05 m below the gripper.
  BufferCore buffer;
  putStatic(buffer, "world", "table", pose({1, 0, 0.7}, 0, kZ));
  for (int i = 0; i <= 10; ++i) {
    put(buffer, "world", "gripper", at(i), pose({1, 0.1 * i, 1.2}, kPi, kX));
  }
  for (int i = 0; i <= 4; ++i) put(buffer, "table", "object", at(i), pose({0, 0.5, 0}, 0, kZ));
  for (int i = 5; i <= 10; ++i)
    put(buffer, "gripper", "object", at(i), pose({0, 0, 0.05}, kPi, kX));

  for (const double t : {0.0, 2.5, 4.0, 4.5, 4.999999}) {
    EXPECT_TRUE(near(buffer.lookupTransform("world", "object", at(t)).transform,
                     isometry({1, 0.5, 0.7}, 0, kZ), kTolerance))
        << "t " << t;
  }
  for (const double t : {5.0, 6.5, 10.0}) {
    const Eigen::Isometry3d world_T_object =
        isometry({1, 0.1 * t, 1.2}, kPi, kX) * isometry({0, 0, 0.05}, kPi, kX);
    EXPECT_TRUE(near(buffer.lookupTransform("world", "object", at(t)).transform, world_T_object,
                     kTolerance))
        << "t " << t;
    EXPECT_LE((world_T_object.translation() - Eigen::Vector3d(1, 0.1 * t, 1.15)).norm(), 1e-12);
  }
  std::string parent;
  ASSERT_TRUE(buffer.getParent("object", at(4.5), parent));
  EXPECT_EQ(parent, "table");
  ASSERT_TRUE(buffer.getParent("object", at(5), parent));
  EXPECT_EQ(parent, "gripper");
  ASSERT_TRUE(buffer.getParent("object", kLatestTime, parent));
  EXPECT_EQ(parent, "gripper");
}

TEST(BufferCoreLookup, LatestTimeIsTheOldestNewestStampOfTheDynamicEdgesOnThePath) {
  // world =static=> base -(dynamic, newest 5)-> arm =static=> tool, world -(dynamic, newest 3)->
  // other.
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({0, 0, 0.5}, 0, kZ));
  for (int i = 1; i <= 5; ++i)
    put(buffer, "base", "arm", at(i), pose({0.1 * i, 0, 0}, 0.1 * i, kZ));
  putStatic(buffer, "arm", "tool", pose({0, 0, 0.2}, kPi / 2, kY));
  for (int i = 0; i <= 3; ++i) put(buffer, "world", "other", at(i), pose({-1.0 * i, 0, 0}, 0, kZ));

  const TransformStamped world_T_tool = buffer.lookupTransform("world", "tool", kLatestTime);
  EXPECT_EQ(world_T_tool.stamp, at(5));
  EXPECT_TRUE(
      identical(world_T_tool.transform, buffer.lookupTransform("world", "tool", at(5)).transform));

  const TransformStamped other_T_tool = buffer.lookupTransform("other", "tool", kLatestTime);
  EXPECT_EQ(other_T_tool.stamp, at(3));
  EXPECT_TRUE(
      identical(other_T_tool.transform, buffer.lookupTransform("other", "tool", at(3)).transform));
  EXPECT_EQ(other_T_tool.parent_frame, "other");
  EXPECT_EQ(other_T_tool.child_frame, "tool");

  EXPECT_EQ(buffer.getLatestCommonTime("world", "tool"), at(5));
  EXPECT_EQ(buffer.getLatestCommonTime("tool", "other"), at(3));
  EXPECT_EQ(buffer.getLatestCommonTime("other", "world"), at(3));
}

TEST(BufferCoreLookup, LatestTimeLookupIsTheLookupAtTheLatestCommonTime) {
  // map -> odom (100 Hz) =static=> base -> arm (30 Hz) =static=> tool, and map =static=> mount ->
  // camera (about 50 Hz, stamps uneven): each new sample moves the latest common time, which
  // falls on a newest sample, between the two newest, or further back.
  BufferCore buffer(std::chrono::seconds(10));
  putStatic(buffer, "odom", "base", pose({0.1, 0, 0.3}, 0.2, kZ));
  putStatic(buffer, "arm", "tool", pose({0, 0, 0.2}, kPi / 2, kY));
  putStatic(buffer, "map", "mount", pose({2, 1, 1.5}, -0.4, {1, 0, 1}));
  const std::vector<std::string> frames = {"map", "odom", "base", "arm", "tool", "mount", "camera"};
  std::mt19937_64 random(5);
  std::uniform_int_distribution<std::int64_t> jitter(-3000, 3000);
  std::int64_t odom_next = 3'000;
  std::int64_t arm_next = 7'000;
  std::int64_t camera_next = 11'000;
  const auto stampOf = [](std::int64_t micros) {
    return lcmtf_test::kEpoch + std::chrono::microseconds(micros);
  };
  const auto seconds = [](std::int64_t micros) { return 1e-6 * static_cast<double>(micros); };
  std::size_t checked = 0;
  for (std::int64_t now = 0; now < 400'000; now += 1'000) {
    if (now >= odom_next) {
      put(buffer, "map", "odom", stampOf(odom_next),
          pose({seconds(odom_next), 0.5, 0}, 0.7 * seconds(odom_next), kZ));
      odom_next += 10'000;
    }
    if (now >= arm_next) {
      put(buffer, "base", "arm", stampOf(arm_next),
          pose({0, 0.2, 0.9}, -2.1 * seconds(arm_next), {1, 1, 0}));
      arm_next += 33'333;
    }
    if (now >= camera_next) {
      put(buffer, "mount", "camera", stampOf(camera_next),
          pose({0, 0, 0.05}, 1.3 * seconds(camera_next), {0, 1, 2}));
      camera_next += 20'000 + jitter(random);
    }
    for (const std::string& target : frames) {
      for (const std::string& source : frames) {
        if (target == source || !buffer.canTransform(target, source, kLatestTime)) continue;
        const TransformStamped latest = buffer.lookupTransform(target, source, kLatestTime);
        ASSERT_EQ(latest.stamp, buffer.getLatestCommonTime(target, source))
            << source << " in " << target;
        ASSERT_TRUE(identical(latest.transform,
                              buffer.lookupTransform(target, source, latest.stamp).transform))
            << source << " in " << target << " at " << toUtime(latest.stamp);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 10'000u);
}

TEST(BufferCoreLookup, LatestTimeOverOnlyStaticEdgesHasStampZero) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({0, 0, 0.5}, 0.1, kZ));
  putStatic(buffer, "base", "laser", pose({0.2, 0, 0.1}, kPi, kX));
  put(buffer, "world", "other", at(3), pose({1, 0, 0}, 0, kZ));  // off the path
  const TransformStamped result = buffer.lookupTransform("laser", "world", kLatestTime);
  EXPECT_EQ(result.stamp, TimePoint{});
  EXPECT_TRUE(near(result.transform,
                   (isometry({0, 0, 0.5}, 0.1, kZ) * isometry({0.2, 0, 0.1}, kPi, kX)).inverse(),
                   kTolerance));
  EXPECT_EQ(buffer.getLatestCommonTime("laser", "world"), TimePoint{});
  EXPECT_EQ(buffer.getLatestCommonTime("base", "laser"), TimePoint{});
}

TEST(BufferCoreLookup, LatestTimeLookupFailsWhenTheEdgesShareNoTime) {
  // a -> b has data only at 1, b -> c only at 5: no time has data on both.
  BufferCore buffer;
  put(buffer, "a", "b", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "b", "c", at(5), pose({0, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.getLatestCommonTime("a", "c"), at(1));
  EXPECT_THROW(buffer.lookupTransform("a", "c", kLatestTime), PastExtrapolationException);
  EXPECT_FALSE(buffer.canTransform("a", "c", kLatestTime));
  put(buffer, "a", "b", at(6), pose({0, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.lookupTransform("a", "c", kLatestTime).stamp, at(5));
}

TEST(BufferCoreLookup, LatestCommonTimeIgnoresEdgesAboveTheCommonAncestor) {
  BufferCore buffer;
  put(buffer, "world", "base", at(100), pose({0, 0, 0}, 0, kZ));
  put(buffer, "base", "left", at(5), pose({0, 1, 0}, 0, kZ));
  put(buffer, "base", "left", at(7), pose({0, 2, 0}, 0, kZ));
  put(buffer, "base", "right", at(6), pose({0, -1, 0}, 0, kZ));
  EXPECT_EQ(buffer.getLatestCommonTime("left", "right"), at(6));
  EXPECT_EQ(buffer.lookupTransform("left", "right", kLatestTime).stamp, at(6));
  EXPECT_EQ(buffer.getLatestCommonTime("left", "base"), at(7));
  EXPECT_EQ(buffer.getLatestCommonTime("world", "left"), at(7));
}

// x hangs from c until 3 s, then from a; c from b (data at 2 s only), b from a (at 4 s only).
// In the tree as of the newest samples x and c meet at a, where x's and c's newest samples
// last overlap at 2 s; at 2 s x hangs from c, so b's edge, which has no data then, is not on
// the way. tf answers 2 s with x's older sample.
class LatestTimeAcrossAParentChange : public ::testing::Test {
 protected:
  void SetUp() override {
    put(buffer_, "c", "x", at(1), pose({1, 0, 0}, 0, kZ));
    put(buffer_, "a", "x", at(3), pose({0, 3, 0}, 0, kZ));
    put(buffer_, "b", "c", at(2), pose({0, 0, 2}, 0, kZ));
    put(buffer_, "a", "b", at(4), pose({0, 0, 4}, 0, kZ));
  }
  BufferCore buffer_;
};

TEST_F(LatestTimeAcrossAParentChange, LatestLookupIsMadeInTheTreeAsItWasAtTheLatestCommonTime) {
  EXPECT_EQ(buffer_.getLatestCommonTime("c", "x"), at(2));
  const TransformStamped c_T_x = buffer_.lookupTransform("c", "x", kLatestTime);
  EXPECT_EQ(c_T_x.stamp, at(2));
  EXPECT_TRUE(identical(c_T_x.transform, pose({1, 0, 0}, 0, kZ)));
  EXPECT_TRUE(buffer_.canTransform("c", "x", kLatestTime));
  EXPECT_TRUE(
      identical(buffer_.lookupTransform("x", "c", kLatestTime).transform, pose({-1, 0, 0}, 0, kZ)));
}

TEST_F(LatestTimeAcrossAParentChange, TimeTravelWithALatestLegIsMadeInTheTreeOfThatTime) {
  // c in itself at the latest time is the identity at c's newest stamp.
  const TransformStamped travelled = buffer_.lookupTransform("c", kLatestTime, "x", at(2), "c");
  EXPECT_EQ(travelled.stamp, at(2));
  EXPECT_TRUE(identical(travelled.transform, pose({1, 0, 0}, 0, kZ)));
  const TransformStamped latest_source = buffer_.lookupTransform("c", at(2), "x", kLatestTime, "c");
  EXPECT_TRUE(identical(latest_source.transform, pose({1, 0, 0}, 0, kZ)));
  EXPECT_TRUE(buffer_.canTransform("c", at(2), "x", kLatestTime, "c"));
}

TEST(BufferCoreLookup, RotationAFewUlpsOffUnitLengthIsStoredAndLookedUpAsGiven) {
  // Its squared norm is 1 - 1.6e-12: close enough to unit to keep, as sent.
  const Transform sent(Eigen::Vector3d(0.6, 2.5, -3.25),
                       Eigen::Quaterniond(0.79999999999900528, 0, 0, -0.6));
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({1, 0, 0}, 0.2, kZ));
  put(buffer, "base", "camera", at(1), sent);
  EXPECT_TRUE(identical(buffer.lookupTransform("base", "camera", kLatestTime).transform, sent));
  EXPECT_TRUE(near(buffer.lookupTransform("camera", "world", at(1)).transform,
                   (isometry({1, 0, 0}, 0.2, kZ) * sent.toIsometry()).inverse(), 1e-9));
}

TEST(BufferCoreLookup, LatestCommonTimeOfAFrameWithItselfIsItsNewestStamp) {
  BufferCore buffer;
  put(buffer, "world", "base", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "world", "base", at(4), pose({0, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.getLatestCommonTime("base", "base"), at(4));
  EXPECT_EQ(buffer.getLatestCommonTime("world", "world"), TimePoint{});
  EXPECT_EQ(buffer.lookupTransform("base", "base", kLatestTime).stamp, at(4));
}

// The base drives a helix in odom: radius 2 m, 0.3 rad/s, climbing 0.1 m/s, heading along the
// tangent; samples at 10 Hz for 10 s. A camera sits on the base.
class HelixTimeTravel : public ::testing::Test {
 protected:
  static constexpr double kRadius = 2.0;
  static constexpr double kRate = 0.3;
  static constexpr double kClimb = 0.1;

  static Eigen::Vector3d position(double t) {
    return {kRadius * std::cos(kRate * t), kRadius * std::sin(kRate * t), kClimb * t};
  }
  static double heading(double t) { return kRate * t + kPi / 2; }
  static Eigen::Isometry3d odom_T_base(double t) { return isometry(position(t), heading(t), kZ); }

  void SetUp() override {
    for (int i = 0; i <= 100; ++i) {
      const double t = 0.1 * i;
      put(buffer_, "odom", "base", at(t), pose(position(t), heading(t), kZ));
    }
    putStatic(buffer_, "base", "camera", pose({0.2, 0, 1.1}, 0.7, {1, -1, 2}));
    // The object is seen once, at t1.
    put(buffer_, "camera", "object", at(kT1), pose({1, 0.3, 2.5}, 0.4, kY));
  }
  static constexpr double kT1 = 2.0;
  const Eigen::Isometry3d base_T_camera = isometry({0.2, 0, 1.1}, 0.7, {1, -1, 2});
  const Eigen::Isometry3d camera_T_object = isometry({1, 0.3, 2.5}, 0.4, kY);
  BufferCore buffer_;
};

TEST_F(HelixTimeTravel, ObjectSeenEarlierIsExpressedInTheBaseLaterThroughTheFixedFrame) {
  for (const double t2 : {2.0, 2.1, 5.0, 7.3, 10.0}) {
    const Eigen::Isometry3d expected =
        odom_T_base(t2).inverse() * odom_T_base(kT1) * base_T_camera * camera_T_object;
    const TransformStamped result =
        buffer_.lookupTransform("base", at(t2), "object", at(kT1), "odom");
    EXPECT_TRUE(near(result.transform, expected, kTolerance)) << "t2 " << t2;
    EXPECT_EQ(result.parent_frame, "base");
    EXPECT_EQ(result.child_frame, "object");
    EXPECT_EQ(result.stamp, at(t2));
  }
}

TEST_F(HelixTimeTravel, TimeTravelBetweenSamplesUsesTheInterpolatedBasePose) {
  // Halfway between two samples: the chord midpoint, heading at the mean angle.
  const double t2 = 7.35;
  Eigen::Isometry3d odom_T_base_t2 =
      isometry((position(7.3) + position(7.4)) / 2, heading(7.35), kZ);
  const Eigen::Isometry3d expected =
      odom_T_base_t2.inverse() * odom_T_base(kT1) * base_T_camera * camera_T_object;
  EXPECT_TRUE(near(buffer_.lookupTransform("base", at(t2), "object", at(kT1), "odom").transform,
                   expected, kTolerance));
}

TEST_F(HelixTimeTravel, TimeTravelWithEqualTimesMatchesThePlainLookup) {
  EXPECT_TRUE(near(buffer_.lookupTransform("base", at(kT1), "object", at(kT1), "odom").transform,
                   buffer_.lookupTransform("base", "object", at(kT1)).transform, kTolerance));
}

// Both frames hang below odom -> base, and map -> odom is static, far off and turned: each
// half of the lookup crosses that chain, one way and back.
TEST_F(HelixTimeTravel, TimeTravelThroughAFixedFrameAboveAStaticChainCrossesItBothWays) {
  const Eigen::Isometry3d map_T_odom = isometry({120, -45, 3}, 2.1, {1, 2, 3});
  putStatic(buffer_, "map", "odom", pose({120, -45, 3}, 2.1, {1, 2, 3}));
  for (const double t2 : {2.0, 5.0, 7.3, 10.0}) {
    const Eigen::Isometry3d map_T_camera_t2 = map_T_odom * odom_T_base(t2) * base_T_camera;
    const Eigen::Isometry3d map_T_object =
        map_T_odom * odom_T_base(kT1) * base_T_camera * camera_T_object;
    const TransformStamped result =
        buffer_.lookupTransform("camera", at(t2), "object", at(kT1), "map");
    EXPECT_TRUE(near(result.transform, map_T_camera_t2.inverse() * map_T_object, kTolerance))
        << "t2 " << t2;
    const TransformStamped back =
        buffer_.lookupTransform("object", at(kT1), "camera", at(t2), "map");
    EXPECT_TRUE(near(back.transform, map_T_object.inverse() * map_T_camera_t2, kTolerance))
        << "t2 " << t2;
  }
}

TEST_F(HelixTimeTravel, TimeTravelIntoAFrameWhoseDataIsOutOfRangeThrowsExtrapolation) {
  EXPECT_THROW(buffer_.lookupTransform("base", at(10.5), "object", at(kT1), "odom"),
               FutureExtrapolationException);
  EXPECT_THROW(buffer_.lookupTransform("base", at(5), "object", at(3), "odom"),
               FutureExtrapolationException);
  std::string why;
  EXPECT_FALSE(buffer_.canTransform("base", at(10.5), "object", at(kT1), "odom", &why));
  EXPECT_NE(why.find("future"), std::string::npos) << why;
  EXPECT_TRUE(buffer_.canTransform("base", at(9.99), "object", at(kT1), "odom"));
}

TEST(BufferCoreLookup, FrameHandleLookupsEqualStringLookups) {
  BufferCore buffer;
  const YTree tree(buffer, at(1), at(1));
  put(buffer, "world", "base", at(2), pose({6, 5, 0}, 1.2, kZ));
  put(buffer, "base", "left_arm", at(2), pose({0, 0.4, 1}, 0.3, kX));
  const std::vector<std::string> names{"world", "base", "left_arm", "left_hand", "right_hand"};
  TransformStamped reused;  // every field overwritten by each lookup into it
  for (const std::string& target : names) {
    for (const std::string& source : names) {
      const FrameHandle target_handle = buffer.findFrame(target);
      const FrameHandle source_handle = buffer.resolveFrame(source);
      ASSERT_TRUE(target_handle);
      ASSERT_TRUE(source_handle);
      EXPECT_EQ(buffer.resolveFrame(target), target_handle);
      EXPECT_EQ(buffer.findFrame("/" + source), source_handle);
      for (const TimePoint t : {at(1), kLatestTime}) {
        const TransformStamped by_name = buffer.lookupTransform(target, source, t);
        const TransformStamped by_handle = buffer.lookupTransform(target_handle, source_handle, t);
        EXPECT_TRUE(identical(by_handle.transform, by_name.transform))
            << source << " in " << target;
        EXPECT_EQ(by_handle.stamp, by_name.stamp);
        EXPECT_EQ(by_handle.parent_frame, target);
        EXPECT_EQ(by_handle.child_frame, source);
        buffer.lookupTransform(target_handle, source_handle, t, reused);
        EXPECT_TRUE(identical(reused.transform, by_name.transform)) << source << " in " << target;
        EXPECT_EQ(reused.stamp, by_name.stamp);
        EXPECT_EQ(reused.parent_frame, target);
        EXPECT_EQ(reused.child_frame, source);
        EXPECT_TRUE(buffer.canTransform(target_handle, source_handle, t));
      }
      std::string why_by_name;
      std::string why_by_handle;
      const bool can_by_name = buffer.canTransform(target, source, at(1.5), &why_by_name);
      EXPECT_EQ(buffer.canTransform(target_handle, source_handle, at(1.5), &why_by_handle),
                can_by_name);
      EXPECT_EQ(why_by_handle, why_by_name);
    }
  }
}

TEST(BufferCoreLookup, AResultReusedAcrossLookupsTakesEachLookupsNames) {
  BufferCore buffer;
  const std::string long_parent = "a_parent_frame_with_a_name_longer_than_most";
  const std::string long_child = "a_child_frame_with_a_name_longer_than_most";
  put(buffer, "w", long_parent, at(1), pose({1, 0, 0}, 0.1, kZ));
  put(buffer, long_parent, long_child, at(1), pose({0, 2, 0}, 0.2, kX));
  put(buffer, "w", "ab", at(1), pose({0, 0, 3}, 0.3, kY));
  const FrameHandle w = buffer.findFrame("w");
  const FrameHandle parent = buffer.findFrame(long_parent);
  const FrameHandle child = buffer.findFrame(long_child);
  const FrameHandle ab = buffer.findFrame("ab");
  TransformStamped reused;
  const std::vector<std::pair<FrameHandle, FrameHandle>> pairs{
      {parent, child}, {parent, child}, {w, ab},      {parent, child}, {ab, child},
      {w, ab},         {child, child},  {ab, parent}, {child, w},      {w, ab}};
  for (const auto& [target, source] : pairs) {
    buffer.lookupTransform(target, source, at(1), reused);
    const TransformStamped returned = buffer.lookupTransform(target, source, at(1));
    EXPECT_EQ(reused.parent_frame, returned.parent_frame);
    EXPECT_EQ(reused.child_frame, returned.child_frame);
    EXPECT_EQ(reused.stamp, returned.stamp);
    EXPECT_TRUE(identical(reused.transform, returned.transform)) << returned.child_frame;
  }
  EXPECT_EQ(reused.parent_frame, "w");
  EXPECT_EQ(reused.child_frame, "ab");
}

TEST(BufferCoreLookup, FindFrameIsNullForUnknownFramesAndResolveFrameCreatesThem) {
  BufferCore buffer;
  EXPECT_FALSE(buffer.findFrame("ghost"));
  EXPECT_FALSE(buffer.frameExists("ghost"));
  const FrameHandle ghost = buffer.resolveFrame("/ghost");
  EXPECT_TRUE(ghost);
  EXPECT_TRUE(buffer.frameExists("ghost"));
  EXPECT_EQ(buffer.findFrame("ghost"), ghost);
  put(buffer, "world", "ghost", at(1), pose({1, 0, 0}, 0, kZ));
  EXPECT_EQ(buffer.findFrame("ghost"), ghost);
  const FrameHandle world = buffer.findFrame("world");
  EXPECT_NE(world, ghost);
  EXPECT_TRUE(near(buffer.lookupTransform(world, ghost, at(1)).transform,
                   isometry({1, 0, 0}, 0, kZ), kTolerance));
}

TEST(BufferCoreLookup, FrameHandlesStayValidAcrossClear) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({1, 2, 3}, 0.5, kZ));
  const FrameHandle world = buffer.findFrame("world");
  const FrameHandle base = buffer.findFrame("base");
  buffer.clear();
  EXPECT_EQ(buffer.findFrame("world"), world);
  EXPECT_TRUE(near(buffer.lookupTransform(world, base, at(7)).transform,
                   isometry({1, 2, 3}, 0.5, kZ), kTolerance));
}

TEST(BufferCoreLookup, OneLeadingSlashIsStrippedFromEveryQuery) {
  BufferCore buffer;
  put(buffer, "/world", "/base", at(1), pose({1, 0, 0}, 0.2, kZ));
  put(buffer, "world", "base", at(2), pose({2, 0, 0}, 0.2, kZ));
  put(buffer, "base", "/arm", at(2), pose({0, 1, 0}, 0, kZ));
  EXPECT_TRUE(buffer.frameExists("world"));
  EXPECT_TRUE(buffer.frameExists("/world"));
  const TransformStamped result = buffer.lookupTransform("/world", "/base", at(1.5));
  EXPECT_EQ(result.parent_frame, "world");
  EXPECT_EQ(result.child_frame, "base");
  EXPECT_TRUE(
      identical(result.transform, buffer.lookupTransform("world", "base", at(1.5)).transform));
  EXPECT_TRUE(near(result.transform, isometry({1.5, 0, 0}, 0.2, kZ), kTolerance));
  EXPECT_TRUE(buffer.canTransform("/world", "arm", at(2)));
  EXPECT_EQ(buffer.getLatestCommonTime("/arm", "/world"), at(2));
  EXPECT_EQ(buffer.getFrameChain("/world", "/arm", at(2)),
            (std::vector<std::string>{"arm", "base", "world"}));
  std::string parent;
  ASSERT_TRUE(buffer.getParent("/arm", at(2), parent));
  EXPECT_EQ(parent, "base");
  const TransformStamped travelled =
      buffer.lookupTransform("/arm", at(2), "/base", at(1), "/world");
  EXPECT_EQ(travelled.parent_frame, "arm");
  EXPECT_EQ(travelled.child_frame, "base");
  EXPECT_TRUE(identical(travelled.transform,
                        buffer.lookupTransform("arm", at(2), "base", at(1), "world").transform));
}

// A sender without a clock stamps its samples 0, which is also the time that asks for the
// latest. As in tf2, such an edge sets no bound on the latest common time, and at time 0 it
// gives its newest sample.
TEST(BufferCoreLookup, AnEdgeWhoseNewestSampleIsStampedZeroSetsNoBoundOnTheLatestTime) {
  BufferCore buffer;
  put(buffer, "world", "base", fromUtime(0), pose({1, 0, 0}, 0, kZ));
  put(buffer, "base", "camera", at(5), pose({0, 2, 0}, 0, kZ));
  put(buffer, "base", "camera", at(6), pose({0, 3, 0}, 0, kZ));
  EXPECT_EQ(buffer.getLatestCommonTime("world", "camera"), at(6));
  EXPECT_THROW(buffer.lookupTransform("world", "camera", kLatestTime), ExtrapolationException);
  EXPECT_FALSE(buffer.canTransform("world", "camera", kLatestTime));
  EXPECT_EQ(buffer.getLatestCommonTime("world", "base"), fromUtime(0));
  EXPECT_TRUE(near(buffer.lookupTransform("world", "base", kLatestTime).transform,
                   isometry({1, 0, 0}, 0, kZ), kTolerance));
  put(buffer, "base", "arm", fromUtime(-1), pose({0, 0, 1}, 0, kZ));
  put(buffer, "base", "arm", fromUtime(0), pose({0, 0, 2}, 0, kZ));
  const TransformStamped world_T_arm = buffer.lookupTransform("world", "arm", kLatestTime);
  EXPECT_EQ(world_T_arm.stamp, fromUtime(0));
  EXPECT_TRUE(near(world_T_arm.transform, isometry({1, 0, 2}, 0, kZ), kTolerance));
}

}  // namespace
}  // namespace lcmtf
