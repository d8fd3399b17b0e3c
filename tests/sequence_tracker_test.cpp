#include "lcmtf/sequence_tracker.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <limits>

namespace lcmtf {
namespace {

SequenceCounts countsAfter(std::initializer_list<std::int64_t> numbers) {
  SequenceTracker tracker;
  for (const std::int64_t n : numbers) tracker.observe(n);
  return tracker.counts();
}

void expectCounts(const SequenceCounts& counts, std::uint64_t lost, std::uint64_t reordered,
                  std::uint64_t duplicated, std::uint64_t restarts) {
  EXPECT_EQ(counts.lost, lost);
  EXPECT_EQ(counts.reordered, reordered);
  EXPECT_EQ(counts.duplicated, duplicated);
  EXPECT_EQ(counts.restarts, restarts);
}

TEST(SequenceTracker, NumbersInOrderCountNothing) {
  expectCounts(countsAfter({1, 2, 3, 4, 5}), 0, 0, 0, 0);
}

TEST(SequenceTracker, NumbersBeforeTheFirstHeardAreNotLost) {
  expectCounts(countsAfter({500, 501, 502}), 0, 0, 0, 0);
}

TEST(SequenceTracker, SkippedNumbersAreLostUntilTheyComeLate) {
  expectCounts(countsAfter({1, 2, 6}), 3, 0, 0, 0);
  expectCounts(countsAfter({1, 2, 6, 4, 3}), 1, 2, 0, 0);
  expectCounts(countsAfter({1, 2, 6, 4, 3, 5}), 0, 3, 0, 0);
}

TEST(SequenceTracker, ANumberHeardBeforeTheFirstIsLateNotTakenBack) {
  expectCounts(countsAfter({10, 11, 9, 12}), 0, 1, 0, 0);
}

TEST(SequenceTracker, ANumberHeardAgainIsADuplicate) {
  expectCounts(countsAfter({1, 2, 2, 3, 2, 3}), 0, 0, 3, 0);
}

TEST(SequenceTracker, NumbersFarBelowTheHighestAreARestartNotALoss) {
  SequenceTracker tracker;
  for (std::int64_t n = 1; n <= 1000; ++n) tracker.observe(n);
  for (std::int64_t n = 500; n <= 600; ++n) tracker.observe(n);  // a log replayed from its middle
  expectCounts(tracker.counts(), 0, 0, 0, 1);
}

TEST(SequenceTracker, OneAgainIsARestartEvenCloseToTheHighest) {
  expectCounts(countsAfter({1, 2, 3, 1, 2, 3, 4}), 0, 0, 0, 1);
  expectCounts(countsAfter({7, 8, 1, 2}), 0, 0, 0, 1);
}

TEST(SequenceTracker, UnnumberedBatchesAreIgnored) {
  expectCounts(countsAfter({0, 0, -5, std::numeric_limits<std::int64_t>::min()}), 0, 0, 0, 0);
  expectCounts(countsAfter({1, 0, 2, -1, 3}), 0, 0, 0, 0);
}

TEST(SequenceTracker, AHugeJumpCountsItsGapAndTakesNoTime) {
  const std::int64_t top = std::numeric_limits<std::int64_t>::max();
  expectCounts(countsAfter({1, top}), static_cast<std::uint64_t>(top - 2), 0, 0, 0);
  expectCounts(countsAfter({1, top, 2}), static_cast<std::uint64_t>(top - 2), 0, 0, 1);
  expectCounts(countsAfter({1, top, top - 1}), static_cast<std::uint64_t>(top - 3), 1, 0, 0);
}

TEST(SequenceTracker, RestartForgetsTheNumbersButKeepsTheCounts) {
  SequenceTracker tracker;
  for (const std::int64_t n : {1, 3}) tracker.observe(n);
  tracker.restart();
  for (const std::int64_t n : {1, 2}) tracker.observe(n);
  expectCounts(tracker.counts(), 1, 0, 0, 0);
}

}  // namespace
}  // namespace lcmtf
