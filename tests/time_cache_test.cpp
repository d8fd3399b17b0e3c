#include "time_cache.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace lcmtf::detail {
namespace {

constexpr FrameId kParent = 1;
constexpr FrameId kOtherParent = 2;
constexpr std::int64_t kKeepAll = std::int64_t{1} << 40;
constexpr std::int64_t kCacheTime = 100;

// A value told apart from every other stamp's, and from other versions at the same stamp.
Transform valueAt(std::int64_t stamp, int version = 0) {
  const double t = static_cast<double>(stamp);
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 3.0).normalized();
  return Transform(Eigen::Vector3d(t, 0.5 * t + version, -t),
                   Eigen::Quaterniond(Eigen::AngleAxisd(1e-3 * t + 0.1 * version, axis)));
}

EdgeSample sampleAt(std::int64_t stamp, FrameId parent = kParent, int version = 0) {
  return EdgeSample{stamp, parent, valueAt(stamp, version)};
}

::testing::AssertionResult holds(const Transform* actual, const Transform& expected) {
  if (actual == nullptr) return ::testing::AssertionFailure() << "no transform";
  if (actual->translation == expected.translation &&
      actual->rotation.coeffs() == expected.rotation.coeffs()) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "holds translation " << actual->translation.transpose()
                                       << ", expected " << expected.translation.transpose();
}

::testing::AssertionResult sameSpan(const SampleSpan& actual, const SampleSpan& expected) {
  if (actual.older == expected.older && actual.newer == expected.newer &&
      actual.ratio == expected.ratio && actual.parent == expected.parent &&
      (actual.newer == nullptr || actual.arc_squared == expected.arc_squared ||
       (std::isnan(actual.arc_squared) && std::isnan(expected.arc_squared)))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "older " << actual.older << " newer " << actual.newer << " ratio " << actual.ratio
         << " parent " << actual.parent << ", expected older " << expected.older << " newer "
         << expected.newer << " ratio " << expected.ratio << " parent " << expected.parent;
}

void expectExactly(const TimeCache& cache, std::int64_t stamp, const Transform& value,
                   FrameId parent = kParent) {
  SampleSpan span;
  ASSERT_EQ(cache.find(stamp, span), SampleStatus::kOk) << "at " << stamp;
  EXPECT_TRUE(holds(span.older, value)) << "at " << stamp;
  EXPECT_EQ(span.newer, nullptr) << "at " << stamp;
  EXPECT_EQ(span.parent, parent) << "at " << stamp;
}

void expectBetween(const TimeCache& cache, std::int64_t stamp, std::int64_t older,
                   std::int64_t newer, FrameId parent = kParent) {
  SampleSpan span;
  ASSERT_EQ(cache.find(stamp, span), SampleStatus::kOk) << "at " << stamp;
  EXPECT_TRUE(holds(span.older, valueAt(older))) << "at " << stamp;
  EXPECT_TRUE(holds(span.newer, valueAt(newer))) << "at " << stamp;
  EXPECT_DOUBLE_EQ(span.ratio,
                   static_cast<double>(stamp - older) / static_cast<double>(newer - older))
      << "at " << stamp;
  EXPECT_EQ(span.parent, parent) << "at " << stamp;
}

FrameId parentAt(const TimeCache& cache, std::int64_t stamp, SampleStatus expected_status) {
  SampleStatus status = SampleStatus::kEmpty;
  const FrameId parent = cache.parentAt(stamp, status);
  EXPECT_EQ(status, expected_status) << "at " << stamp;
  return parent;
}

// The gap after a sample: runs of close samples alternating with runs of far apart ones, as
// no even spacing describes.
std::int64_t unevenGap(std::size_t index, std::mt19937_64& random) {
  const bool close = (index / 25) % 2 == 0;
  std::uniform_int_distribution<std::int64_t> gap(close ? 1 : 40, close ? 4 : 400);
  return gap(random);
}

std::vector<std::int64_t> unevenStamps(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<std::int64_t> stamps{1'000'000};
  while (stamps.size() < count) stamps.push_back(stamps.back() + unevenGap(stamps.size(), random));
  return stamps;
}

// Asks spanWithin() at every stamp from the oldest of `stamps` (those the cache keeps, in order)
// to the newest, from a correct hint, wrong ones, none, and the cache's own, and expects what
// find() gives. Returns at how many stamps prefetch() guessed a wrong place.
std::size_t expectSpanWithinAgreesWithFind(const TimeCache& cache,
                                           const std::vector<std::int64_t>& stamps) {
  EXPECT_TRUE(cache.hasSingleParent());
  EXPECT_EQ(cache.size(), stamps.size());
  if (stamps.size() < 2) return 0;
  const std::size_t last_hint = stamps.size() - 2;
  std::size_t at = 0;  // the newest sample at or before the stamp
  std::size_t wrong_guesses = 0;
  for (std::int64_t stamp = stamps.front(); stamp <= stamps.back(); ++stamp) {
    while (at + 1 < stamps.size() && stamps[at + 1] <= stamp) ++at;
    SampleSpan expected;
    if (cache.find(stamp, expected) != SampleStatus::kOk) {
      ADD_FAILURE() << "no value at " << stamp;
      return wrong_guesses;
    }
    const std::size_t correct = std::min(at, last_hint);
    const std::size_t guess = cache.prefetch(stamp);
    if (guess != correct) ++wrong_guesses;
    const std::size_t hints[] = {correct,
                                 (correct + stamps.size() / 2) % (last_hint + 1),
                                 0,
                                 last_hint,
                                 TimeCache::kNoHint,
                                 guess,
                                 cache.hintNearNewest()};
    for (const std::size_t hint : hints) {
      EXPECT_TRUE(sameSpan(cache.spanWithin(stamp, hint), expected))
          << "at " << stamp << " from hint " << hint;
    }
  }
  return wrong_guesses;
}

TEST(TimeCache, SamplesInsertedInAnyOrderAreFoundInTimeOrder) {
  const std::vector<std::int64_t> stamps = unevenStamps(300, 3);
  std::vector<std::int64_t> shuffled = stamps;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(5));
  TimeCache cache;
  for (const std::int64_t stamp : shuffled) {
    ASSERT_EQ(cache.insert(sampleAt(stamp), kKeepAll), InsertOutcome::kAdded);
  }
  ASSERT_EQ(cache.size(), stamps.size());
  EXPECT_EQ(cache.oldestStamp(), stamps.front());
  EXPECT_EQ(cache.newestStamp(), stamps.back());
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    expectExactly(cache, stamps[i], valueAt(stamps[i]));
    if (i + 1 == stamps.size() || stamps[i + 1] - stamps[i] < 2) continue;
    expectBetween(cache, stamps[i] + 1, stamps[i], stamps[i + 1]);
    expectBetween(cache, stamps[i + 1] - 1, stamps[i], stamps[i + 1]);
  }
}

TEST(TimeCache, RepeatedStampReplacesTheSampleThere) {
  for (const std::int64_t repeated : {100, 200, 300}) {
    SCOPED_TRACE(repeated);
    TimeCache cache;
    for (const std::int64_t stamp : {100, 200, 300}) cache.insert(sampleAt(stamp), kKeepAll);
    EXPECT_EQ(cache.insert(sampleAt(repeated, kParent, 1), kKeepAll), InsertOutcome::kReplaced);
    EXPECT_EQ(cache.size(), 3u);
    for (const std::int64_t stamp : {100, 200, 300}) {
      expectExactly(cache, stamp, valueAt(stamp, stamp == repeated ? 1 : 0));
    }
  }
}

TEST(TimeCache, SampleAtTheWindowEdgeIsKeptAndOneOlderIsPruned) {
  TimeCache cache;
  for (const std::int64_t stamp : {899, 900, 950}) cache.insert(sampleAt(stamp), kCacheTime);
  ASSERT_EQ(cache.size(), 3u);
  ASSERT_EQ(cache.insert(sampleAt(1000), kCacheTime), InsertOutcome::kAdded);
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(cache.oldestStamp(), 900);
  SampleSpan span;
  EXPECT_EQ(cache.find(899, span), SampleStatus::kPast);
  expectExactly(cache, 900, valueAt(900));
}

TEST(TimeCache, SampleAtTheWindowEdgeIsInsertedAndOneOlderIsRefused) {
  TimeCache cache;
  cache.insert(sampleAt(950), kCacheTime);
  cache.insert(sampleAt(1000), kCacheTime);
  EXPECT_TRUE(cache.isTooOld(899, kCacheTime));
  EXPECT_FALSE(cache.isTooOld(900, kCacheTime));
  EXPECT_EQ(cache.insert(sampleAt(899), kCacheTime), InsertOutcome::kTooOld);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.oldestStamp(), 950);
  EXPECT_EQ(cache.insert(sampleAt(900), kCacheTime), InsertOutcome::kAdded);
  EXPECT_EQ(cache.oldestStamp(), 900);
  EXPECT_EQ(cache.insert(sampleAt(900, kParent, 1), kCacheTime), InsertOutcome::kReplaced);
  expectExactly(cache, 900, valueAt(900, 1));
}

TEST(TimeCache, EmptyEdgeHasNoValueAndNoParent) {
  TimeCache cache;
  SampleSpan span;
  EXPECT_EQ(cache.find(0, span), SampleStatus::kEmpty);
  EXPECT_EQ(parentAt(cache, 0, SampleStatus::kEmpty), kNoFrame);
  EXPECT_FALSE(cache.changesParent());
  EXPECT_FALSE(cache.isTooOld(std::numeric_limits<std::int64_t>::min(), kCacheTime));
}

TEST(TimeCache, StampsOutsideTheHistoryArePastOrFutureWithTheNearestParent) {
  TimeCache cache;
  cache.insert(sampleAt(100, kParent), kKeepAll);
  cache.insert(sampleAt(200, kOtherParent), kKeepAll);
  SampleSpan span;
  EXPECT_EQ(cache.find(99, span), SampleStatus::kPast);
  EXPECT_EQ(cache.find(201, span), SampleStatus::kFuture);
  EXPECT_EQ(parentAt(cache, 99, SampleStatus::kPast), kParent);
  EXPECT_EQ(parentAt(cache, 201, SampleStatus::kFuture), kOtherParent);
  expectExactly(cache, 100, valueAt(100), kParent);
  expectExactly(cache, 200, valueAt(200), kOtherParent);
  cache.clearHistory();
  EXPECT_EQ(cache.find(150, span), SampleStatus::kEmpty);
}

TEST(TimeCache, ParentChangeKeepsTheOlderSampleAloneUntilTheChange) {
  TimeCache cache;
  cache.insert(sampleAt(100, kParent), kKeepAll);
  cache.insert(sampleAt(200, kParent), kKeepAll);
  cache.insert(sampleAt(300, kOtherParent), kKeepAll);
  cache.insert(sampleAt(400, kOtherParent), kKeepAll);
  expectBetween(cache, 150, 100, 200, kParent);
  expectExactly(cache, 250, valueAt(200), kParent);
  expectExactly(cache, 299, valueAt(200), kParent);
  expectExactly(cache, 300, valueAt(300), kOtherParent);
  expectBetween(cache, 350, 300, 400, kOtherParent);
  EXPECT_EQ(parentAt(cache, 250, SampleStatus::kOk), kParent);
  EXPECT_EQ(parentAt(cache, 299, SampleStatus::kOk), kParent);
  EXPECT_EQ(parentAt(cache, 300, SampleStatus::kOk), kOtherParent);
  EXPECT_EQ(parentAt(cache, 350, SampleStatus::kOk), kOtherParent);
  EXPECT_FALSE(cache.hasSingleParent());
  EXPECT_TRUE(cache.changesParent());
  EXPECT_EQ(cache.singleParentFrom(), std::numeric_limits<std::int64_t>::max());
}

TEST(TimeCache, PruningTheOldParentsLastSampleLeavesOneParent) {
  TimeCache cache;
  cache.insert(sampleAt(100, kParent), kCacheTime);
  cache.insert(sampleAt(150, kOtherParent), kCacheTime);
  cache.insert(sampleAt(200, kOtherParent), kCacheTime);
  ASSERT_EQ(cache.oldestStamp(), 100);
  ASSERT_FALSE(cache.hasSingleParent());
  cache.insert(sampleAt(201, kOtherParent), kCacheTime);
  EXPECT_EQ(cache.oldestStamp(), 150);
  EXPECT_TRUE(cache.hasSingleParent());
  EXPECT_FALSE(cache.changesParent());
  EXPECT_EQ(cache.singleParentFrom(), cache.oldestStamp());
  expectBetween(cache, 175, 150, 200, kOtherParent);
}

TEST(TimeCache, LateSampleWithAnotherParentAmongOthersMakesTheEdgeChangeParent) {
  TimeCache cache;
  for (const std::int64_t stamp : {100, 200, 300}) cache.insert(sampleAt(stamp), kKeepAll);
  ASSERT_TRUE(cache.hasSingleParent());
  ASSERT_EQ(cache.singleParentFrom(), 100);
  EXPECT_EQ(cache.insert(sampleAt(150, kOtherParent), kKeepAll), InsertOutcome::kAdded);
  EXPECT_FALSE(cache.hasSingleParent());
  EXPECT_TRUE(cache.changesParent());
  EXPECT_EQ(cache.singleParentFrom(), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(parentAt(cache, 125, SampleStatus::kOk), kParent);
  EXPECT_EQ(parentAt(cache, 150, SampleStatus::kOk), kOtherParent);
  EXPECT_EQ(parentAt(cache, 175, SampleStatus::kOk), kOtherParent);
  EXPECT_EQ(parentAt(cache, 200, SampleStatus::kOk), kParent);
  expectExactly(cache, 125, valueAt(100), kParent);
  expectExactly(cache, 175, valueAt(150), kOtherParent);
}

TEST(TimeCache, LateSampleWithAnotherParentBeforeTheOldestMakesTheEdgeChangeParent) {
  TimeCache cache;
  for (const std::int64_t stamp : {100, 200}) cache.insert(sampleAt(stamp), kKeepAll);
  cache.insert(sampleAt(50, kOtherParent), kKeepAll);
  EXPECT_FALSE(cache.hasSingleParent());
  EXPECT_EQ(cache.singleParentFrom(), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(parentAt(cache, 75, SampleStatus::kOk), kOtherParent);
  EXPECT_EQ(parentAt(cache, 100, SampleStatus::kOk), kParent);
}

TEST(TimeCache, LateSampleWithTheSameParentKeepsOneParentFromTheOldest) {
  TimeCache cache;
  for (const std::int64_t stamp : {100, 200}) cache.insert(sampleAt(stamp), kKeepAll);
  cache.insert(sampleAt(50), kKeepAll);
  cache.insert(sampleAt(150), kKeepAll);
  EXPECT_TRUE(cache.hasSingleParent());
  EXPECT_EQ(cache.singleParentFrom(), 50);
}

TEST(TimeCache, SetStaticDropsTheHistory) {
  TimeCache cache;
  cache.insert(sampleAt(100, kParent), kKeepAll);
  cache.insert(sampleAt(200, kOtherParent), kKeepAll);
  cache.setStatic(kOtherParent, valueAt(7));
  EXPECT_TRUE(cache.isStatic());
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_FALSE(cache.changesParent());
  EXPECT_EQ(cache.staticParent(), kOtherParent);
  for (const std::int64_t stamp :
       {std::numeric_limits<std::int64_t>::min(), std::int64_t{0}, std::int64_t{100},
        std::int64_t{150}, std::numeric_limits<std::int64_t>::max()}) {
    expectExactly(cache, stamp, valueAt(7), kOtherParent);
    EXPECT_EQ(parentAt(cache, stamp, SampleStatus::kOk), kOtherParent);
    EXPECT_FALSE(cache.isTooOld(stamp, kCacheTime));
  }
}

TEST(TimeCache, ClearHistoryKeepsAStaticValue) {
  TimeCache cache;
  cache.setStatic(kParent, valueAt(7));
  cache.clearHistory();
  EXPECT_TRUE(cache.isStatic());
  expectExactly(cache, 12345, valueAt(7), kParent);
}

TEST(TimeCache, ClearHistoryForgetsHowOldTheHistoryWas) {
  TimeCache cache;
  cache.insert(sampleAt(100), kCacheTime);
  cache.insert(sampleAt(1000), kCacheTime);
  cache.clearHistory();
  EXPECT_TRUE(cache.empty());
  EXPECT_EQ(cache.newestParent(), kNoFrame);
  EXPECT_EQ(cache.insert(sampleAt(10), kCacheTime), InsertOutcome::kAdded);
  expectExactly(cache, 10, valueAt(10));
}

TEST(TimeCache, SampleAfterAStaticValueMakesTheEdgeDynamic) {
  TimeCache cache;
  cache.setStatic(kParent, valueAt(7));
  EXPECT_EQ(cache.insert(sampleAt(500, kOtherParent), kCacheTime), InsertOutcome::kAdded);
  EXPECT_FALSE(cache.isStatic());
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.newestParent(), kOtherParent);
  expectExactly(cache, 500, valueAt(500), kOtherParent);
  SampleSpan span;
  EXPECT_EQ(cache.find(499, span), SampleStatus::kPast);
}

// Asks for the two newest samples and the ratio between them at every stamp from a few before
// the older to a few after the newer, and expects what find() gives there: the same samples
// and ratio, 0 at the older's stamp and 1 at the newer's, and no ratio outside them.
void expectNewestPairAgreesWithFind(const TimeCache& cache) {
  const Transform* older = nullptr;
  const Transform* newer = nullptr;
  double arc = 0.0;
  if (cache.size() < 2) {
    EXPECT_FALSE(cache.newestPair(older, newer, arc));
    return;
  }
  ASSERT_TRUE(cache.newestPair(older, newer, arc));
  SampleSpan at_newest;
  ASSERT_EQ(cache.find(cache.newestStamp(), at_newest), SampleStatus::kOk);
  EXPECT_EQ(newer, at_newest.older);
  const std::int64_t newest = cache.newestStamp();
  // The older sample's stamp: the newest before the newer's where find() gives it alone.
  std::int64_t older_stamp = newest - 1;
  SampleSpan span;
  for (; cache.find(older_stamp, span) == SampleStatus::kOk; --older_stamp) {
    if (span.older == older && span.newer == nullptr) break;
  }
  ASSERT_TRUE(span.older == older && span.newer == nullptr) << "no older sample found";
  for (std::int64_t stamp = older_stamp - 3; stamp <= newest + 3; ++stamp) {
    double ratio = -1.0;
    const bool between = older_stamp <= stamp && stamp <= newest;
    ASSERT_EQ(cache.ratioInNewestPair(stamp, ratio), between) << "at " << stamp;
    if (!between) continue;
    ASSERT_EQ(cache.find(stamp, span), SampleStatus::kOk) << "at " << stamp;
    if (stamp == older_stamp) {
      EXPECT_EQ(ratio, 0.0) << "at " << stamp;
      EXPECT_EQ(span.older, older) << "at " << stamp;
    } else if (stamp == newest) {
      EXPECT_EQ(ratio, 1.0) << "at " << stamp;
    } else {
      EXPECT_TRUE(sameSpan(SampleSpan{older, newer, ratio, span.parent, arc}, span))
          << "at " << stamp;
    }
  }
}

// Expects each of `stamps` (those the cache keeps, in order) but the newest to carry the arc to
// the sample after it, as interpolating between them reads it. `version` gives each stamp's value.
void expectArcsToTheNextSample(const TimeCache& cache, const std::vector<std::int64_t>& stamps,
                               const std::map<std::int64_t, int>& version = {}) {
  const auto valueOf = [&version](std::int64_t stamp) {
    const auto found = version.find(stamp);
    return valueAt(stamp, found == version.end() ? 0 : found->second);
  };
  for (std::size_t i = 0; i + 1 < stamps.size(); ++i) {
    if (stamps[i + 1] - stamps[i] < 2) continue;
    SampleSpan span;
    ASSERT_EQ(cache.find(stamps[i] + 1, span), SampleStatus::kOk) << "after " << stamps[i];
    ASSERT_TRUE(holds(span.older, valueOf(stamps[i]))) << "at " << stamps[i];
    ASSERT_TRUE(holds(span.newer, valueOf(stamps[i + 1]))) << "at " << stamps[i + 1];
    const double expected = signedArcSquared(span.older->rotation, span.newer->rotation);
    EXPECT_TRUE(span.arc_squared == expected ||
                (std::isnan(span.arc_squared) && std::isnan(expected)))
        << "the sample at " << stamps[i] << " keeps the arc " << span.arc_squared
        << " to the next, which is " << expected;
  }
}

TEST(TimeCache, SpanWithinAgreesWithFindFromAnyHintOverUnevenSamples) {
  const std::vector<std::int64_t> stamps = unevenStamps(200, 9);
  TimeCache cache;
  for (const std::int64_t stamp : stamps) cache.insert(sampleAt(stamp), kKeepAll);
  EXPECT_GT(expectSpanWithinAgreesWithFind(cache, stamps), 0u)
      << "even spacing guessed every sample: the search beyond the guess went untested";
  expectNewestPairAgreesWithFind(cache);
}

TEST(TimeCache, SpanWithinAgreesWithFindAfterTheRingWrapsAround) {
  constexpr std::int64_t kWindow = 3000;
  std::mt19937_64 random(17);
  TimeCache cache;
  std::set<std::int64_t> kept;
  std::int64_t newest = 1'000'000;
  // The newest sample sits in a slot before the oldest's.
  const auto wrapped = [&cache] {
    SampleSpan oldest;
    SampleSpan newest_span;
    return cache.find(cache.oldestStamp(), oldest) == SampleStatus::kOk &&
           cache.find(cache.newestStamp(), newest_span) == SampleStatus::kOk &&
           newest_span.older < oldest.older;
  };
  for (std::size_t i = 0; i < 100'000 && (i < 2000 || !wrapped()); ++i) {
    if (i % 7 == 3) {
      std::uniform_int_distribution<std::int64_t> late(newest - kWindow / 2, newest - 1);
      const std::int64_t stamp = late(random);
      if (kept.count(stamp)) continue;
      ASSERT_EQ(cache.insert(sampleAt(stamp), kWindow), InsertOutcome::kAdded);
      kept.insert(stamp);
    } else {
      newest += unevenGap(i, random);
      ASSERT_EQ(cache.insert(sampleAt(newest), kWindow), InsertOutcome::kAdded);
      kept.insert(newest);
      kept.erase(kept.begin(), kept.lower_bound(newest - kWindow));
    }
  }
  ASSERT_TRUE(wrapped());
  const std::vector<std::int64_t> stamps(kept.begin(), kept.end());
  ASSERT_EQ(cache.size(), stamps.size());
  for (const std::int64_t stamp : stamps) expectExactly(cache, stamp, valueAt(stamp));
  expectArcsToTheNextSample(cache, stamps);
  EXPECT_GT(expectSpanWithinAgreesWithFind(cache, stamps), 0u)
      << "even spacing guessed every sample: the search beyond the guess went untested";
  expectNewestPairAgreesWithFind(cache);
}

// Each sample's arc to the next is kept in the padding of its transform's slot: however a sample
// arrives (after the others, between two, in place of one), and however the ring moves its
// samples (inserting among them, growing), each sample keeps the arc to the one now after it.
TEST(TimeCache, EachSampleKeepsTheArcToTheSampleAfterItInWhateverOrderTheyCame) {
  std::mt19937_64 random(23);
  const std::vector<std::int64_t> stamps = unevenStamps(300, 5);
  std::vector<std::int64_t> order = stamps;
  std::shuffle(order.begin(), order.end(), random);
  TimeCache cache;
  std::map<std::int64_t, int> version;
  for (std::size_t i = 0; i < order.size(); ++i) {
    ASSERT_EQ(cache.insert(sampleAt(order[i]), kKeepAll), InsertOutcome::kAdded);
    if (i % 5 == 4) {
      const std::int64_t again = order[i / 2];
      ASSERT_EQ(cache.insert(sampleAt(again, kParent, 1), kKeepAll), InsertOutcome::kReplaced);
      version[again] = 1;
    }
  }
  ASSERT_EQ(cache.size(), stamps.size());
  expectArcsToTheNextSample(cache, stamps, version);
  // The newest sample replaced, then a sample after it.
  ASSERT_EQ(cache.insert(sampleAt(stamps.back(), kParent, 2), kKeepAll), InsertOutcome::kReplaced);
  version[stamps.back()] = 2;
  std::vector<std::int64_t> longer = stamps;
  longer.push_back(stamps.back() + 50);
  ASSERT_EQ(cache.insert(sampleAt(longer.back()), kKeepAll), InsertOutcome::kAdded);
  expectArcsToTheNextSample(cache, longer, version);
}

TEST(TimeCache, AnOlderSampleWithAnotherParentKeepsEachSamplesParent) {
  TimeCache cache;
  cache.insert(sampleAt(200, kParent), kKeepAll);
  cache.insert(sampleAt(100, kOtherParent), kKeepAll);
  EXPECT_EQ(parentAt(cache, 100, SampleStatus::kOk), kOtherParent);
  EXPECT_EQ(parentAt(cache, 200, SampleStatus::kOk), kParent);
  EXPECT_EQ(cache.newestParent(), kParent);
  EXPECT_TRUE(cache.changesParent());
}

TEST(TimeCache, ReplacingTheOnlySampleWithAnotherParentChangesTheParent) {
  TimeCache cache;
  cache.insert(sampleAt(100, kParent), kKeepAll);
  EXPECT_EQ(cache.insert(sampleAt(100, kOtherParent, 1), kKeepAll), InsertOutcome::kReplaced);
  EXPECT_EQ(cache.newestParent(), kOtherParent);
  EXPECT_FALSE(cache.changesParent());
  cache.insert(sampleAt(200, kOtherParent), kKeepAll);
  expectExactly(cache, 100, valueAt(100, 1), kOtherParent);
  expectExactly(cache, 200, valueAt(200), kOtherParent);
}

TEST(TimeCache, ParentsKeptPerSampleSurviveGrowingAndWrapping) {
  TimeCache cache;
  constexpr std::int64_t kWindow = 1000;
  for (std::int64_t stamp = 0; stamp < 5000; stamp += 10) {
    const FrameId parent = (stamp / 100) % 2 == 0 ? kParent : kOtherParent;
    cache.insert(sampleAt(stamp, parent), kWindow);
  }
  for (std::int64_t stamp = 4000; stamp < 4990; stamp += 10) {
    const FrameId parent = (stamp / 100) % 2 == 0 ? kParent : kOtherParent;
    EXPECT_EQ(parentAt(cache, stamp, SampleStatus::kOk), parent) << "at " << stamp;
    expectExactly(cache, stamp, valueAt(stamp), parent);
  }
}

// A steady edge's ring ends a little above its window, and one with a short history stays
// within a quarter of it: a sample then costs close to the 64 bytes it takes.
TEST(TimeCache, RingEndsNearTheWindowOfASteadyEdgeAndStaysSmallForAShortHistory) {
  constexpr std::int64_t kPeriod = 10'000;
  constexpr std::int64_t kWindow = 10'000'000;
  constexpr std::size_t kWindowSamples = kWindow / kPeriod + 1;
  TimeCache steady;
  for (std::int64_t k = 0; k < 3000; ++k) steady.insert(sampleAt(k * kPeriod), kWindow);
  EXPECT_EQ(steady.size(), kWindowSamples);
  EXPECT_GE(steady.capacity(), kWindowSamples);
  EXPECT_LE(steady.capacity(), kWindowSamples + kWindowSamples / 64 + 4);
  TimeCache short_history;
  for (std::int64_t k = 0; k < 20; ++k) short_history.insert(sampleAt(k * kPeriod), kWindow);
  EXPECT_LE(short_history.capacity(), 20u + 20u / 4);
}

// What a listener may hold at most is the frames times the samples an edge may keep times a
// sample's size: a ring never has room for more samples than its edge may keep, however
// unevenly its samples come.
TEST(TimeCache, RingNeverHasRoomForMoreSamplesThanTheEdgeMayKeep) {
  constexpr std::size_t kMostSamples = 100;
  constexpr std::int64_t kLongWindow = 1'000'000'000;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> gap(1, 5000);
  TimeCache cache;
  std::int64_t stamp = 0;
  for (int k = 0; k < 2000; ++k) {
    stamp += gap(rng);
    cache.insert(sampleAt(stamp, k % 50 < 25 ? kParent : kOtherParent), kLongWindow, kMostSamples);
    ASSERT_LE(cache.capacity(), kMostSamples) << "after " << k + 1 << " samples";
  }
  EXPECT_EQ(cache.size(), kMostSamples);
}

// spanWithin() from prefetch()'s hint at every stamp strictly between two samples: the two
// samples, and a ratio within a few ulps of the quotient.
void expectRatiosAreQuotients(const TimeCache& cache, const std::vector<std::int64_t>& stamps) {
  for (std::size_t i = 0; i + 1 < stamps.size(); ++i) {
    for (std::int64_t stamp = stamps[i] + 1; stamp < stamps[i + 1]; ++stamp) {
      const SampleSpan span = cache.spanWithin(stamp, cache.prefetch(stamp));
      EXPECT_TRUE(holds(span.older, valueAt(stamps[i]))) << "at " << stamp;
      EXPECT_TRUE(holds(span.newer, valueAt(stamps[i + 1]))) << "at " << stamp;
      EXPECT_DOUBLE_EQ(span.ratio, static_cast<double>(stamp - stamps[i]) /
                                       static_cast<double>(stamps[i + 1] - stamps[i]))
          << "at " << stamp;
    }
  }
}

// An edge is steady while every sample it keeps is one interval after the one before: a
// late sample between two others ends that until it leaves the window, an append out of step
// until the samples before it have. Spans agree with find() throughout.
TEST(TimeCache, SteadinessFollowsTheSpacingOfTheSamplesKept) {
  constexpr std::int64_t kWindow = 400;
  TimeCache cache;
  std::vector<std::int64_t> stamps;
  const auto add = [&](std::int64_t stamp) {
    ASSERT_NE(cache.insert(sampleAt(stamp), kWindow), InsertOutcome::kTooOld);
    stamps.insert(std::upper_bound(stamps.begin(), stamps.end(), stamp), stamp);
    stamps.erase(stamps.begin(),
                 std::lower_bound(stamps.begin(), stamps.end(), stamps.back() - kWindow));
  };
  const auto check = [&] {
    expectSpanWithinAgreesWithFind(cache, stamps);
    expectRatiosAreQuotients(cache, stamps);
    expectNewestPairAgreesWithFind(cache);
  };
  EXPECT_FALSE(cache.isSteady());
  for (std::int64_t k = 0; k < 30; ++k) add(1000 + 10 * k);
  EXPECT_TRUE(cache.isSteady());
  check();
  add(1103);
  EXPECT_FALSE(cache.isSteady());
  check();
  std::int64_t newest = stamps.back();
  for (int k = 0; k < 20; ++k) add(newest += 10);
  EXPECT_FALSE(cache.isSteady()) << "the late sample is still kept";
  check();
  for (int k = 0; k < 30; ++k) add(newest += 10);
  EXPECT_TRUE(cache.isSteady());
  check();
  add(newest += 13);
  EXPECT_FALSE(cache.isSteady());
  check();
  for (int k = 0; k < 40; ++k) add(newest += 13);
  EXPECT_TRUE(cache.isSteady());
  check();
  add(newest);  // the newest again: the stamps stay as they were
  EXPECT_TRUE(cache.isSteady());
}

// The ratio between two samples depends on their stamps alone, not on the edge's other samples
// or the order they came in: a log replayed into a buffer that keeps less history, or one that
// saw a late sample, interpolates bit for bit as the live buffer did. Pairs at the steady
// intervals of 100, 30 and 1,000 Hz, where a steady edge's ratios are asked for.
TEST(TimeCache, RatioBetweenTwoSamplesDependsOnTheirStampsAlone) {
  for (const std::int64_t interval : {10'000, 33'333, 1'000}) {
    const std::int64_t start = 1'000'000;
    const std::int64_t older = start + 10 * interval;
    const std::int64_t newer = older + interval;
    TimeCache steady;
    TimeCache uneven_oldest;
    TimeCache late_sample;
    TimeCache short_window;
    uneven_oldest.insert(sampleAt(start - 7), kKeepAll);
    for (std::int64_t stamp = start; stamp <= newer; stamp += interval) {
      steady.insert(sampleAt(stamp), kKeepAll);
      uneven_oldest.insert(sampleAt(stamp), kKeepAll);
      short_window.insert(sampleAt(stamp), 3 * interval);
      if (stamp != older - interval) late_sample.insert(sampleAt(stamp), kKeepAll);
    }
    late_sample.insert(sampleAt(older - interval), kKeepAll);
    ASSERT_TRUE(steady.isSteady());
    const TimeCache* others[] = {&uneven_oldest, &late_sample, &short_window};
    std::size_t differing = 0;
    for (std::int64_t stamp = older + 1; stamp < newer; ++stamp) {
      SampleSpan expected;
      ASSERT_EQ(steady.find(stamp, expected), SampleStatus::kOk);
      EXPECT_DOUBLE_EQ(expected.ratio,
                       static_cast<double>(stamp - older) / static_cast<double>(interval));
      for (const TimeCache* other : others) {
        SampleSpan span;
        ASSERT_EQ(other->find(stamp, span), SampleStatus::kOk);
        const SampleSpan within = other->spanWithin(stamp, other->prefetch(stamp));
        double newest_pair_ratio = -1.0;
        ASSERT_TRUE(other->ratioInNewestPair(stamp, newest_pair_ratio));
        if (span.ratio != expected.ratio || within.ratio != expected.ratio ||
            newest_pair_ratio != expected.ratio) {
          ++differing;
        }
      }
    }
    EXPECT_EQ(differing, 0u) << "ratios that differ in their last bits, " << interval
                             << " us apart";
  }
}

// At a steady interval, the guess of where a stamp falls (from the samples a microsecond, kept
// in fixed point) is the sample at or before it, or at a sample's own stamp the one before that,
// which spanWithin() takes at once: neither searches. However short the interval, however late
// the stamps.
TEST(TimeCache, GuessOfASteadyEdgeIsTheSampleBeforeEachStamp) {
  constexpr std::size_t kSamples = 300;
  for (const std::int64_t interval : {1, 2, 3, 1'000, 10'000, 33'333}) {
    for (const std::int64_t start :
         {std::int64_t{1'000'000}, std::int64_t{1'764'000'000'000'000}}) {
      TimeCache cache;
      for (std::size_t k = 0; k < kSamples; ++k) {
        cache.insert(sampleAt(start + static_cast<std::int64_t>(k) * interval), kKeepAll);
      }
      ASSERT_TRUE(cache.isSteady()) << interval << " us apart";
      for (std::size_t k = 0; k + 1 < kSamples; ++k) {
        const std::int64_t sample = start + static_cast<std::int64_t>(k) * interval;
        for (const std::int64_t past :
             {std::int64_t{0}, std::int64_t{1}, interval / 2, interval - 1}) {
          if (past >= interval) continue;
          const std::size_t guess = cache.prefetch(sample + past);
          const bool right = past == 0 ? guess == k || guess + 1 == k : guess == k;
          ASSERT_TRUE(right) << "guessed sample " << guess << " for " << past << " us after sample "
                             << k << ", " << interval << " us apart, from " << start;
          SampleSpan expected;
          ASSERT_EQ(cache.find(sample + past, expected), SampleStatus::kOk);
          ASSERT_TRUE(sameSpan(cache.spanWithin(sample + past, guess), expected));
        }
      }
    }
  }
}

TEST(TimeCache, NewestPairNeedsTwoSamples) {
  TimeCache cache;
  expectNewestPairAgreesWithFind(cache);
  cache.insert(sampleAt(1000), kKeepAll);
  expectNewestPairAgreesWithFind(cache);
  cache.insert(sampleAt(1010), kKeepAll);
  expectNewestPairAgreesWithFind(cache);
  const Transform* older = nullptr;
  const Transform* newer = nullptr;
  double arc = 0.0;
  EXPECT_TRUE(cache.newestPair(older, newer, arc));
  EXPECT_TRUE(holds(older, valueAt(1000)));
  EXPECT_TRUE(holds(newer, valueAt(1010)));
}

TEST(TimeCache, EdgeWithIntervalsTooLongToKeepIsNeverSteady) {
  constexpr std::int64_t kLong = std::int64_t{1} << 33;
  TimeCache cache;
  std::vector<std::int64_t> stamps;
  for (std::int64_t k = 0; k < 5; ++k) {
    cache.insert(sampleAt(k * kLong), kKeepAll);
    stamps.push_back(k * kLong);
    EXPECT_FALSE(cache.isSteady()) << "after " << k + 1 << " samples";
  }
  for (std::size_t i = 0; i + 1 < stamps.size(); ++i) {
    const std::int64_t stamp = stamps[i] + kLong / 3;
    EXPECT_TRUE(sameSpan(cache.spanWithin(stamp, cache.prefetch(stamp)), [&] {
      SampleSpan span;
      cache.find(stamp, span);
      return span;
    }()));
  }
}

TEST(TimeCache, ClearingOrMakingStaticForgetsTheInterval) {
  TimeCache cache;
  for (std::int64_t k = 0; k < 10; ++k) cache.insert(sampleAt(100 * k), kKeepAll);
  ASSERT_TRUE(cache.isSteady());
  cache.clearHistory();
  EXPECT_FALSE(cache.isSteady());
  cache.insert(sampleAt(5000), kKeepAll);
  cache.insert(sampleAt(5007), kKeepAll);
  EXPECT_TRUE(cache.isSteady());
  cache.setStatic(kParent, valueAt(0));
  EXPECT_FALSE(cache.isSteady());
  cache.insert(sampleAt(9000), kKeepAll);
  EXPECT_FALSE(cache.isSteady()) << "one sample has no interval";
}

}  // namespace
}  // namespace lcmtf::detail
