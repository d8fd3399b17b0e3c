// What the URDF publisher costs and how long its transforms take to reach a listener.
//
//   urdf_publisher_bench [--skip-e2e] [--seconds S] [--fill-seconds S] [--rate HZ]
//                        [--port P] [Google Benchmark flags]
//
// 1. Joint states handled per second, excluding LCM, for the Unitree G1 (29 movable joints,
//    from ../shared/urdf) and a PR2-scale robot (79 links, generated): from a decoded
//    joint_state_t to its transform batch, and from its bytes to the batch's bytes.
// 2. End to end over udpm on this host: this program publishes joint states of the G1, the
//    real lcmtf-urdf-publisher turns them into transforms, and a TransformListener here
//    reports the moment the root-to-deepest-link lookup at the state's stamp succeeds; next to
//    two raw LCM hops of the same joint states through a relay process, the two paths taking
//    turns (--rate joint states per second each, default 500, the G1's own rate).
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "bench_summary.hpp"
#include "lcmtf/programs/stop_signal.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf_urdf/joint_state_generator.hpp"
#include "lcmtf_urdf/joint_state_processor.hpp"
#include "pr2_scale_urdf.hpp"

extern char** environ;

namespace bench {
namespace {

using Clock = std::chrono::steady_clock;
using lcmtf::urdf::RobotModel;

constexpr double kTargetMessagesPerSecond = 100e3;
constexpr double kTargetRatio = 3.0;
constexpr const char* kRawIn = "JOINT_STATES_RAW_HOP_1";
constexpr const char* kRawOut = "JOINT_STATES_RAW_HOP_2";
constexpr int kDistinctStates = 1024;

struct Options {
  bool e2e = true;
  double seconds = 5.0;
  double fill_seconds =
      std::chrono::duration<double>(lcmtf::BufferCore::kDefaultCacheTime).count() + 1.0;
  double rate_hz = 500.0;  ///< joint states per second on each path
  int port = 0;
  std::string role = "sender";
  std::string url;
};

std::string g1Path() { return std::string(LCMTF_SHARED_URDF_DIR) + "/unitree_g1_29dof.urdf"; }

// Sweeping joint states of `robot` and their encodings, to cycle through.
struct Workload {
  RobotModel robot;
  std::vector<lcmtf::joint_state_t> states;
  std::vector<std::vector<std::uint8_t>> encoded;
  std::size_t transforms_per_message = 0;
};

Workload makeWorkload(RobotModel robot) {
  Workload workload{std::move(robot), {}, {}, 0};
  lcmtf::urdf::JointStateGeneratorOptions sweeping;
  sweeping.sweep = true;
  const lcmtf::urdf::JointStateGenerator generator(workload.robot, sweeping);
  const std::int64_t start = lcmtf::toUtime(lcmtf::now());
  for (int k = 0; k < kDistinctStates; ++k) {
    workload.states.push_back(generator.stateAt(0.002 * k, lcmtf::fromUtime(start + 2000 * k)));
    const lcmtf::joint_state_t& state = workload.states.back();
    workload.encoded.emplace_back(static_cast<std::size_t>(state.getEncodedSize()));
    state.encode(workload.encoded.back().data(), 0, state.getEncodedSize());
  }
  workload.transforms_per_message = workload.robot.movable_joints.size();
  return workload;
}

void decodedStateToBatch(benchmark::State& state, const Workload* workload) {
  lcmtf::urdf::JointStateProcessor processor(workload->robot);
  std::size_t k = 0;
  for (auto _ : state) {
    const lcmtf::tf_message_t* batch = processor.process(workload->states[k++ % kDistinctStates]);
    benchmark::DoNotOptimize(batch);
  }
  state.counters["msgs_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// What the publisher does per message short of the socket: decode, compute, encode.
void bytesToBytes(benchmark::State& state, const Workload* workload) {
  lcmtf::urdf::JointStateProcessor processor(workload->robot);
  std::vector<std::uint8_t> out(1 << 16);
  std::size_t k = 0;
  for (auto _ : state) {
    const std::vector<std::uint8_t>& bytes = workload->encoded[k++ % kDistinctStates];
    const lcmtf::tf_message_t* batch = processor.process(bytes.data(), bytes.size());
    benchmark::DoNotOptimize(batch->encode(out.data(), 0, static_cast<int>(out.size())));
  }
  state.counters["msgs_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void printThroughput(const RecordingReporter& reporter,
                     const std::vector<std::pair<std::string, const Workload*>>& workloads) {
  std::printf("\njoint states handled per second, excluding LCM (target >= %.0fk for the G1)\n",
              kTargetMessagesPerSecond / 1e3);
  std::printf("%-22s %6s %8s %12s %16s %16s\n", "robot", "links", "joints", "transforms",
              "decoded -> batch", "bytes -> bytes");
  for (const auto& [name, workload] : workloads) {
    const double decoded = counter(reporter.find(name + "/decoded_state_to_batch"), "msgs_per_s");
    const double bytes = counter(reporter.find(name + "/bytes_to_bytes"), "msgs_per_s");
    std::printf("%-22s %6zu %8zu %12zu %14.0fk/s %14.0fk/s", name.c_str(),
                workload->robot.links.size(), workload->states[0].name.size(),
                workload->transforms_per_message, decoded / 1e3, bytes / 1e3);
    if (name == "unitree_g1") {
      std::printf("  %s", std::min(decoded, bytes) >= kTargetMessagesPerSecond ? "met" : "MISSED");
    }
    std::printf("\n");
  }
}

// A process this program starts; stopped with SIGTERM (then SIGKILL) and reaped at scope end.
class Child {
 public:
  explicit Child(std::vector<std::string> argv) {
    std::vector<char*> args;
    for (std::string& arg : argv) args.push_back(arg.data());
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    const int error = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error(argv[0] + ": " + std::strerror(error));
  }
  ~Child() {
    kill(pid_, SIGTERM);
    for (int i = 0; i < 200 && waitpid(pid_, nullptr, WNOHANG) == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (kill(pid_, SIGKILL) == 0) waitpid(pid_, nullptr, 0);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // User plus system CPU time so far, in seconds.
  double cpuSeconds() const {
    std::ifstream stat("/proc/" + std::to_string(pid_) + "/stat");
    std::string line;
    std::getline(stat, line);
    const auto close = line.rfind(')');
    if (close == std::string::npos) return NAN;
    std::istringstream fields(line.substr(close + 2));
    std::string skip;
    for (int i = 0; i < 11; ++i) fields >> skip;  // state .. cmajflt
    double user = 0;
    double system = 0;
    fields >> user >> system;
    return (user + system) / static_cast<double>(sysconf(_SC_CLK_TCK));
  }

 private:
  pid_t pid_ = -1;
};

std::string thisProgram() {
  char path[4096] = {};
  if (readlink("/proc/self/exe", path, sizeof path - 1) <= 0) {
    throw std::runtime_error("cannot find this program's path");
  }
  return path;
}

// The latency of each joint state k: from its publication to the moment it was seen.
class Latencies {
 public:
  explicit Latencies(int count) : sent_(count), seen_(count) {}
  void sent(int k) { sent_[k] = Clock::now(); }
  void seen(int k) {
    if (k < 0 || k >= static_cast<int>(seen_.size())) return;
    std::lock_guard<std::mutex> guard(mutex_);
    if (seen_[k] == Clock::time_point{}) seen_[k] = Clock::now();
  }
  // Microseconds for the states from `first` on that were seen, sorted.
  std::vector<double> sortedFrom(int first) const {
    std::lock_guard<std::mutex> guard(mutex_);
    std::vector<double> result;
    for (std::size_t k = static_cast<std::size_t>(first); k < seen_.size(); ++k) {
      if (seen_[k] == Clock::time_point{} || sent_[k] == Clock::time_point{}) continue;
      result.push_back(std::chrono::duration<double, std::micro>(seen_[k] - sent_[k]).count());
    }
    std::sort(result.begin(), result.end());
    return result;
  }

 private:
  std::vector<Clock::time_point> sent_;
  mutable std::mutex mutex_;
  std::vector<Clock::time_point> seen_;
};

double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return NAN;
  const auto rank =
      static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

// The joint state's index from its stamp, or -1.
int indexOf(std::int64_t utime, std::int64_t base_utime, std::int64_t period_us, int count) {
  const std::int64_t offset = utime - base_utime;
  if (offset < 0 || offset % period_us != 0 || offset / period_us >= count) return -1;
  return static_cast<int>(offset / period_us);
}

// The raw path's end: joint states back from the relay, on an LCM and thread of their own.
class RawEcho {
 public:
  RawEcho(const std::string& url, Latencies& latencies, std::int64_t base_utime,
          std::int64_t period_us, int count)
      : lcm_(url),
        latencies_(latencies),
        base_utime_(base_utime),
        period_us_(period_us),
        count_(count) {
    lcm_.subscribe(kRawOut, &RawEcho::onMessage, this)->setQueueCapacity(1000);
    thread_ = std::thread([this] {
      while (!stopping_) lcm_.handleTimeout(50);
    });
  }
  ~RawEcho() {
    stopping_ = true;
    thread_.join();
  }

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    lcmtf::joint_state_t state;
    if (!lcmtf::decodeMessage(buffer->data, buffer->data_size, state).ok) return;
    latencies_.seen(indexOf(state.utime, base_utime_, period_us_, count_));
  }

  lcm::LCM lcm_;
  Latencies& latencies_;
  std::int64_t base_utime_;
  std::int64_t period_us_;
  int count_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

// The first link reached by the longest chain of joints from the root.
std::string deepestLink(const RobotModel& robot) {
  std::map<std::string, std::string> parent;
  for (const auto& joint : robot.movable_joints) parent[joint.child_link] = joint.parent_link;
  for (const auto& joint : robot.fixed_joints) parent[joint.child_link] = joint.parent_link;
  std::string deepest = robot.root_link;
  std::size_t deepest_depth = 0;
  for (const std::string& link : robot.links) {
    std::size_t depth = 0;
    for (std::string at = link; parent.count(at); at = parent[at]) ++depth;
    if (depth > deepest_depth) {
      deepest = link;
      deepest_depth = depth;
    }
  }
  return deepest;
}

struct EndToEndFigures {
  std::vector<double> raw_us;
  std::vector<double> lcmtf_us;
  double publisher_cpu_percent = NAN;
};

// Both paths at once, their joint states taking turns half a period apart, so that whatever
// else the machine does in the meantime weighs on both alike.
EndToEndFigures measureEndToEnd(const Options& options, const Workload& workload, int measured_from,
                                int count) {
  const std::string root = workload.robot.root_link;
  const std::string deepest = deepestLink(workload.robot);
  Child relay({thisProgram(), "--role", "relay", "--url", options.url});
  Child publisher({URDF_PUBLISHER_PROGRAM, "--lcm-url", options.url, g1Path()});
  lcm::LCM lcm(options.url);
  const std::int64_t period_us = std::llround(1e6 / options.rate_hz);
  const std::int64_t raw_base = lcmtf::toUtime(lcmtf::now());
  const std::int64_t lcmtf_base = raw_base + period_us / 2;
  // Declared before the buffer, so they outlive any callback it could still make.
  Latencies raw(count);
  Latencies via_lcmtf(count);
  std::function<void(int)> arm;
  RawEcho echo(options.url, raw, raw_base, period_us, count);
  lcmtf::Buffer buffer;
  lcmtf::ListenerOptions listening;
  listening.lcm_url = options.url;
  lcmtf::TransformListener listener(buffer, listening);
  const auto& fixed = workload.robot.fixed_joints.front();
  if (!buffer.canTransform(fixed.parent_link, fixed.child_link, lcmtf::kLatestTime,
                           std::chrono::seconds(10))) {
    throw std::runtime_error("lcmtf-urdf-publisher sent no static transforms");
  }

  // One request pending at a time: the callback runs within the insert that makes the lookup
  // possible, and arms the request for the next state.
  arm = [&](int k) {
    for (; k < count; ++k) {
      const auto handle = buffer.addTransformableRequest(
          [&, k](lcmtf::TransformableRequestHandle, const std::string&, const std::string&,
                 lcmtf::TimePoint, lcmtf::TransformableResult result) {
            if (result == lcmtf::TransformableResult::kAvailable) via_lcmtf.seen(k);
            arm(k + 1);
          },
          root, deepest, lcmtf::fromUtime(lcmtf_base + k * period_us));
      if (handle != 0) return;
      via_lcmtf.seen(k);
    }
  };
  arm(0);

  EndToEndFigures figures;
  const auto half = std::chrono::microseconds(period_us / 2);
  const auto start = Clock::now() + std::chrono::milliseconds(50);
  double cpu_before = NAN;
  Clock::time_point wall_before;
  for (int k = 0; k < count; ++k) {
    if (k == measured_from) {
      cpu_before = publisher.cpuSeconds();
      wall_before = Clock::now();
    }
    lcmtf::joint_state_t state = workload.states[static_cast<std::size_t>(k % kDistinctStates)];
    const auto due = start + std::chrono::microseconds(k * period_us);
    std::this_thread::sleep_until(due);
    state.utime = raw_base + k * period_us;
    raw.sent(k);
    lcm.publish(kRawIn, &state);
    std::this_thread::sleep_until(due + half);
    state.utime = lcmtf_base + k * period_us;
    via_lcmtf.sent(k);
    lcm.publish(lcmtf::kJointStatesChannel, &state);
  }
  figures.publisher_cpu_percent = 100.0 * (publisher.cpuSeconds() - cpu_before) /
                                  std::chrono::duration<double>(Clock::now() - wall_before).count();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  figures.raw_us = raw.sortedFrom(measured_from);
  figures.lcmtf_us = via_lcmtf.sortedFrom(measured_from);
  return figures;
}

void printRow(const char* name, const std::vector<double>& l) {
  std::printf("%-40s %6zu %8.0f %8.0f %8.0f %8.0f\n", name, l.size(), percentile(l, 50),
              percentile(l, 90), percentile(l, 99), l.empty() ? NAN : l.back());
}

void runEndToEnd(const Options& options, const Workload& g1) {
  const int warmup = static_cast<int>(std::lround((0.5 + options.fill_seconds) * options.rate_hz));
  const int measured = static_cast<int>(std::lround(options.seconds * options.rate_hz));
  const EndToEndFigures figures = measureEndToEnd(options, g1, warmup, warmup + measured);

  std::printf("\nend to end over %s: G1 joint states at %.0f Hz on each path, taking turns;\n",
              options.url.c_str(), options.rate_hz);
  std::printf("%.1f s measured after %.1f s in which the listener's buffer fills its history\n",
              options.seconds, 0.5 + options.fill_seconds);
  std::printf("raw:   joint state -> relay process -> back here (two LCM hops), at the callback\n");
  std::printf("lcmtf: joint state -> lcmtf-urdf-publisher -> TransformListener here, when\n");
  std::printf("       %s -> %s at the state's stamp can be looked up\n\n",
              g1.robot.root_link.c_str(), deepestLink(g1.robot).c_str());
  std::printf("%-40s %6s %8s %8s %8s %8s\n", "latency (us)", "n", "p50", "p90", "p99", "max");
  printRow("two raw LCM hops", figures.raw_us);
  printRow("joint state -> lookup", figures.lcmtf_us);
  const double ratio = percentile(figures.lcmtf_us, 99) / percentile(figures.raw_us, 99);
  std::printf("\np99 lcmtf / p99 two raw hops: %.2fx (target <= %.0fx): %s\n", ratio, kTargetRatio,
              ratio <= kTargetRatio ? "met" : "MISSED");
  std::printf("lcmtf-urdf-publisher CPU while measured: %.1f %% of one core\n",
              figures.publisher_cpu_percent);
  std::printf("lost: raw %zu of %d, lcmtf %zu of %d\n", measured - figures.raw_us.size(), measured,
              measured - figures.lcmtf_us.size(), measured);
}

int runRelay(const std::string& url) {
  const std::atomic<bool>& stop = lcmtf::programs::installStopSignalHandlers();
  lcm::LCM lcm(url);
  if (!lcm.good()) return 1;
  struct Relay {
    void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
      lcm->publish(kRawOut, buffer->data, buffer->data_size);
    }
    lcm::LCM* lcm;
  } relay{&lcm};
  lcm.subscribe(kRawIn, &Relay::onMessage, &relay)->setQueueCapacity(1000);
  while (!stop) lcm.handleTimeout(100);
  return 0;
}

// Takes this program's own flags out of argv, leaving Google Benchmark's.
Options takeOptions(int& argc, char** argv) {
  Options options;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    const bool has_value = i + 1 < argc;
    if (name == "--skip-e2e") {
      options.e2e = false;
    } else if (name == "--seconds" && has_value) {
      options.seconds = std::stod(argv[++i]);
    } else if (name == "--fill-seconds" && has_value) {
      options.fill_seconds = std::stod(argv[++i]);
    } else if (name == "--rate" && has_value) {
      options.rate_hz = std::stod(argv[++i]);
    } else if (name == "--port" && has_value) {
      options.port = std::stoi(argv[++i]);
    } else if (name == "--role" && has_value) {
      options.role = argv[++i];
    } else if (name == "--url" && has_value) {
      options.url = argv[++i];
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  if (!(options.rate_hz > 0 && options.seconds > 0 && options.fill_seconds >= 0)) {
    throw std::invalid_argument("--rate and --seconds must be positive, --fill-seconds >= 0");
  }
  const int port = options.port != 0 ? options.port : 40000 + getpid() % 10000;
  if (options.url.empty()) options.url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
  return options;
}

int run(int argc, char** argv) {
  const Options options = takeOptions(argc, argv);
  if (options.role == "relay") return runRelay(options.url);
  if (!std::filesystem::exists(g1Path())) {
    std::fprintf(stderr, "urdf_publisher_bench: %s is absent; the G1 figures need it\n",
                 g1Path().c_str());
    return 1;
  }
  const Workload g1 = makeWorkload(lcmtf::urdf::loadRobotModel(g1Path()));
  const Workload pr2 = makeWorkload(lcmtf::urdf::parseRobotModel(pr2ScaleUrdf(), "pr2_scale"));
  const std::vector<std::pair<std::string, const Workload*>> workloads{{"unitree_g1", &g1},
                                                                       {"pr2_scale", &pr2}};
  for (const auto& [name, workload] : workloads) {
    benchmark::RegisterBenchmark((name + "/decoded_state_to_batch").c_str(), decodedStateToBatch,
                                 workload);
    benchmark::RegisterBenchmark((name + "/bytes_to_bytes").c_str(), bytesToBytes, workload);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printThroughput(reporter, workloads);
  if (options.e2e) runEndToEnd(options, g1);
  return 0;
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  try {
    return bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "urdf_publisher_bench: %s\n", e.what());
    return 1;
  }
}
