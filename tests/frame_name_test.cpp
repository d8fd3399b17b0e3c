#include "lcmtf/frame_name.hpp"

#include <gtest/gtest.h>

namespace lcmtf {
namespace {

TEST(CanonicalFrameName, OneLeadingSlashIsNotPartOfTheName) {
  EXPECT_EQ(canonicalFrameName("/base_link"), "base_link");
  EXPECT_EQ(canonicalFrameName("base_link"), "base_link");
  EXPECT_EQ(canonicalFrameName("//odd"), "/odd");
  EXPECT_EQ(canonicalFrameName("/"), "");
  EXPECT_EQ(canonicalFrameName(""), "");
  EXPECT_EQ(canonicalFrameName("robot1/base"), "robot1/base");
}

}  // namespace
}  // namespace lcmtf
