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

  // Names of up to 32 bytes, nearly all of them, take a fixed number of words, read 8 bytes at a
  // time (overlapping where the size is not a multiple of 8, so no word is read byte by byte),
  // and seeded words multiply in pairs, each 128-bit product folded to 64 bits: one
  // multiplication deep, where a lookup by name waits for the hash before it can start. (Against
  // a mix of each word alone and a finishing mix: 1-4 % off the lookups of buffer_core_bench on
  // pr2, deep_chain and wide, 7-8 % off canTransform, the forest's names as evenly spread.)
  std::uint64_t operator()(std::string_view name) const {
    const std::size_t size = name.size();
    const char* bytes = name.data();
    const std::uint64_t sized = size * kMultiplier;
    if (size <= 8) return sized ^ fold(shortNameWord(bytes, size) ^ seeds_.first, seeds_.last);
    const std::uint64_t ends =
        fold(nameWord(bytes) ^ seeds_.first, nameWord(bytes + size - 8) ^ seeds_.last);
    if (size <= 16) return sized ^ ends;
    if (size <= 32) {
      return sized ^ (ends + fold(nameWord(bytes + 8) ^ seeds_.second,
                                  nameWord(bytes + size - 16) ^ seeds_.second_last));
    }
    // Each word's seed depends on its place, so that words trading places change the hash.
    std::uint64_t middle = 0;
    for (std::size_t offset = 8; offset + 8 < size; offset += 8) {
      middle += fold(nameWord(bytes + offset) ^ (seeds_.first + offset * kMultiplier),
                     seeds_.second + offset);
    }
    return sized ^ (ends + middle);
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
  // `last` multiplies every name of up to 8 bytes: odd, so that it is never 0.
  static Seeds seedsFrom(std::uint64_t seed) {
    const std::uint64_t other = mixed(seed ^ kMultiplier) | 1;
    return Seeds{seed, other, mixed(seed), mixed(other)};
  }
  static std::uint64_t randomSeed() {
    try {
      std::random_device device;
      return (std::uint64_t{device()} << 32) ^ device();
    } catch (const std::exception&) {
      // No source of randomness: the time at least differs from run to run.
      return mixed(
          static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()));
    }
  }

  // The high and low halves of a * b, combined.
  static std::uint64_t fold(std::uint64_t a, std::uint64_t b) {
    __extension__ using Wide = unsigned __int128;
    const Wide product = Wide{a} * b;
    return static_cast<std::uint64_t>(product) ^ static_cast<std::uint64_t>(product >> 64);
  }
  // A seed's bits spread over a whole word, for the seeds derived from it.
  static std::uint64_t mixed(std::uint64_t value) {
    value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ull;
    value = (value ^ (value >> 27)) * 0x94d049bb133111ebull;
    return value ^ (value >> 31);
  }

  Seeds seeds_;
};

}  // namespace lcmtf::detail
