#pragma once

#include <atomic>

namespace lcmtf::detail {

extern std::atomic<bool> quick_lookups_enabled;

/// Whether lookups may take the root paths (the quick way) before walking the tree edge by
/// edge; on unless a test turns it off, to check the walk alone against the same answers.
inline bool quickLookupsEnabled() { return quick_lookups_enabled.load(std::memory_order_relaxed); }
/// Turns quick lookups on or off for every buffer in the process (for tests).
void setQuickLookupsEnabled(bool enabled);

/// Whether every quick answer is recomputed by the walk, and a disagreement aborts the program
/// with both answers: in the sanitizer builds, where the tests run slowly anyway.
#ifdef LCMTF_CROSS_CHECK_LOOKUPS
constexpr bool kCrossCheckQuickLookups = true;
#else
constexpr bool kCrossCheckQuickLookups = false;
#endif

}  // namespace lcmtf::detail
