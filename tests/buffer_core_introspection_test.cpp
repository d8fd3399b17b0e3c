// BufferCore introspection: frame names, parents, frame chains, the YAML and DOT dumps.
#include "lcmtf/buffer_core.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/buffer_core_helpers.hpp"

namespace lcmtf {
namespace {

using lcmtf_test::at;
using lcmtf_test::pose;
using lcmtf_test::put;
using lcmtf_test::putStatic;
using lcmtf_test::stamped;
using ::testing::ElementsAre;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using ::testing::UnorderedElementsAre;

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// world -> base: 10 samples at 100 Hz from t = 1 by "driver"; base -> laser static by "calib".
class BufferCoreIntrospection : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i < 10; ++i) {
      put(buffer_, "world", "base", at(1) + std::chrono::milliseconds(10 * i),
          pose({0.01 * i, 0, 0}, 0, kZ), false, "driver");
    }
    putStatic(buffer_, "base", "laser", pose({0.2, 0, 0.1}, 0, kZ), "calib");
  }
  BufferCore buffer_;
};

TEST_F(BufferCoreIntrospection, DescribeEdgesGivesEachEdgesParentSenderRateAndHistory) {
  buffer_.resolveFrame("lonely");  // a frame with no parent is no edge
  const std::vector<EdgeDescription> edges = buffer_.describeEdges();
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges[0].child, "base");
  EXPECT_EQ(edges[0].parent, "world");
  EXPECT_EQ(edges[0].authority, "driver");
  EXPECT_FALSE(edges[0].is_static);
  EXPECT_EQ(edges[0].samples, 10u);
  EXPECT_NEAR(edges[0].rate_hz, 100.0, 1e-9);
  EXPECT_EQ(edges[0].oldest, at(1));
  EXPECT_EQ(edges[0].newest, at(1) + std::chrono::milliseconds(90));
  EXPECT_EQ(edges[1].child, "laser");
  EXPECT_EQ(edges[1].parent, "base");
  EXPECT_EQ(edges[1].authority, "calib");
  EXPECT_TRUE(edges[1].is_static);
  EXPECT_EQ(edges[1].rate_hz, 0.0);
  EXPECT_EQ(edges[1].newest, TimePoint());
  EXPECT_EQ(edges[0].authority_conflicts, 0u);
  put(buffer_, "world", "base", at(1.5), pose({0, 0, 0}, 0, kZ), false, "other_driver");
  const EdgeDescription taken_over = buffer_.describeEdges()[0];
  EXPECT_EQ(taken_over.authority, "other_driver");
  EXPECT_EQ(taken_over.authority_conflicts, 1u);
}

TEST_F(BufferCoreIntrospection, AllFrameNamesListsEveryFrameOnceInOrderOfAppearance) {
  put(buffer_, "laser", "spot", at(1), pose({1, 0, 0}, 0, kZ));
  put(buffer_, "world", "base", at(2), pose({0, 0, 0}, 0, kZ));
  buffer_.resolveFrame("/extra");
  buffer_.setErrorReporter(nullptr);
  buffer_.setTransform(
      stamped("nowhere", "base", at(2),
              Transform(Eigen::Vector3d(std::nan(""), 0, 0), Eigen::Quaterniond::Identity())),
      "test");
  const std::vector<std::string> names = buffer_.getAllFrameNames();
  ASSERT_EQ(names.size(), 5u);
  // world and base arrived in the same transform.
  EXPECT_THAT(std::vector<std::string>(names.begin(), names.begin() + 2),
              UnorderedElementsAre("world", "base"));
  EXPECT_THAT(std::vector<std::string>(names.begin() + 2, names.end()),
              ElementsAre("laser", "spot", "extra"));
}

TEST_F(BufferCoreIntrospection, FrameNamesStayAfterClear) {
  const std::vector<std::string> before = buffer_.getAllFrameNames();
  buffer_.clear();
  EXPECT_EQ(buffer_.getAllFrameNames(), before);
  EXPECT_TRUE(buffer_.frameExists("base"));
}

TEST_F(BufferCoreIntrospection, GetParentGivesTheParentWhereTheEdgeHasData) {
  std::string parent;
  ASSERT_TRUE(buffer_.getParent("base", at(1.05), parent));
  EXPECT_EQ(parent, "world");
  ASSERT_TRUE(buffer_.getParent("/laser", at(1e6), parent));
  EXPECT_EQ(parent, "base");
  parent = "unchanged";
  EXPECT_FALSE(buffer_.getParent("world", at(1.05), parent));  // a root
  EXPECT_FALSE(buffer_.getParent("ghost", at(1.05), parent));
  EXPECT_FALSE(buffer_.getParent("base", at(5), parent));  // after its data
  EXPECT_EQ(parent, "unchanged");
  ASSERT_TRUE(buffer_.getParent("base", kLatestTime, parent));
  EXPECT_EQ(parent, "world");
}

TEST(BufferCoreFrameChain, ChainGoesFromSourceUpToTheCommonAncestorAndDownToTarget) {
  BufferCore buffer;
  putStatic(buffer, "world", "base", pose({0, 0, 0}, 0, kZ));
  putStatic(buffer, "base", "left_arm", pose({0, 1, 0}, 0, kZ));
  putStatic(buffer, "left_arm", "left_hand", pose({1, 0, 0}, 0, kZ));
  putStatic(buffer, "base", "right_arm", pose({0, -1, 0}, 0, kZ));
  putStatic(buffer, "right_arm", "right_hand", pose({1, 0, 0}, 0, kZ));
  EXPECT_THAT(buffer.getFrameChain("right_hand", "left_hand"),
              ElementsAre("left_hand", "left_arm", "base", "right_arm", "right_hand"));
  EXPECT_THAT(buffer.getFrameChain("left_hand", "right_hand", at(3)),
              ElementsAre("right_hand", "right_arm", "base", "left_arm", "left_hand"));
  EXPECT_THAT(buffer.getFrameChain("world", "left_hand"),
              ElementsAre("left_hand", "left_arm", "base", "world"));
  EXPECT_THAT(buffer.getFrameChain("left_hand", "world"),
              ElementsAre("world", "base", "left_arm", "left_hand"));
  EXPECT_THAT(buffer.getFrameChain("left_arm", "left_hand"), ElementsAre("left_hand", "left_arm"));
  EXPECT_THAT(buffer.getFrameChain("base", "base"), ElementsAre("base"));
}

TEST(BufferCoreFrameChain, ChainFollowsTheParentsAtTheRequestedTime) {
  BufferCore buffer;
  putStatic(buffer, "world", "table", pose({1, 0, 0}, 0, kZ));
  put(buffer, "world", "gripper", at(1), pose({0, 0, 1}, 0, kZ));
  put(buffer, "world", "gripper", at(3), pose({0, 0, 1}, 0, kZ));
  put(buffer, "table", "cup", at(1), pose({0, 0, 0}, 0, kZ));
  put(buffer, "gripper", "cup", at(2), pose({0, 0, 0}, 0, kZ));
  put(buffer, "gripper", "cup", at(3), pose({0, 0, 0}, 0, kZ));
  EXPECT_THAT(buffer.getFrameChain("world", "cup", at(1.5)), ElementsAre("cup", "table", "world"));
  EXPECT_THAT(buffer.getFrameChain("world", "cup", at(2.5)),
              ElementsAre("cup", "gripper", "world"));
  EXPECT_THAT(buffer.getFrameChain("world", "cup"), ElementsAre("cup", "gripper", "world"));
}

TEST_F(BufferCoreIntrospection, YamlDumpDescribesEveryEdge) {
  const std::string yaml = buffer_.allFramesAsYaml();
  EXPECT_THAT(yaml, HasSubstr("'base':\n"
                              "  parent: 'world'\n"
                              "  authority: 'driver'\n"
                              "  static: false\n"
                              "  rate: 100.000\n"
                              "  samples: 10\n"
                              "  most_recent_transform: 1700000001.090000\n"
                              "  oldest_transform: 1700000001.000000\n"
                              "  buffer_length: 0.090000\n"
                              "  authority_conflicts: 0\n"));
  EXPECT_THAT(yaml, HasSubstr("'laser':\n"
                              "  parent: 'base'\n"
                              "  authority: 'calib'\n"
                              "  static: true\n"
                              "  rate: 0.000\n"
                              "  samples: 1\n"));
  EXPECT_THAT(yaml, Not(HasSubstr("'world':")));  // a root has no edge to describe
}

TEST_F(BufferCoreIntrospection, YamlDumpQuotesNamesWithQuotes) {
  put(buffer_, "base", "it's", at(1), pose({0, 0, 0}, 0, kZ), false, "o'neil");
  const std::string yaml = buffer_.allFramesAsYaml();
  EXPECT_THAT(yaml, HasSubstr("'it''s':\n  parent: 'base'\n  authority: 'o''neil'\n"));
}

TEST_F(BufferCoreIntrospection, YamlDumpDropsClearedHistory) {
  buffer_.clear();
  const std::string yaml = buffer_.allFramesAsYaml();
  EXPECT_THAT(yaml, Not(HasSubstr("'base':")));
  EXPECT_THAT(yaml, HasSubstr("'laser':\n  parent: 'base'\n"));
}

TEST_F(BufferCoreIntrospection, DotDumpDrawsEveryFrameAndEdge) {
  buffer_.resolveFrame("lonely");
  const std::string dot = buffer_.allFramesAsDot();
  EXPECT_THAT(dot, StartsWith("digraph lcmtf {\n"));
  EXPECT_THAT(dot, EndsWith("}\n"));
  for (const char* frame : {"world", "base", "laser", "lonely"}) {
    EXPECT_THAT(dot, HasSubstr("  \"" + std::string(frame) + "\";\n")) << frame;
  }
  EXPECT_THAT(dot, HasSubstr("  \"world\" -> \"base\" [label=\"Broadcaster: driver\\n"
                             "Average rate: 100.000 Hz\\n"
                             "Most recent transform: 1700000001.090000\\n"
                             "Buffer length: 0.090 s\"];\n"));
  EXPECT_THAT(dot, HasSubstr("  \"base\" -> \"laser\" [label=\"Broadcaster: calib\\nstatic\", "
                             "style=dashed];\n"));
  EXPECT_THAT(dot, Not(HasSubstr("-> \"lonely\"")));
  EXPECT_THAT(dot, Not(HasSubstr("-> \"world\"")));
  EXPECT_EQ(std::count(dot.begin(), dot.end(), '{'), std::count(dot.begin(), dot.end(), '}'));
}

TEST_F(BufferCoreIntrospection, DotDumpEscapesQuotesInNames) {
  put(buffer_, "base", "say \"hi\"", at(1), pose({0, 0, 0}, 0, kZ), false, "a \"b\"");
  const std::string dot = buffer_.allFramesAsDot();
  EXPECT_THAT(dot, HasSubstr("  \"base\" -> \"say \\\"hi\\\"\" [label=\"Broadcaster: a \\\"b\\\""));
}

TEST_F(BufferCoreIntrospection, DotDumpEscapesBackslashesInAuthorities) {
  // Unescaped, Graphviz would read "\l" as a left-justified line break.
  put(buffer_, "base", "arm", at(1), pose({0, 0, 0}, 0, kZ), false, "lab\\lab");
  const std::string dot = buffer_.allFramesAsDot();
  EXPECT_THAT(dot, HasSubstr("[label=\"Broadcaster: lab\\\\lab\\n"));
}

}  // namespace
}  // namespace lcmtf
