// Large arrays mapped on their own for huge pages, small ones from the heap.
#include "large_arrays.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "stable_vector.hpp"

namespace lcmtf::detail {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

bool alignedTo(const void* memory, std::size_t alignment) {
  return reinterpret_cast<std::uintptr_t>(memory) % alignment == 0;
}

TEST(LargeArrays, ArraysFromTwoMebibytesUpAreMappedOnHugePageBoundariesAndCounted) {
  const std::size_t before = mappedLargeArrayBytes();
  const std::size_t bytes = kHugePage + 12345;
  void* const memory = allocateLargeArray(bytes);
  ASSERT_NE(memory, nullptr);
  EXPECT_TRUE(alignedTo(memory, kHugePage));
  EXPECT_GE(mappedLargeArrayBytes() - before, bytes);
  EXPECT_LT(mappedLargeArrayBytes() - before, bytes + 4096);
  std::memset(memory, 0x5a, bytes);
  EXPECT_EQ(static_cast<unsigned char*>(memory)[bytes - 1], 0x5a);
  freeLargeArray(memory, bytes);
  EXPECT_EQ(mappedLargeArrayBytes(), before);
}

TEST(LargeArrays, SmallArraysComeFromTheHeapAlignedToACacheLine) {
  const std::size_t before = mappedLargeArrayBytes();
  void* const memory = allocateLargeArray(1000);
  EXPECT_TRUE(alignedTo(memory, 64));
  EXPECT_EQ(mappedLargeArrayBytes(), before);
  std::memset(memory, 1, 1000);
  freeLargeArray(memory, 1000);
  freeLargeArray(nullptr, kHugePage);
  EXPECT_EQ(mappedLargeArrayBytes(), before);
}

TEST(LargeArrays, AVectorGrowsFromTheHeapIntoMappedArraysKeepingItsElements) {
  const std::size_t before = mappedLargeArrayBytes();
  {
    std::vector<std::uint64_t, LargeArrayAllocator<std::uint64_t>> values;
    for (std::uint64_t i = 0; i < 1'000'000; ++i) values.push_back(i * 7);
    EXPECT_GE(mappedLargeArrayBytes() - before, values.size() * sizeof(std::uint64_t));
    for (std::uint64_t i = 0; i < values.size(); i += 9973) ASSERT_EQ(values[i], i * 7);
  }
  EXPECT_EQ(mappedLargeArrayBytes(), before);
}

TEST(LargeArrays, AStableVectorsElementsStayPutAsItsChunksGrowPastTwoMebibytes) {
  struct alignas(64) Record {
    std::uint64_t index;
    char payload[56];
  };
  const std::size_t before = mappedLargeArrayBytes();
  {
    StableVector<Record> records;
    std::vector<const Record*> placed;
    for (std::uint64_t i = 0; i < 200'000; ++i) {
      placed.push_back(&records.emplace_back(Record{i, {}}));
      ASSERT_TRUE(alignedTo(placed.back(), 64));
    }
    EXPECT_GT(mappedLargeArrayBytes(), before);
    // Every element, those on each side of every chunk's edge among them, is where it was put.
    for (std::uint64_t i = 0; i < records.size(); ++i) {
      ASSERT_EQ(&records[i], placed[i]) << i;
      ASSERT_EQ(records[i].index, i);
    }
  }
  EXPECT_EQ(mappedLargeArrayBytes(), before);
}

}  // namespace
}  // namespace lcmtf::detail
