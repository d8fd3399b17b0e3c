// End-to-end latency of lcmtf over LCM udpm between two processes on one machine: from
// TransformBroadcaster::sendTransform to the moment the other process's Buffer can answer the
// lookup, next to the raw LCM hop of the same bytes, and the receiving process's CPU time.
//
//   transport_latency_bench [--seconds S] [--fill-seconds S] [--rate HZ] [--port P]
//
// The program starts a copy of itself as the receiver (--role receiver --url URL) and drives
// it over its stdin/stdout, one phase after the other: raw (a plain LCM subscriber), then TF
// (a TransformListener on its own thread). The TF phase measures once the buffer holds its
// full history (--fill-seconds, default the cache time + 1 s); the batches before that are
// reported on their own row, since the history growing costs the listener extra.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "transport_latency_protocol.hpp"

extern char** environ;

namespace bench {
namespace {

constexpr double kTargetRatio = 3.0;
constexpr double kTwoPi = 6.283185307179586;
constexpr auto kReplyTimeout = std::chrono::seconds(20);

struct Options {
  double seconds = 5.0;
  double fill_seconds =
      std::chrono::duration<double>(lcmtf::BufferCore::kDefaultCacheTime).count() + 1.0;
  int rate_hz = 1000;
  int port = 0;
};

// The receiver process, driven by lines on its stdin and answering on its stdout; killed and
// reaped when this goes out of scope.
class Receiver {
 public:
  explicit Receiver(const std::string& url) {
    char program[4096] = {};
    if (readlink("/proc/self/exe", program, sizeof program - 1) <= 0) {
      throw std::runtime_error("cannot find this program's path");
    }
    std::vector<std::string> args{program, "--role", "receiver", "--url", url};
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);

    int to_child[2] = {-1, -1};
    int from_child[2] = {-1, -1};
    int error = pipe2(to_child, O_CLOEXEC) == 0 && pipe2(from_child, O_CLOEXEC) == 0 ? 0 : errno;
    if (error == 0) {
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_adddup2(&actions, to_child[0], STDIN_FILENO);
      posix_spawn_file_actions_adddup2(&actions, from_child[1], STDOUT_FILENO);
      error = posix_spawn(&pid_, program, &actions, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&actions);
    }
    for (int fd : {to_child[0], from_child[1], error != 0 ? to_child[1] : -1,
                   error != 0 ? from_child[0] : -1}) {
      if (fd >= 0) close(fd);
    }
    if (error != 0) {
      throw std::runtime_error(std::string("cannot start the receiver: ") + std::strerror(error));
    }
    to_child_ = to_child[1];
    from_child_ = from_child[0];
  }

  ~Receiver() {
    close(to_child_);
    close(from_child_);
    if (pid_ <= 0) return;
    for (int i = 0; i < 200; ++i) {
      if (waitpid(pid_, nullptr, WNOHANG) != 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  Receiver(const Receiver&) = delete;
  Receiver& operator=(const Receiver&) = delete;

  void send(const std::string& line) {
    const std::string data = line + "\n";
    if (write(to_child_, data.data(), data.size()) != static_cast<ssize_t>(data.size())) {
      throw std::runtime_error("the receiver is gone");
    }
  }

  std::string readLine() {
    const auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    for (;;) {
      const auto newline = pending_.find('\n');
      if (newline != std::string::npos) {
        std::string line = pending_.substr(0, newline);
        pending_.erase(0, newline + 1);
        return line;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd fd{from_child_, POLLIN, 0};
      if (left.count() <= 0 || poll(&fd, 1, static_cast<int>(left.count())) <= 0) {
        throw std::runtime_error("no answer from the receiver");
      }
      char chunk[65536];
      const ssize_t n = read(from_child_, chunk, sizeof chunk);
      if (n <= 0) throw std::runtime_error("the receiver exited");
      pending_.append(chunk, static_cast<std::size_t>(n));
    }
  }

 private:
  pid_t pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  std::string pending_;
};

int warmupBatches(const Options& options) { return std::max(1, options.rate_hz / 2); }

std::vector<lcmtf::TransformStamped> makeBatch(const std::vector<Edge>& edges, std::int64_t stamp) {
  std::vector<lcmtf::TransformStamped> batch;
  batch.reserve(edges.size());
  const double phase = static_cast<double>(stamp % 1000000) * 1e-6 * kTwoPi;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    lcmtf::TransformStamped t;
    t.stamp = lcmtf::fromUtime(stamp);
    t.parent_frame = edges[i].parent;
    t.child_frame = edges[i].child;
    const double angle = 0.3 * std::sin(phase + static_cast<double>(i));
    t.transform =
        lcmtf::Transform(Eigen::Vector3d(0.1, 0.02 * static_cast<double>(i % 5), 0.05),
                         Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())));
    batch.push_back(std::move(t));
  }
  return batch;
}

struct PhaseFigures {
  Outcome outcome;
  int sent = 0;
  std::vector<std::int64_t> warming_us;  // from the end of warm-up to measured_from
  std::vector<std::int64_t> measured_us;
};

Phase planPhase(Phase::Kind kind, const Options& options) {
  Phase phase;
  phase.kind = kind;
  phase.period_us = 1000000 / options.rate_hz;
  const auto batches = [&options](double seconds) {
    return static_cast<int>(std::lround(seconds * options.rate_hz));
  };
  phase.measured_from = warmupBatches(options);
  if (kind == Phase::Kind::kTf) phase.measured_from += batches(options.fill_seconds);
  phase.count = phase.measured_from + batches(options.seconds);
  return phase;
}

PhaseFigures runPhase(Phase phase, int warmup, lcm::LCM& lcm,
                      lcmtf::TransformBroadcaster& broadcaster, Receiver& receiver) {
  const std::vector<Edge> edges = robotEdges();
  const auto lead = std::chrono::milliseconds(100);
  const auto start = std::chrono::steady_clock::now() + lead;
  phase.base_us = wallMicros() + std::chrono::microseconds(lead).count();
  receiver.send(phase.format());
  if (receiver.readLine() != "READY") throw std::runtime_error("the receiver is not ready");

  std::vector<std::int64_t> sent_us(phase.count, 0);
  for (int k = 0; k < phase.count; ++k) {
    std::this_thread::sleep_until(start + std::chrono::microseconds(k * phase.period_us));
    const auto batch = makeBatch(edges, phase.stamp(k));
    sent_us[k] = wallMicros();
    if (phase.kind == Phase::Kind::kTf) {
      broadcaster.sendTransform(batch);
    } else {
      const lcmtf::tf_message_t message = lcmtf::makeTfMessage(batch, broadcaster.authority());
      lcm.publish(kRawChannel, &message);
    }
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  receiver.send("END");

  PhaseFigures figures;
  figures.sent = phase.count;
  std::istringstream result(receiver.readLine());
  std::string word;
  Outcome& o = figures.outcome;
  result >> word >> o.received >> o.late >> o.lookup_errors >> o.cpu_ns >> o.wall_us;
  if (word != "RESULT") throw std::runtime_error("unexpected answer: " + word);
  for (std::string line = receiver.readLine(); line != "DONE"; line = receiver.readLine()) {
    long long k = -1;
    long long done = 0;
    if (std::sscanf(line.c_str(), "%lld %lld", &k, &done) != 2 || k < warmup || k >= phase.count) {
      continue;
    }
    (k < phase.measured_from ? figures.warming_us : figures.measured_us)
        .push_back(done - sent_us[static_cast<std::size_t>(k)]);
  }
  std::sort(figures.warming_us.begin(), figures.warming_us.end());
  std::sort(figures.measured_us.begin(), figures.measured_us.end());
  return figures;
}

std::int64_t percentile(const std::vector<std::int64_t>& sorted, double p) {
  if (sorted.empty()) return 0;
  const auto rank =
      static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

double cpuPercent(const Outcome& o) {
  return o.wall_us > 0
             ? 100.0 * static_cast<double>(o.cpu_ns) / 1e3 / static_cast<double>(o.wall_us)
             : std::nan("");
}

void printRow(const std::string& name, const std::vector<std::int64_t>& l) {
  std::printf("%-34s %6zu %7lld %7lld %7lld %7lld\n", name.c_str(), l.size(),
              static_cast<long long>(percentile(l, 50)), static_cast<long long>(percentile(l, 90)),
              static_cast<long long>(percentile(l, 99)),
              static_cast<long long>(l.empty() ? 0 : l.back()));
}

void printLoss(const char* name, const PhaseFigures& f) {
  std::printf("%s: %d batches sent, %lld received, %lld lost\n", name, f.sent,
              static_cast<long long>(f.outcome.received),
              static_cast<long long>(f.sent - f.outcome.received));
}

int runSender(const Options& options) {
  const int port = options.port != 0 ? options.port : 50000 + getpid() % 10000;
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
  lcm::LCM lcm(url);
  if (!lcm.good()) throw std::runtime_error("cannot open LCM at " + url);
  lcmtf::TransformBroadcaster broadcaster(lcm);
  signal(SIGPIPE, SIG_IGN);
  Receiver receiver(url);
  const int warmup = warmupBatches(options);
  const PhaseFigures raw =
      runPhase(planPhase(Phase::Kind::kRaw, options), warmup, lcm, broadcaster, receiver);
  const PhaseFigures tf =
      runPhase(planPhase(Phase::Kind::kTf, options), warmup, lcm, broadcaster, receiver);

  std::printf("lcmtf transport latency over %s\n", url.c_str());
  std::printf("%zu-transform batches at %d Hz, %d warm-up batches, then %.1f s measured\n",
              robotEdges().size(), options.rate_hz, warmup, options.seconds);
  std::printf("raw: the same tf_message_t on %s, timed at a plain subscriber's callback\n",
              kRawChannel);
  std::printf("TF:  sendTransform until the receiver can look up %s in %s at the batch stamp,\n",
              kDeepestFrame, kRootFrame);
  std::printf("     measured after %.1f s more, in which the buffer fills its %.0f s of history\n",
              options.fill_seconds,
              std::chrono::duration<double>(lcmtf::BufferCore::kDefaultCacheTime).count());
  std::printf("clock: CLOCK_REALTIME (system_clock, us), read by both processes on this host\n\n");
  std::printf("%-34s %6s %7s %7s %7s %7s\n", "latency (us)", "n", "p50", "p90", "p99", "max");
  printRow("raw LCM hop", raw.measured_us);
  printRow("TF send -> lookup", tf.measured_us);
  if (!tf.warming_us.empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "TF, buffer filling (%.1f s)", options.fill_seconds);
    printRow(name, tf.warming_us);
  }
  const double ratio =
      static_cast<double>(percentile(tf.measured_us, 99)) /
      static_cast<double>(std::max<std::int64_t>(1, percentile(raw.measured_us, 99)));
  std::printf("\np99 TF / p99 raw: %.2fx (target <= %.0fx): %s\n", ratio, kTargetRatio,
              ratio <= kTargetRatio ? "met" : "MISSED");
  std::printf("receiver process CPU while measured (all its threads, LCM's included):\n");
  std::printf("  TF, TransformListener: %.1f %% of one core (%.1f ms per s)\n",
              cpuPercent(tf.outcome), cpuPercent(tf.outcome) * 10.0);
  std::printf("  raw, plain subscriber: %.1f %% of one core\n", cpuPercent(raw.outcome));
  printLoss("raw", raw);
  printLoss("TF", tf);
  if (tf.outcome.late != 0 || tf.outcome.lookup_errors != 0) {
    std::printf("TF: %lld batches seen only after a later one arrived, %lld failed lookups\n",
                static_cast<long long>(tf.outcome.late),
                static_cast<long long>(tf.outcome.lookup_errors));
  }
  return 0;
}

bool parseOptions(int argc, char** argv, Options& options, std::string& role, std::string& url) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string name = argv[i];
    const std::string value = argv[i + 1];
    if (name == "--seconds") {
      options.seconds = std::stod(value);
    } else if (name == "--fill-seconds") {
      options.fill_seconds = std::stod(value);
    } else if (name == "--rate") {
      options.rate_hz = std::stoi(value);
    } else if (name == "--port") {
      options.port = std::stoi(value);
    } else if (name == "--role") {
      role = value;
    } else if (name == "--url") {
      url = value;
    } else {
      return false;
    }
  }
  return argc % 2 == 1 && options.seconds > 0 && options.fill_seconds >= 0 && options.rate_hz > 0 &&
         options.rate_hz <= 1000000 && options.port >= 0 && options.port < 65536;
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  bench::Options options;
  std::string role;
  std::string url;
  try {
    if (!bench::parseOptions(argc, argv, options, role, url)) {
      std::fprintf(stderr, "usage: %s [--seconds S] [--fill-seconds S] [--rate HZ] [--port P]\n",
                   argv[0]);
      return 2;
    }
    if (role == "receiver") return bench::runReceiver(url);
    return bench::runSender(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "transport_latency_bench: %s\n", e.what());
    return 1;
  }
}
