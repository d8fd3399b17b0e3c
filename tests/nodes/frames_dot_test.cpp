// The DOT drawing of the frame tree, and Graphviz rendering it when it is installed.
#include "lcmtf/nodes/frames_dot.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lcmtf/nodes/graphviz.hpp"
#include "support/child_process.hpp"
#include "support/wire_samples.hpp"

namespace lcmtf::nodes {
namespace {

using std::chrono::milliseconds;
using testing::HasSubstr;
using testing::Not;

constexpr TimePoint kStart = lcmtf_test::kToolsEpoch;

EdgeTraffic dynamicEdge(const std::string& parent, const std::string& child,
                        std::vector<std::string> authorities) {
  EdgeTraffic edge;
  edge.parent = parent;
  edge.child = child;
  edge.authorities = std::move(authorities);
  edge.samples = 250;
  edge.rate_hz = 50.0;
  edge.oldest_stamp = kStart;
  edge.newest_stamp = kStart + milliseconds(4980);
  edge.buffered = 250;
  return edge;
}

TrafficSummary summaryOf(std::vector<EdgeTraffic> edges) {
  TrafficSummary summary;
  summary.window_start = kStart;
  summary.window_end = kStart + std::chrono::seconds(5);
  summary.edges = std::move(edges);
  return summary;
}

TEST(FramesDot, EachEdgeIsLabelledWithBroadcasterRateNewestStampAndBuffer) {
  const std::string dot =
      framesToDot(summaryOf({dynamicEdge("odom", "base", {"driver@robot:12"})}), "caption");
  EXPECT_THAT(dot, HasSubstr("digraph lcmtf_frames {"));
  EXPECT_THAT(dot, HasSubstr("  \"base\" [label=\"base\"];\n  \"odom\" [label=\"odom\"];\n"));
  EXPECT_THAT(dot, HasSubstr("  \"odom\" -> \"base\" [label=\"broadcaster: driver@robot:12\\n"
                             "average rate: 50.00 Hz\\n"
                             "most recent: 1700000004.980000 (0.020 s old)\\n"
                             "buffer: 4.980 s (250 samples)\"];\n"));
  EXPECT_THAT(dot, HasSubstr("label=\"caption\""));
}

TEST(FramesDot, AnEdgeHeardOnceHasNoRate) {
  EdgeTraffic once = dynamicEdge("odom", "base", {"driver"});
  once.samples = 1;
  once.rate_hz = 0.0;
  EXPECT_THAT(framesToDot(summaryOf({once}), ""), HasSubstr("\\naverage rate: - (heard once)\\n"));
}

TEST(FramesDot, StaticEdgesAreDashedAndSaySo) {
  EdgeTraffic camera;
  camera.parent = "base";
  camera.child = "camera";
  camera.is_static = true;
  camera.authorities = {"mounts"};
  camera.samples = 5;
  camera.rate_hz = 1.0;
  camera.last_received = kStart + std::chrono::milliseconds(4250);
  const std::string dot = framesToDot(summaryOf({camera}), "");
  EXPECT_THAT(dot, HasSubstr("\"base\" -> \"camera\" [label=\"static\\nbroadcaster: mounts\\n"
                             "resent: 1.00 Hz (heard 5 times)\\n"
                             "most recent: 1700000004.250000 (0.750 s old)\\n"
                             "buffer: one value, valid at every time\", style=dashed];"));
  camera.samples = 1;
  EXPECT_THAT(framesToDot(summaryOf({camera}), ""), HasSubstr("resent: - (heard once)\\n"));
}

TEST(FramesDot, AFrameFromTwoBroadcastersIsRed) {
  TrafficSummary summary = summaryOf({dynamicEdge("map", "base", {"localizer", "odometry"})});
  summary.conflicts.push_back({"base", {"'localizer' ...", "'odometry' ..."}});
  const std::string dot = framesToDot(summary, "");
  EXPECT_THAT(dot, HasSubstr("\"base\" [label=\"base\", color=red, fontcolor=red];"));
  EXPECT_THAT(dot, HasSubstr("broadcasters: localizer, odometry\\nCONFLICT: more than one "
                             "broadcaster\\n"));
  EXPECT_THAT(dot, HasSubstr("(250 samples)\", color=red, fontcolor=red];"));
  EXPECT_THAT(dot, Not(HasSubstr("\"map\" [label=\"map\", color=red")));
}

TEST(FramesDot, FramesThatDifferOnlyInUnshowableBytesStayApart) {
  const std::string dot = framesToDot(
      summaryOf({dynamicEdge("base", "cam?", {"a"}), dynamicEdge("base", "cam\x01", {"b"}),
                 dynamicEdge("base", "cam\xff", {"c"})}),
      "");
  EXPECT_THAT(dot, HasSubstr("  \"cam?\" [label=\"cam?\"];\n"));
  EXPECT_THAT(dot, HasSubstr("  \"cam\\\\x01\" [label=\"cam?\"];\n"));
  EXPECT_THAT(dot, HasSubstr("  \"cam\\\\xff\" [label=\"cam?\"];\n"));
  EXPECT_THAT(dot, HasSubstr("  \"base\" -> \"cam\\\\x01\" [label=\"broadcaster: b\\n"));
}

TEST(FramesDot, GraphvizDrawsHostileNamesWhenInstalled) {
  const std::optional<std::string> dot = findOnPath("dot");
  if (!dot) GTEST_SKIP() << "Graphviz's dot is not installed";
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("frames-dot");
  const std::string gv = (directory / "frames.gv").string();
  std::ofstream(gv) << framesToDot(
      summaryOf({dynamicEdge("world\"}; digraph x {", "a\\Nb\n<c>", {"evil\"]"}),
                 dynamicEdge("caf\xc3\xa9", "\xff\xfe", {"latin"})}),
      "}");
  const std::string svg = (directory / "frames.svg").string();
  EXPECT_EQ(renderDot(*dot, gv, "svg", svg), "");
  const std::string drawing = lcmtf_test::readWholeFile(svg);
  EXPECT_THAT(drawing, HasSubstr("world&quot;}; digraph x {"));
  EXPECT_THAT(drawing, HasSubstr("a\\Nb"));
  EXPECT_THAT(drawing, HasSubstr("&lt;c&gt;"));
  const std::string pdf = (directory / "frames.pdf").string();
  EXPECT_EQ(renderDot(*dot, gv, "pdf", pdf), "");
  EXPECT_EQ(lcmtf_test::readWholeFile(pdf).substr(0, 5), "%PDF-");
  EXPECT_GT(std::filesystem::file_size(pdf), 1000u);
  std::filesystem::remove_all(directory);
}

TEST(Graphviz, FailureIsDescribedNotHidden) {
  const std::optional<std::string> dot = findOnPath("dot");
  if (!dot) GTEST_SKIP() << "Graphviz's dot is not installed";
  const std::filesystem::path directory = lcmtf_test::makeTemporaryDirectory("frames-dot");
  const std::string broken = (directory / "broken.gv").string();
  std::ofstream(broken) << "digraph { a -> }";
  EXPECT_THAT(renderDot(*dot, broken, "pdf", (directory / "out.pdf").string()),
              HasSubstr("failed (exit status 1) writing"));
  EXPECT_THAT(renderDot((directory / "no-such-dot").string(), broken, "pdf", "x.pdf"),
              HasSubstr("cannot run"));
  std::filesystem::remove_all(directory);
}

TEST(Graphviz, FindOnPathLooksOnlyAtExecutables) {
  const std::optional<std::string> sh = findOnPath("sh");
  ASSERT_TRUE(sh);
  EXPECT_TRUE(std::filesystem::exists(*sh));
  EXPECT_FALSE(findOnPath("surely-no-such-program-here"));
}

}  // namespace
}  // namespace lcmtf::nodes
