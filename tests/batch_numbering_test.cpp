#include "lcmtf/batch_numbering.hpp"

#include <gtest/gtest.h>

#include <optional>

namespace lcmtf {
namespace {

TEST(BatchNumbering, NumbersStartAtOneAndCountUp) {
  BatchNumbering numbering("NUMBERING_A", "counter");
  EXPECT_EQ(numbering.next(), 1);
  EXPECT_EQ(numbering.next(), 2);
  EXPECT_EQ(numbering.next(), 3);
}

TEST(BatchNumbering, OneChannelAndAuthorityShareOneCount) {
  BatchNumbering first("NUMBERING_B", "shared");
  BatchNumbering second("NUMBERING_B", "shared");
  EXPECT_EQ(first.next(), 1);
  EXPECT_EQ(second.next(), 2);
  EXPECT_EQ(first.next(), 3);
}

TEST(BatchNumbering, AnotherChannelOrAuthorityCountsApart) {
  BatchNumbering numbering("NUMBERING_C", "one");
  BatchNumbering other_channel("NUMBERING_D", "one");
  BatchNumbering other_authority("NUMBERING_C", "two");
  numbering.next();
  EXPECT_EQ(other_channel.next(), 1);
  EXPECT_EQ(other_authority.next(), 1);
}

TEST(BatchNumbering, CountStartsAgainOnceNoNumberingOfItIsLeft) {
  std::optional<BatchNumbering> numbering;
  numbering.emplace("NUMBERING_E", "restarted");
  numbering->next();
  numbering->next();
  numbering.emplace("NUMBERING_E", "restarted");
  EXPECT_EQ(numbering->next(), 1);
}

}  // namespace
}  // namespace lcmtf
