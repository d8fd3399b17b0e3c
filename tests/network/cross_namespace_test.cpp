// Broadcasters and a listener as on two machines: each in a network namespace of its own, over
// real interfaces (veth pairs) with ttl=1, and a relay in a third namespace between them that
// drops and reorders datagrams both ways. Skipped where namespaces cannot be made.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer.hpp"
#include "lcmtf/transform_listener.hpp"
#include "network/in_namespace.hpp"
#include "network/namespace_chain.hpp"
#include "network/relay_report.hpp"
#include "support/buffer_core_helpers.hpp"
#include "support/transport_motion.hpp"

namespace lcmtf {
namespace {

using namespace std::chrono_literals;
using lcmtf_test::ChildProcess;
using lcmtf_test::NamespaceChain;
using lcmtf_test::near;
using lcmtf_test::odomTBase;
using lcmtf_test::RelayCounts;

// The namespaces are this test's own, so LCM's default port meets no other test's traffic.
constexpr const char* kGroup = "239.255.76.67";
constexpr const char* kPort = "7667";
const std::string kUrl = std::string("udpm://") + kGroup + ":" + kPort + "?ttl=1";
constexpr unsigned kRelaySeed = 1515;
// Lerp and slerp of the peer's motion are exact, also across a lost sample.
constexpr double kExact = 1e-9;

// A directory of the relay's own, where it writes its report (and the drafts of it).
std::filesystem::path makeReportDirectory() {
  std::string pattern = (std::filesystem::temp_directory_path() / "lcmtf_relay_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

// The lossy relay in the chain's middle namespace, and what it reports.
class Relay {
 public:
  explicit Relay(const NamespaceChain& chain)
      : directory_(makeReportDirectory()),
        report_(directory_ / "report.txt"),
        process_(chain.start(
            chain.relay(), LOSSY_RELAY,
            {kGroup, kPort, NamespaceChain::kRelayToSender, NamespaceChain::kRelayToReceiver,
             std::to_string(kRelaySeed), report_.string(), "60000"})) {}
  ~Relay() {
    process_->kill();
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  Relay(const Relay&) = delete;
  Relay& operator=(const Relay&) = delete;

  // Whether it is listening within `timeout`: it writes its first report once it is.
  bool listensWithin(std::chrono::milliseconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!std::filesystem::exists(report_)) {
      if (std::chrono::steady_clock::now() >= deadline || process_->waitForExit(0ms)) return false;
      std::this_thread::sleep_for(10ms);
    }
    return true;
  }

  // Stops it and reads its last report: the datagrams from the sender's side, then the others.
  std::vector<RelayCounts> finalCounts() {
    process_->kill();
    std::ifstream file(report_);
    return lcmtf_test::parseRelayReport(
        std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()));
  }

 private:
  std::filesystem::path directory_;
  std::filesystem::path report_;
  std::unique_ptr<ChildProcess> process_;
};

std::string describe(const std::vector<RelayCounts>& report) {
  std::ostringstream text;
  for (const RelayCounts& counts : report) {
    text << "from " << counts.arrived_on << ": " << counts.received << " received, "
         << counts.dropped << " dropped, " << counts.reordered << " reordered; ";
  }
  return text.str();
}

class CrossNamespace : public testing::Test {
 protected:
  void SetUp() override {
    try {
      chain_ = std::make_unique<NamespaceChain>();
    } catch (const lcmtf_test::NamespacesUnavailable& e) {
      GTEST_SKIP() << "network namespaces cannot be made here: " << e.what();
    }
    relay_ = std::make_unique<Relay>(*chain_);
    ASSERT_TRUE(relay_->listensWithin(10s)) << "the relay did not start";
  }

  // A TransformListener whose LCM lives in the receiver's namespace.
  std::unique_ptr<TransformListener> listenInReceiver(Buffer& buffer) {
    ListenerOptions options;
    options.lcm_url = kUrl;
    std::unique_ptr<TransformListener> listener;
    lcmtf_test::runInNamespace(chain_->receiver(), [&] {
      listener = std::make_unique<TransformListener>(buffer, options);
    });
    return listener;
  }

  // Requests and answers cross the relay and may be lost: asks again until the tree is there.
  static bool staticTreeArrives(Buffer& buffer, TransformListener& listener,
                                std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!buffer.canTransform("camera_optical", "lidar", kLatestTime, 250ms)) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      listener.requestStatics();
    }
    return true;
  }

  void report(const std::vector<RelayCounts>& counts) {
    std::cout << "[ measured ] relay " << describe(counts) << '\n';
    RecordProperty("relay", describe(counts));
  }

  std::unique_ptr<NamespaceChain> chain_;
  std::unique_ptr<Relay> relay_;
};

TEST_F(CrossNamespace, LateJoinerGetsTheStaticTreeByAskingAcrossALossyLink) {
  // Hear the broadcaster's one publication at start beside it, so the listener below joins after
  // it for sure; with resending off, only an answer to a request across the relay can reach it.
  std::unique_ptr<ChildProcess> statics;
  int heard = 0;
  lcmtf_test::runInNamespace(chain_->sender(), [&] {
    lcm::LCM probe(kUrl);
    if (!probe.good())
      throw std::runtime_error("cannot open LCM at " + kUrl + " beside the sender");
    probe.subscribeFunction(
        kTfStaticChannel,
        +[](const lcm::ReceiveBuffer*, const std::string&, int* count) { ++*count; }, &heard);
    statics = chain_->start(chain_->sender(), TRANSPORT_PEER, {"static", kUrl, "--no-resend"});
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (heard == 0 && std::chrono::steady_clock::now() < deadline) probe.handleTimeout(20);
  });
  ASSERT_GT(heard, 0) << "the static peer never published in its namespace";
  std::this_thread::sleep_for(300ms);  // longer than the relay holds anything back

  Buffer buffer;
  const std::unique_ptr<TransformListener> listener = listenInReceiver(buffer);
  ASSERT_TRUE(staticTreeArrives(buffer, *listener, 10s)) << "no static tree across the relay";
  for (const TransformStamped& edge : lcmtf_test::peerStatics()) {
    const TransformStamped got =
        buffer.lookupTransform(edge.parent_frame, edge.child_frame, kLatestTime);
    EXPECT_EQ(got.stamp, kLatestTime);
    EXPECT_TRUE(near(got.transform, edge.transform, 1e-12)) << edge.child_frame;
  }
  report(relay_->finalCounts());
}

TEST_F(CrossNamespace, LookupsEqualTheBroadcastMotionDespiteLossAndReordering) {
  const TimePoint origin = now();
  auto dynamic =
      chain_->start(chain_->sender(), TRANSPORT_PEER,
                    {"dynamic", kUrl, "100", "20000", std::to_string(toUtime(origin)), "1.0"});
  auto statics = chain_->start(chain_->sender(), TRANSPORT_PEER, {"static", kUrl});
  Buffer buffer;
  const std::unique_ptr<TransformListener> listener = listenInReceiver(buffer);

  std::string why;
  ASSERT_TRUE(buffer.canTransform("odom", "base", kLatestTime, 10s, &why)) << why;
  ASSERT_TRUE(staticTreeArrives(buffer, *listener, 10s)) << "no static tree across the relay";
  const TimePoint first = buffer.getLatestCommonTime("odom", "base");
  // 1.5 s of 100 Hz: holes and late arrivals are all but certain among them.
  ASSERT_TRUE(buffer.canTransform("odom", "camera_optical", first + 1500ms, 10s, &why)) << why;

  const std::vector<TransformStamped> tree = lcmtf_test::peerStatics();  // base, camera, optical
  const std::map<std::string, Transform> base_T = {
      {"base", Transform::identity()},
      {"camera", tree[0].transform},
      {"camera_optical", tree[0].transform * tree[1].transform},
      {"lidar", tree[2].transform}};
  // 10.007 ms apart: between the 100 Hz samples, seldom on one.
  for (TimePoint t = first; t < first + 1500ms; t += Duration(10'007)) {
    const Transform odom_T_base = odomTBase(t, origin, 1.0);
    for (const auto& [frame, base_T_frame] : base_T) {
      const TransformStamped got = buffer.lookupTransform("odom", frame, t);
      EXPECT_EQ(got.stamp, t);
      EXPECT_TRUE(near(got.transform, odom_T_base * base_T_frame, kExact))
          << "odom -> " << frame << " at " << toString(t);
    }
  }
  const ListenerStatistics stats = listener->statistics();
  EXPECT_EQ(stats.malformed, 0u);
  EXPECT_EQ(stats.rejected_transforms, 0u);
  EXPECT_EQ(stats.stale_batches, 0u);

  const std::vector<RelayCounts> counts = relay_->finalCounts();
  report(counts);
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_GT(counts[0].dropped, 0u) << "nothing was lost on the way";
  EXPECT_GT(counts[0].reordered, 0u) << "nothing arrived out of order";
}

}  // namespace
}  // namespace lcmtf
