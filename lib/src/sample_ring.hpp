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

/// Storage for a ring of stamped transforms, one cache line a sample: searching by time reads
/// the lines the interpolation then uses, and a sample costs 64 bytes. Where Eigen aligns the
/// rotation to 16 bytes, the stamp fills the 8 bytes that leaves after the translation; else it
/// follows the transform. Slots are left unwritten until stored, so that a ring sized for a
/// long history costs no page faults (under the writer's lock) until the history fills it.
///
/// Each slot has an arc too, a double the edge keeps for interpolating from it to the next
/// slot. Slots and arcs share one plain heap block, aligned by hand: the heap's aligned
/// allocation splits off and frees its margins on every ring, and with a second block for the
/// arcs, adding a frame to the forest of buffer_core_bench took 6-10 % longer.
class SampleRing {
 public:
  SampleRing() = default;
  explicit SampleRing(std::size_t size) : size_(size) {
    if (size == 0) return;
    block_.reset(new unsigned char[size * (sizeof(Slot) + sizeof(double)) + kAlignmentSlack]);
    const auto start = reinterpret_cast<std::uintptr_t>(block_.get());
    slots_ = reinterpret_cast<Slot*>((start + alignof(Slot) - 1) & ~(alignof(Slot) - 1));
  }

  std::size_t size() const { return size_; }
  /// The transform last stored in slot `index`; only stored slots may be read.
  const Transform& transform(std::size_t index) const {
    return *std::launder(reinterpret_cast<const Transform*>(slots_[index].bytes));
  }
  std::int64_t stamp(std::size_t index) const {
    std::int64_t stamp;
    std::memcpy(&stamp, slots_[index].bytes + kStampOffset, sizeof stamp);
    return stamp;
  }
  /// The transform first: constructing it may write its padding, where the stamp may go.
  void store(std::size_t index, std::int64_t stamp, const Transform& value) {
    ::new (static_cast<void*>(slots_[index].bytes)) Transform(value);
    std::memcpy(slots_[index].bytes + kStampOffset, &stamp, sizeof stamp);
  }
  /// Copies slot `from` of `source` (this ring or another) into slot `to`.
  void copy(const SampleRing& source, std::size_t from, std::size_t to) {
    std::memcpy(slots_[to].bytes, source.slots_[from].bytes, sizeof(Slot));
  }
  /// Slot `index`'s arc, to the next slot's rotation.
  double& arc(std::size_t index) { return arcs()[index]; }
  double arc(std::size_t index) const { return arcs()[index]; }
  /// Where slot `index` is, to prefetch.
  const void* address(std::size_t index) const { return slots_[index].bytes; }
  /// Where slot `index`'s arc is, to prefetch.
  const void* arcAddress(std::size_t index) const { return arcs() + index; }
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
  static constexpr bool kStampInPadding = kRotationStart >= kTranslationEnd + sizeof(std::int64_t);
  static constexpr std::size_t kStampOffset = kStampInPadding ? kTranslationEnd : sizeof(Transform);
  static constexpr std::size_t kUsedBytes =
      kStampInPadding ? sizeof(Transform) : sizeof(Transform) + sizeof(std::int64_t);
  struct alignas(64) Slot {
    unsigned char bytes[kUsedBytes];
  };
  static_assert(!kStampInPadding || sizeof(Slot) == 64);
  // The most the slots start after a heap block's start, which is aligned for any scalar.
  static constexpr std::size_t kAlignmentSlack = alignof(Slot) - alignof(std::max_align_t);

  // The arcs follow the slots. Found from them rather than kept, so that the time cache has
  // room for what its steady edges need on the cache line its lookups read.
  double* arcs() const { return reinterpret_cast<double*>(slots_ + size_); }

  std::unique_ptr<unsigned char[]> block_;
  Slot* slots_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace lcmtf::detail
