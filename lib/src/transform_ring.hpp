#pragma once

#include <cstddef>
#include <new>
#include <type_traits>

#include "lcmtf/transform.hpp"
#include "unfilled_array.hpp"

namespace lcmtf::detail {

/// Storage for a ring of transforms, each on a cache line of its own. Slots are left unwritten
/// until a transform is stored in them, so that a ring sized for a long history costs no page
/// faults (under the writer's lock) until the history fills it.
class TransformRing {
 public:
  TransformRing() = default;
  explicit TransformRing(std::size_t size) : slots_(size) {}

  std::size_t size() const { return slots_.size(); }
  /// The transform last stored in slot `index`; only stored slots may be read.
  const Transform& operator[](std::size_t index) const {
    return *std::launder(reinterpret_cast<const Transform*>(slots_[index].bytes));
  }
  void store(std::size_t index, const Transform& value) {
    ::new (static_cast<void*>(slots_[index].bytes)) Transform(value);
  }
  /// Where slot `index` is, to prefetch.
  const void* address(std::size_t index) const { return slots_[index].bytes; }
  void swap(TransformRing& other) noexcept { slots_.swap(other.slots_); }
  void clear() { slots_.clear(); }

 private:
  static_assert(std::is_trivially_destructible_v<Transform>);
  struct alignas(64) Slot {
    unsigned char bytes[sizeof(Transform)];
  };

  UnfilledArray<Slot> slots_;
};

}  // namespace lcmtf::detail
