#pragma once

#include <chrono>
#include <cstdint>
#include <exception>
#include <random>
#include <string_view>
#include <vector>

#include "large_arrays.hpp"
#include "name_words.hpp"
#include "time_cache.hpp"

namespace lcmtf::detail {

/// Frame name -> id: open addressing on a power-of-two table with a cheap hash, since every
/// lookup by name starts here. A slot holds only part of the name's hash and the id, 8 bytes,
/// so that more of the table stays in the nearer caches; the names, which must outlive the
/// index, are reached through the id. Ids are small and dense, as frames are numbered. Each
/// index seeds its hash at random, so that nobody can work out names that land in one run of
/// slots and make every lookup among them walk it.
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

  FrameNameIndex() : names_(1), seeds_(seedsFrom(randomSeed())) {}

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

  // Independent multiplies of 8-byte words (overlapping where the size is not a multiple of 8,
  // so no word is read byte by byte), so that a name's words mix at once rather than in
  // sequence. Names of up to 32 bytes, nearly all of them, take a fixed number of words.
  std::uint64_t hashOf(std::string_view name) const {
    const std::size_t size = name.size();
    const char* bytes = name.data();
    const std::uint64_t hash = size * kMultiplier;
    if (size <= 8) return finish(hash + mix(shortNameWord(bytes, size), seeds_.first));
    const std::uint64_t ends =
        mix(nameWord(bytes), seeds_.first) + mix(nameWord(bytes + size - 8), seeds_.last);
    if (size <= 16) return finish(hash + ends);
    if (size <= 32) {
      return finish(hash + ends + mix(nameWord(bytes + 8), seeds_.second) +
                    mix(nameWord(bytes + size - 16), seeds_.second_last));
    }
    // Each word's seed depends on its place, so that words trading places change the hash.
    std::uint64_t middle = 0;
    for (std::size_t offset = 8; offset + 8 < size; offset += 8) {
      middle += mix(nameWord(bytes + offset), seeds_.first + offset * kMultiplier);
    }
    return finish(hash + ends + middle);
  }

 private:
  static constexpr std::uint64_t kMultiplier = 0x9e3779b97f4a7c15ull;

  // The seed of each word a name of up to 32 bytes is read as, by its place.
  struct Seeds {
    std::uint64_t first;
    std::uint64_t last;
    std::uint64_t second;
    std::uint64_t second_last;
  };
  static Seeds seedsFrom(std::uint64_t seed) {
    return Seeds{seed, ~seed, seed + kMultiplier, seed - kMultiplier};
  }
  static std::uint64_t randomSeed() {
    try {
      std::random_device device;
      return (std::uint64_t{device()} << 32) ^ device();
    } catch (const std::exception&) {
      // No source of randomness: the time at least differs from run to run.
      return finish(
          static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()));
    }
  }

  static std::uint64_t finish(std::uint64_t hash) {
    hash = (hash ^ (hash >> 32)) * 0xbf58476d1ce4e5b9ull;
    return hash ^ (hash >> 31);
  }
  static std::uint64_t mix(std::uint64_t word, std::uint64_t seed) {
    const std::uint64_t product = (word ^ seed) * 0x9e3779b97f4a7c15ull;
    return product ^ (product >> 29);
  }

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
  Seeds seeds_;
};

}  // namespace lcmtf::detail
