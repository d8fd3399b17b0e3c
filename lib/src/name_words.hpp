#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

namespace lcmtf::detail {

/// The bytes of a name read a word at a time, inline: names are short, and a call to memcmp or
/// a loop over bytes costs more than the few words most names take.

/// Eight bytes at `bytes` as one word.
inline std::uint64_t nameWord(const char* bytes) {
  std::uint64_t value;
  std::memcpy(&value, bytes, 8);
  return value;
}

/// Up to 8 bytes as one word, from at most two overlapping reads, without a call to memcpy.
inline std::uint64_t shortNameWord(const char* bytes, std::size_t size) {
  if (size >= 4) {
    std::uint32_t low;
    std::uint32_t high;
    std::memcpy(&low, bytes, 4);
    std::memcpy(&high, bytes + size - 4, 4);
    return (std::uint64_t{high} << 32) | low;
  }
  if (size == 0) return 0;
  const auto byte = [&](std::size_t i) {
    return std::uint64_t{static_cast<unsigned char>(bytes[i])};
  };
  return byte(0) | byte(size / 2) << 8 | byte(size - 1) << 16;
}

/// Equality of two names of equal size.
inline bool sameNameBytes(const char* a, const char* b, std::size_t size) {
  if (size <= 8) return shortNameWord(a, size) == shortNameWord(b, size);
  std::uint64_t differ =
      (nameWord(a) ^ nameWord(b)) | (nameWord(a + size - 8) ^ nameWord(b + size - 8));
  if (size <= 16) return differ == 0;
  if (size <= 32) {
    differ |=
        (nameWord(a + 8) ^ nameWord(b + 8)) | (nameWord(a + size - 16) ^ nameWord(b + size - 16));
    return differ == 0;
  }
  for (std::size_t offset = 8; offset + 8 < size; offset += 8) {
    differ |= nameWord(a + offset) ^ nameWord(b + offset);
  }
  return differ == 0;
}

/// Equality of two names, as lookups and inserts compare them.
inline bool sameName(std::string_view a, std::string_view b) {
  return a.size() == b.size() && sameNameBytes(a.data(), b.data(), a.size());
}

}  // namespace lcmtf::detail
