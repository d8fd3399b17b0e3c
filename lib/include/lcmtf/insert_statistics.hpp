#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace lcmtf {

/// Why setTransform refused a transform; each kind is counted separately.
enum class InsertRejection : std::size_t {
  kNonFinite,         ///< NaN or infinity in translation or rotation
  kBadQuaternion,     ///< quaternion zero, or its norm off 1 by more than 1e-3
  kEmptyFrameName,    ///< parent or child name empty (after stripping one leading '/')
  kSelfParented,      ///< parent and child are the same frame
  kOlderThanHistory,  ///< stamp older than cache_time behind the edge's newest sample
  kEdgeFull,          ///< the edge holds its most samples, all newer (setMostSamplesPerEdge)
  kCount
};

/// A short name for a rejection kind ("non-finite value", ...).
const char* describe(InsertRejection kind);

/// What setTransform has done since construction (clear() keeps these counts).
struct InsertStatistics {
  std::uint64_t inserted = 0;             ///< samples stored, static ones included
  std::uint64_t replaced = 0;             ///< a repeated stamp that replaced its sample
  std::uint64_t normalized = 0;           ///< quaternions normalized on the way in
  std::uint64_t authority_conflicts = 0;  ///< an edge set by another authority than before
  std::uint64_t dropped_for_room = 0;     ///< oldest samples dropped early: the edge held its most
  std::array<std::uint64_t, static_cast<std::size_t>(InsertRejection::kCount)> rejected{};

  std::uint64_t rejectedCount(InsertRejection kind) const {
    return rejected[static_cast<std::size_t>(kind)];
  }
  std::uint64_t rejectedTotal() const {
    std::uint64_t total = 0;
    for (std::uint64_t count : rejected) total += count;
    return total;
  }
};

}  // namespace lcmtf
