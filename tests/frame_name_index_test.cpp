#include "frame_name_index.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace lcmtf::detail {
namespace {

// Names of every length from one byte to well past the longest fixed-size case, with bytes of
// every value, each stored under its own id. (Frame names are never empty.)
class NameIndex : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937_64 random(11);
    std::uniform_int_distribution<int> byte(0, 255);
    for (std::size_t size = 1; size <= 80; ++size) {
      for (int copy = 0; copy < 3; ++copy) {
        std::string name(size, '\0');
        for (char& c : name) c = static_cast<char>(byte(random));
        names.push_back(name);
        index.insert(names.back(), static_cast<FrameId>(names.size()));
      }
    }
  }

  std::deque<std::string> names;  // stable storage, as the index requires
  FrameNameIndex index;
};

TEST_F(NameIndex, EveryNameIsFoundUnderItsId) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(index.find(std::string(names[i])), static_cast<FrameId>(i + 1))
        << "name of " << names[i].size() << " bytes";
  }
}

TEST_F(NameIndex, NameDifferingInAnyOneByteIsNotFound) {
  for (const std::string& name : names) {
    for (std::size_t at = 0; at < name.size(); ++at) {
      std::string other = name;
      other[at] = static_cast<char>(other[at] ^ 0x20);
      EXPECT_EQ(index.find(other), kNoFrame) << "byte " << at << " of " << name.size();
    }
  }
}

TEST_F(NameIndex, PrefixesAndExtensionsOfANameAreNotFound) {
  for (const std::string& name : names) {
    if (name.size() > 1) {
      EXPECT_EQ(index.find(std::string_view(name).substr(0, name.size() - 1)), kNoFrame);
    }
    EXPECT_EQ(index.find(name + "x"), kNoFrame);
  }
}

TEST_F(NameIndex, EveryIdGivesBackItsName) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string_view name = index.nameOf(static_cast<FrameId>(i + 1));
    EXPECT_EQ(name, names[i]);
    EXPECT_EQ(name.data(), names[i].data()) << "the stored name itself, not a copy";
  }
}

TEST(NameIndexEmpty, FindsNothing) { EXPECT_EQ(FrameNameIndex().find("map"), kNoFrame); }

TEST(NameIndexEmpty, NoFrameHasAnEmptyName) {
  EXPECT_TRUE(FrameNameIndex().nameOf(kNoFrame).empty());
}

TEST(NameIndexGaps, AnIdSkippedBelowAnotherHasAnEmptyName) {
  FrameNameIndex index;
  index.insert("odom", 3);
  EXPECT_TRUE(index.nameOf(2).empty());
  EXPECT_EQ(index.nameOf(3), "odom");
}

// Names worked out to land on one slot of an index (here, of one with 65,536 slots, as 10,000
// frames take) land on many slots of another: a peer cannot craft names that crowd every index.
TEST(NameIndexSeeds, NamesThatShareASlotInOneIndexSpreadInAnother) {
  constexpr std::uint64_t kMask = 0xffff;
  const FrameNameIndex crafted_against;
  std::vector<std::string> crowd;
  for (int i = 0; crowd.size() < 12; ++i) {
    std::string name = "frame_" + std::to_string(i);
    if ((crafted_against.hashOf(name) & kMask) == 0x1234) crowd.push_back(std::move(name));
  }
  const FrameNameIndex other;
  std::set<std::uint64_t> slots;
  for (const std::string& name : crowd) slots.insert(other.hashOf(name) & kMask);
  EXPECT_GE(slots.size(), 10u);
}

}  // namespace
}  // namespace lcmtf::detail
