#pragma once

#include <atomic>

namespace lcmtf::detail {

extern std::atomic<bool> quick_lookups_enabled;

/// Whether lookups may take the root paths (the quick way) before walking the tree edge by
/// edge; on unless a test turns it off, to check the walk alone against the same answers.
inline bool quickLookupsEnabled() { return quick_lookups_enabled.load(std::memory_order_relaxed); }
/// Turns quick lookups on or off for every buffer in the process (for tests).
void setQuickLookupsEnabled(bool enabled);

/// Whether this build can recompute every quick answer by the walk and abort the program with
/// both answers when they disagree: the sanitizer builds, where the tests run slowly anyway.
#ifdef LCMTF_CROSS_CHECK_LOOKUPS
constexpr bool kCrossCheckBuild = true;
#else
constexpr bool kCrossCheckBuild = false;
#endif

extern std::atomic<bool> cross_check_enabled;

/// Whether quick answers are checked against the walk now: in a cross-check build, unless a
/// program turned it off (the fuzzers do: their absurd magnitudes probe rounding, not logic).
inline bool crossCheckQuickLookups() {
  return kCrossCheckBuild && cross_check_enabled.load(std::memory_order_relaxed);
}
/// Turns the check of quick answers against the walk on or off, in a cross-check build.
void setCrossCheckEnabled(bool enabled);

}  // namespace lcmtf::detail
