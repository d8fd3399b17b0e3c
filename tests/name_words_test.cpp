#include "name_words.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lcmtf::detail {
namespace {

// A name of `size` bytes whose bytes all differ from their neighbours'.
std::string nameOfSize(std::size_t size) {
  std::string name(size, '\0');
  for (std::size_t i = 0; i < size; ++i) name[i] = static_cast<char>('a' + i % 26);
  return name;
}

TEST(SameName, EqualNamesOfEveryLengthAreTheSame) {
  for (std::size_t size = 0; size <= 72; ++size) {
    const std::string a = nameOfSize(size);
    const std::string b = a;  // other storage, same bytes
    EXPECT_TRUE(sameName(a, b)) << size << " bytes";
  }
}

TEST(SameName, NamesDifferingInAnyOneByteDiffer) {
  for (std::size_t size = 1; size <= 72; ++size) {
    const std::string a = nameOfSize(size);
    for (std::size_t at = 0; at < size; ++at) {
      for (const int flip : {0x01, 0x80, 0xff}) {
        std::string b = a;
        b[at] = static_cast<char>(static_cast<unsigned char>(b[at]) ^ flip);
        EXPECT_FALSE(sameName(a, b)) << size << " bytes, byte " << at << " flipped by " << flip;
      }
    }
  }
}

TEST(SameName, APrefixIsNotTheName) {
  const std::string name = nameOfSize(40);
  for (std::size_t size = 0; size < name.size(); ++size) {
    EXPECT_FALSE(sameName(std::string_view(name).substr(0, size), name)) << size;
  }
}

TEST(SameName, BytesOutsideTheViewsAreNotCompared) {
  const std::string a = "base_link/extra";
  const std::string b = "base_link|other";
  EXPECT_TRUE(sameName(std::string_view(a).substr(0, 9), std::string_view(b).substr(0, 9)));
  EXPECT_TRUE(sameName(std::string_view(a).substr(0, 2), std::string_view(b).substr(0, 2)));
}

}  // namespace
}  // namespace lcmtf::detail
