#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "large_arrays.hpp"
#include "name_hash.hpp"
#include "name_words.hpp"
#include "time_cache.hpp"

namespace lcmtf::detail {

/// Frame name -> id: open addressing on a power-of-two table with a cheap hash, since every
/// lookup by name starts here. A slot holds only part of the name's hash and the id, 8 bytes,
/// so that more of the table stays in the nearer caches; the names, which must outlive the
/// index, are reached through the id. Ids are small and dense, as frames are numbered. Each
/// index keys its hash at random (NameHash).
class FrameNameIndex {
 public:
  FrameId find(std::string_view name) const {
    if (slots_.empty()) return kNoFrame;
    const std::uint64_t hash = hashOf(name);
    const std::uint32_t tag = tagOf(hash);
    for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
      const Slot slot = slots_[i];
      if (slot.id == kNoFrame) return kNoFrame;
      if (slot.tag != tag) continue;
      if (sameName(names_[slot.id], name)) return slot.id;
    }
  }

  FrameNameIndex() : names_(1) {}

  /// The name of frame `id`: empty for kNoFrame, and for an id not inserted below the highest.
  std::string_view nameOf(FrameId id) const { return names_[id]; }

  void insert(std::string_view name, FrameId id) {
    // At most a quarter full, so that most names are found at the first slot tried.
    if (4 * (count_ + 1) > slots_.size()) grow();
    if (names_.size() <= id) names_.resize(id + 1);
    names_[id] = name;
    place(hashOf(name), id);
    ++count_;
  }

  /// The hash this index places `name` by.
  std::uint64_t hashOf(std::string_view name) const { return hash_(name); }

 private:
  // The hash's high half: its low bits pick the slot.
  static std::uint32_t tagOf(std::uint64_t hash) { return static_cast<std::uint32_t>(hash >> 32); }

  struct Slot {
    std::uint32_t tag = 0;
    FrameId id = kNoFrame;
  };

  void place(std::uint64_t hash, FrameId id) {
    std::size_t i = hash & mask_;
    while (slots_[i].id != kNoFrame) i = (i + 1) & mask_;
    slots_[i] = Slot{tagOf(hash), id};
  }

  void grow() {
    std::vector<Slot, LargeArrayAllocator<Slot>> old;
    old.swap(slots_);
    slots_.resize(old.empty() ? 64 : old.size() * 2);
    mask_ = slots_.size() - 1;
    for (const Slot& slot : old) {
      if (slot.id != kNoFrame) place(hashOf(names_[slot.id]), slot.id);
    }
  }

  std::vector<Slot, LargeArrayAllocator<Slot>> slots_;
  std::vector<std::string_view, LargeArrayAllocator<std::string_view>> names_;  // by id, from 0
  std::size_t mask_ = 0;
  std::size_t count_ = 0;
  NameHash hash_;
};

}  // namespace lcmtf::detail
