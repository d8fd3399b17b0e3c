#include "batch_interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

void expectBatchMatchesOneByOne(std::size_t count) {
  const Batch batch = makeBatch(count);
  std::vector<Transform> out(count);
  std::vector<InterpolationTask> tasks;
  for (std::size_t i = 0; i < count; ++i) {
    tasks.push_back({&batch.older[i], &batch.newer[i], batch.ratios[i], &out[i]});
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
  }
}

TEST(InterpolateBatch, EmptyBatchDoesNothing) { interpolateBatch(nullptr, 0); }

}  // namespace
}  // namespace lcmtf::detail
