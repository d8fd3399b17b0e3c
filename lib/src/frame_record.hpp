#pragma once

#include <string_view>
#include <vector>

#include "lcmtf/transform.hpp"
#include "stable_vector.hpp"
#include "time_cache.hpp"

namespace lcmtf {

using detail::FrameId;
using detail::kNoFrame;

/// One frame and the edge to its parent. Each record starts a cache line: what an insert
/// reads and writes (the name, the ids beside it and the edge's hot part) fills its first three
/// lines, in what the cache's alignment would leave as padding after the name.
struct alignas(64) FrameRecord {
  std::string_view name;
  std::uint32_t authority = 0;
  // The child of the edge inserted after this frame's the last time, so that a publisher's
  // next edge is found without hashing its name (see BufferCore::Impl::knownChild()).
  FrameId next_inserted = kNoFrame;
  // The highest frame reached from this one through static edges alone (this frame itself
  // when its edge is not static), and the static edges between them composed, so a lookup
  // crosses a chain of static edges in one step.
  FrameId static_top = kNoFrame;
  // The buffer's count of stored samples, modulo 2^32, once this edge's last dynamic sample
  // was stored (BufferCore::Impl::prefetchNextSample()), in what was padding.
  std::uint32_t stored_after = 0;
  detail::TimeCache cache;
  std::uint64_t authority_conflicts = 0;
  Transform static_top_T_frame;
};

/// How many of a record's cache lines an insert reads.
constexpr std::size_t kInsertedRecordLines = 3;

/// Every frame's record, indexed by FrameId; records stay where they are as frames are added.
using FrameTable = detail::StableVector<FrameRecord>;

/// Continues `parent`'s static chain through `record`'s static edge `parent_T_record`.
inline void continueStaticChain(FrameRecord& record, const FrameRecord& parent,
                                const Transform& parent_T_record) {
  record.static_top = parent.static_top;
  record.static_top_T_frame = parent.static_top_T_frame * parent_T_record;
}

}  // namespace lcmtf
