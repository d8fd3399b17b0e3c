#pragma once

#include <algorithm>

#ifndef LCMTF_TEST_WORK_DIVISOR
#define LCMTF_TEST_WORK_DIVISOR 1
#endif

namespace lcmtf_test {

/// Randomized and concurrent tests run at full size in optimized builds, and at a part of it
/// in unoptimized or sanitized builds, which run 10 to 50 times slower (the build sets this).
inline constexpr int kWorkDivisor = LCMTF_TEST_WORK_DIVISOR;

/// `full` in an optimized build, a kWorkDivisor-th of it (at least `least`) in the slower ones.
inline int scaledCount(int full, int least = 1) { return std::max(least, full / kWorkDivisor); }

}  // namespace lcmtf_test
