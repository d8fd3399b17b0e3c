// Who set each edge: the names kept for it, and clearing one sender's history.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "authority_table.hpp"
#include "lcmtf/buffer_core.hpp"
#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::put;
using ::testing::HasSubstr;
using ::testing::Not;

const Transform kStep(Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Quaterniond::Identity());

TEST(AuthorityTable, KeepsANameOnlyWhileAnEdgeUsesIt) {
  detail::AuthorityTable table;
  const std::uint32_t arm = table.idOf("arm");
  table.moveEdge(0, arm);
  const std::uint32_t base = table.idOf("base");
  table.moveEdge(0, base);
  EXPECT_EQ(table.size(), 2u);
  EXPECT_EQ(table.name(arm), "arm");
  table.moveEdge(base, arm);
  EXPECT_EQ(table.size(), 1u);
  EXPECT_EQ(table.find("base"), 0u);
  EXPECT_EQ(table.find("arm"), arm);
}

TEST(AuthorityTable, ANewNameOnEveryMessageKeepsOneNamePerEdge) {
  detail::AuthorityTable table;
  std::uint32_t edges[3] = {0, 0, 0};
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t id = table.idOf("forger-" + std::to_string(i));
    std::uint32_t& edge = edges[i % 3];
    table.moveEdge(edge, id);
    edge = id;
  }
  EXPECT_LE(table.size(), 3u);
  EXPECT_EQ(table.name(edges[0]), "forger-99999");
  EXPECT_EQ(table.find("forger-5"), 0u);
}

TEST(AuthorityTable, ANameAskedForButNeverUsedIsNotKept) {
  detail::AuthorityTable table;
  const std::uint32_t used = table.idOf("used");
  table.moveEdge(0, used);
  for (int i = 0; i < 1000; ++i) table.idOf("refused-" + std::to_string(i));
  EXPECT_LE(table.size(), 2u);
  EXPECT_EQ(table.name(used), "used");
}

TEST(BufferCoreAuthority, ClearAuthorityDropsOnlyTheHistoryThatSenderSetLast) {
  BufferCore buffer;
  put(buffer, "map", "odom", at(0), kStep, false, "localizer");
  put(buffer, "odom", "base", at(0), kStep, false, "driver");
  put(buffer, "odom", "base", at(1), kStep, false, "driver");
  put(buffer, "base", "arm", at(0), kStep, false, "driver");
  put(buffer, "base", "arm", at(1), kStep, false, "arm_controller");
  put(buffer, "base", "camera", at(0), kStep, true, "driver");

  EXPECT_EQ(buffer.clearAuthority("driver"), 1u);
  EXPECT_FALSE(buffer.canTransform("odom", "base", at(1)));
  EXPECT_TRUE(buffer.canTransform("map", "odom", at(0)));
  EXPECT_TRUE(buffer.canTransform("base", "arm", at(1)));
  EXPECT_TRUE(buffer.canTransform("base", "camera", at(5)));
  EXPECT_EQ(buffer.clearAuthority("nobody"), 0u);

  // The cleared edge takes new samples and is looked up as before.
  put(buffer, "odom", "base", at(7), kStep, false, "driver");
  EXPECT_TRUE(buffer.canTransform("odom", "camera", at(7)));
  EXPECT_FALSE(buffer.canTransform("map", "camera", at(7)));
}

TEST(BufferCoreAuthority, ClearAuthorityRepairsTheTreeOfAnEdgeThatChangedParent) {
  BufferCore buffer;
  put(buffer, "a", "x", at(0), kStep, false, "mover");
  put(buffer, "b", "x", at(1), kStep, false, "mover");
  put(buffer, "a", "y", at(0), kStep, false, "other");
  put(buffer, "a", "y", at(1), kStep, false, "other");
  EXPECT_EQ(buffer.clearAuthority("mover"), 1u);
  EXPECT_FALSE(buffer.canTransform("b", "x", at(1)));
  put(buffer, "a", "x", at(2), kStep, false, "mover");
  put(buffer, "a", "x", at(3), kStep, false, "mover");
  EXPECT_FALSE(buffer.canTransform("b", "x", at(2.5)));
  EXPECT_FALSE(buffer.canTransform("y", "x", at(0)));
  const TransformStamped x_in_a = buffer.lookupTransform("a", "x", at(2.5));
  EXPECT_NEAR(x_in_a.transform.translation.x(), 1.0, 1e-12);
}

TEST(BufferCoreAuthority, IntrospectionNamesTheSenderThatSetEachEdgeLast) {
  BufferCore buffer;
  for (int i = 0; i < 50; ++i) {
    put(buffer, "map", "odom", at(i * 0.01), kStep, false, "forger-" + std::to_string(i));
  }
  const std::string yaml = buffer.allFramesAsYaml();
  EXPECT_THAT(yaml, HasSubstr("forger-49"));
  EXPECT_THAT(yaml, Not(HasSubstr("forger-48")));
  EXPECT_EQ(buffer.clearAuthority("forger-48"), 0u);
  EXPECT_EQ(buffer.clearAuthority("forger-49"), 1u);
}

}  // namespace
}  // namespace lcmtf
