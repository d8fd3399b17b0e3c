#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include "lcmtf/transform.hpp"

namespace lcmtf::detail {

/// Storage for a ring of stamped transforms: each transform on a cache line of its own, with the
/// arc from its rotation to the next slot's beside it, and the stamps side by side in an array
/// after the slots. Where Eigen aligns the rotation to 16 bytes, the arc fills the 8 bytes that
/// leaves after the translation; else it follows the transform. A sample costs 72 bytes.
///
/// A search by time reads stamps eight to a line, and a steady edge's interpolation two lines
/// (its ratio needs no stamp), where with each stamp in its slot and the arcs in an array of
/// their own it read three. In buffer_core_bench (fastest of five alternating runs), wide's
/// random lookups 85.0 -> 78.1 ns, its time-travel ones 139 -> 134, the other lookups 1-3 %
/// faster; with --jitter-us=300, wide's inserts 85.7 -> 73.2 ns and the latest-time lookups of
/// pr2 and deep_chain 5-9 % faster, deep_chain's random ones 5 % slower, the rest within 4 %.
///
/// Slots and stamps share one plain heap block, aligned by hand: the heap's aligned allocation
/// splits off and frees its margins on every ring, and with a second block, adding a frame to
/// the forest of buffer_core_bench took 6-10 % longer. Slots are left unwritten until stored,
/// so that a ring sized for a long history costs no page faults (under the writer's lock)
/// until the history fills it.
class SampleRing {
 public:
  SampleRing() = default;
  explicit SampleRing(std::size_t size) : size_(size) {
    if (size == 0) return;
    block_.reset(new unsigned char[size * (sizeof(Slot) + sizeof(std::int64_t)) + kAlignmentSlack]);
    const auto start = reinterpret_cast<std::uintptr_t>(block_.get());
    slots_ = reinterpret_cast<Slot*>((start + alignof(Slot) - 1) & ~(alignof(Slot) - 1));
  }

  std::size_t size() const { return size_; }
  /// The transform last stored in slot `index`; only stored slots may be read.
  const Transform& transform(std::size_t index) const {
    return *std::launder(reinterpret_cast<const Transform*>(slots_[index].bytes));
  }
  std::int64_t stamp(std::size_t index) const { return stamps()[index]; }
  /// Stores a sample, leaving the slot's arc to be set: constructing the transform may write
  /// its padding, where the arc may be.
  void store(std::size_t index, std::int64_t stamp, const Transform& value) {
    ::new (static_cast<void*>(slots_[index].bytes)) Transform(value);
    stamps()[index] = stamp;
  }
  /// Copies slot `from` of `source` (this ring or another), its arc included, into slot `to`.
  void copy(const SampleRing& source, std::size_t from, std::size_t to) {
    std::memcpy(slots_[to].bytes, source.slots_[from].bytes, sizeof(Slot));
    stamps()[to] = source.stamps()[from];
  }
  /// Slot `index`'s arc, to the next slot's rotation.
  double arc(std::size_t index) const {
    double arc;
    std::memcpy(&arc, slots_[index].bytes + kArcOffset, sizeof arc);
    return arc;
  }
  void setArc(std::size_t index, double arc) {
    std::memcpy(slots_[index].bytes + kArcOffset, &arc, sizeof arc);
  }
  /// Where slot `index` is, to prefetch.
  const void* address(std::size_t index) const { return slots_[index].bytes; }
  /// Where slot `index`'s stamp is, to prefetch.
  const void* stampAddress(std::size_t index) const { return stamps() + index; }
  void swap(SampleRing& other) noexcept {
    block_.swap(other.block_);
    std::swap(slots_, other.slots_);
    std::swap(size_, other.size_);
  }
  void clear() { SampleRing().swap(*this); }

 private:
  static_assert(std::is_trivially_destructible_v<Transform>);
  // Where the translation ends and the rotation begins, both doubles.
  static constexpr std::size_t kTranslationEnd = sizeof(Eigen::Vector3d);
  static constexpr std::size_t kRotationStart = sizeof(Transform) - sizeof(Eigen::Quaterniond);
  static constexpr bool kArcInPadding = kRotationStart >= kTranslationEnd + sizeof(double);
  static constexpr std::size_t kArcOffset = kArcInPadding ? kTranslationEnd : sizeof(Transform);
  static constexpr std::size_t kUsedBytes =
      kArcInPadding ? sizeof(Transform) : sizeof(Transform) + sizeof(double);
  struct alignas(64) Slot {
    unsigned char bytes[kUsedBytes];
  };
  static_assert(!kArcInPadding || sizeof(Slot) == 64);
  // The most the slots start after a heap block's start, which is aligned for any scalar.
  static constexpr std::size_t kAlignmentSlack = alignof(Slot) - alignof(std::max_align_t);

  // The stamps follow the slots. Found from them rather than kept, so that the time cache has
  // room for what its steady edges need on the cache line its lookups read.
  std::int64_t* stamps() const { return reinterpret_cast<std::int64_t*>(slots_ + size_); }

  std::unique_ptr<unsigned char[]> block_;
  Slot* slots_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace lcmtf::detail
