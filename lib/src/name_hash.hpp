#pragma once

#include <chrono>
#include <cstdint>
#include <exception>
#include <random>
#include <string_view>

#include "name_words.hpp"

namespace lcmtf::detail {

/// A hash of names from the network (frames, senders), keyed at random by each instance, so that
/// nobody can work out names that share a slot or bucket of the table it serves and make every
/// lookup among them walk the others. The key enters every word's mix: with known seeds, names
/// of 32 bytes could be made to share their whole hash.
class NameHash {
 public:
  NameHash() : seeds_(seedsFrom(randomSeed())) {}

  // Independent multiplies of 8-byte words (overlapping where the size is not a multiple of 8,
  // so no word is read byte by byte), so that a name's words mix at once rather than in
  // sequence. Names of up to 32 bytes, nearly all of them, take a fixed number of words.
  std::uint64_t operator()(std::string_view name) const {
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

  Seeds seeds_;
};

}  // namespace lcmtf::detail
