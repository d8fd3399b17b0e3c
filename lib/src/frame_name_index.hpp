#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "time_cache.hpp"

namespace lcmtf::detail {

/// Frame name -> id: open addressing on a power-of-two table with a cheap hash, since every
/// lookup by name starts here. Names are owned elsewhere and must outlive the index.
class FrameNameIndex {
 public:
  FrameId find(std::string_view name) const {
    if (slots_.empty()) return kNoFrame;
    const std::uint64_t hash = hashOf(name);
    for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
      const Slot& slot = slots_[i];
      if (slot.id == kNoFrame) return kNoFrame;
      if (slot.hash == hash && slot.name == name) return slot.id;
    }
  }

  void insert(std::string_view name, FrameId id) {
    if (2 * (count_ + 1) > slots_.size()) grow();
    place(Slot{hashOf(name), name, id});
    ++count_;
  }

  static std::uint64_t hashOf(std::string_view name) {
    constexpr std::uint64_t kMultiplier = 0x9e3779b97f4a7c15ull;
    std::uint64_t hash = name.size() * kMultiplier;
    std::size_t offset = 0;
    for (; offset + 8 <= name.size(); offset += 8) {
      std::uint64_t chunk;
      std::memcpy(&chunk, name.data() + offset, 8);
      hash = (hash ^ chunk) * kMultiplier;
      hash ^= hash >> 29;
    }
    if (offset < name.size()) {
      std::uint64_t chunk = 0;
      std::memcpy(&chunk, name.data() + offset, name.size() - offset);
      hash = (hash ^ chunk) * kMultiplier;
    }
    hash ^= hash >> 32;
    return hash * kMultiplier;
  }

 private:
  struct Slot {
    std::uint64_t hash = 0;
    std::string_view name;
    FrameId id = kNoFrame;
  };

  void place(const Slot& slot) {
    std::size_t i = slot.hash & mask_;
    while (slots_[i].id != kNoFrame) i = (i + 1) & mask_;
    slots_[i] = slot;
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.resize(old.empty() ? 64 : old.size() * 2);
    mask_ = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.id != kNoFrame) place(slot);
    }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::size_t count_ = 0;
};

}  // namespace lcmtf::detail
