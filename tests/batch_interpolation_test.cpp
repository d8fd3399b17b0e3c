#include "batch_interpolation.hpp"

#include "slerp_weights.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace lcmtf::detail {
namespace {

// Pairs of rotations from identical to half a turn apart (both series and the libm path),
// including pairs on opposite sides of the sphere, at ratios that include both ends.
struct Batch {
  std::vector<Transform> older;
  std::vector<Transform> newer;
  std::vector<double> ratios;
};

Batch makeBatch(std::size_t count) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double arcs[] = {0.0, 1e-12, 1e-6, 0.01, 0.06, 0.2, 0.5, 1.0, 2.0, 3.1};
  Batch batch;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Quaterniond start = Eigen::Quaterniond::UnitRandom();
    const Eigen::Vector3d axis = Eigen::Vector3d::Random().normalized();
    Eigen::Quaterniond end = start * Eigen::Quaterniond(Eigen::AngleAxisd(arcs[i % 10], axis));
    if (i % 3 == 0) end.coeffs() = -end.coeffs();
    batch.older.emplace_back(Eigen::Vector3d::Random(), start);
    batch.newer.emplace_back(Eigen::Vector3d::Random(), end);
    batch.ratios.push_back(i % 11 == 0 ? 0.0 : i % 13 == 0 ? 1.0 : unit(random));
  }
  return batch;
}

// With `arcs_known`, each task carries the arc as a time cache works it out on insert; else
// the batch works out every arc itself.
void expectBatchMatchesOneByOne(std::size_t count, bool arcs_known = false) {
  const Batch batch = makeBatch(count);
  std::vector<Transform> out(count);
  std::vector<InterpolationTask> tasks;
  for (std::size_t i = 0; i < count; ++i) {
    const double arc = arcs_known
                           ? signedArcSquared(batch.older[i].rotation, batch.newer[i].rotation)
                           : std::numeric_limits<double>::quiet_NaN();
    tasks.push_back({&batch.older[i], &batch.newer[i], batch.ratios[i], &out[i], arc, nullptr});
  }
  interpolateBatch(tasks.data(), tasks.size());
  for (std::size_t i = 0; i < count; ++i) {
    const Transform expected = interpolate(batch.older[i], batch.newer[i], batch.ratios[i]);
    EXPECT_LE((out[i].translation - expected.translation).norm(), 1e-15) << "task " << i;
    EXPECT_LE((out[i].rotation.coeffs() - expected.rotation.coeffs()).norm(), 1e-15)
        << "task " << i << " at ratio " << batch.ratios[i];
  }
}

TEST(InterpolateBatch, MatchesInterpolateOneByOne) { expectBatchMatchesOneByOne(10); }

TEST(InterpolateBatch, BatchesLargerThanOneRoundOfLanesMatchToo) {
  expectBatchMatchesOneByOne(101);
}

TEST(InterpolateBatch, EveryBatchSizeUpToTwoRoundsOfLanesMatches) {
  for (std::size_t count = 1; count <= 9; ++count) {
    expectBatchMatchesOneByOne(count);
    expectBatchMatchesOneByOne(count, true);
  }
}

TEST(InterpolateBatch, ArcsWorkedOutBeforehandGiveTheSameResults) {
  expectBatchMatchesOneByOne(101, true);
}

TEST(InterpolateBatch, ArcKnownBeforehandIsNegativeWhenTheNewerRotationMustBeNegated) {
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond b(Eigen::AngleAxisd(0.31, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond negated_b(-b.coeffs());
  // The arc between the quaternions on the sphere is half the angle between the rotations.
  EXPECT_NEAR(signedArcSquared(a, b), 0.005 * 0.005, 1e-15);
  EXPECT_NEAR(signedArcSquared(a, negated_b), -0.005 * 0.005, 1e-15);
  EXPECT_TRUE(std::isnan(
      signedArcSquared(a, Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX())))));
}

TEST(InterpolateBatch, AnAnchoredTaskGivesItsAnchorTimesTheInterpolatedValue) {
  const Batch batch = makeBatch(9);
  const Transform anchor(
      Eigen::Vector3d(0.5, -2.0, 1.25),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())));
  std::vector<Transform> out(9);
  std::vector<InterpolationTask> tasks;
  for (std::size_t i = 0; i < 9; ++i) {
    // Every other task anchored, so that anchored and plain tasks share rounds of lanes.
    tasks.push_back({&batch.older[i], &batch.newer[i], batch.ratios[i], &out[i],
                     std::numeric_limits<double>::quiet_NaN(), i % 2 == 0 ? &anchor : nullptr});
  }
  interpolateBatch(tasks.data(), tasks.size());
  for (std::size_t i = 0; i < 9; ++i) {
    const Transform value = interpolate(batch.older[i], batch.newer[i], batch.ratios[i]);
    const Transform expected = i % 2 == 0 ? anchor * value : value;
    EXPECT_LE((out[i].translation - expected.translation).norm(), 1e-14) << "task " << i;
    EXPECT_LE((out[i].rotation.coeffs() - expected.rotation.coeffs()).norm(), 1e-15)
        << "task " << i;
  }
}

TEST(InterpolateBatch, EmptyBatchDoesNothing) { interpolateBatch(nullptr, 0); }

}  // namespace
}  // namespace lcmtf::detail
