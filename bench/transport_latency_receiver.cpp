// The receiving process of transport_latency_bench: one phase at a time, as the sender asks.
#include <atomic>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/buffer.hpp"
#include "lcmtf/transform_listener.hpp"
#include "lcmtf/wire_decode.hpp"
#include "transport_latency_protocol.hpp"

namespace bench {
namespace {

// The CPU time is read again at each of the last batches seen, so a lost last batch does not
// lose the figure.
constexpr int kEndSnapshots = 100;

// When each batch was seen, and the process CPU time across the measured batches.
class Recorder {
 public:
  explicit Recorder(const Phase& phase) : phase_(phase) { outcome_.done_us.assign(phase.count, 0); }

  void record(int k, std::int64_t done_us) {
    if (k < 0 || k >= phase_.count || outcome_.done_us[k] != 0) return;
    outcome_.done_us[k] = done_us;
    if (k >= phase_.measured_from && first_us_ == 0) {
      first_cpu_ns_ = processCpuNanos();
      first_us_ = done_us;
    } else if (k >= phase_.count - kEndSnapshots && first_us_ != 0) {
      outcome_.cpu_ns = processCpuNanos() - first_cpu_ns_;
      outcome_.wall_us = done_us - first_us_;
    }
  }

  Outcome& outcome() { return outcome_; }

 private:
  const Phase& phase_;
  Outcome outcome_;
  std::int64_t first_cpu_ns_ = 0;
  std::int64_t first_us_ = 0;
};

void awaitEnd() {
  std::string line;
  while (std::getline(std::cin, line) && line != "END") {
  }
}

// A plain subscriber with its own handling thread, as the listener has: the time is taken on
// entry, the stamp decoded afterwards to name the batch.
class RawSubscriber {
 public:
  RawSubscriber(const Phase& phase, Recorder& recorder) : phase_(phase), recorder_(recorder) {}

  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string&) {
    const std::int64_t now_us = wallMicros();
    ++received_;
    lcmtf::tf_message_t batch;
    if (lcmtf::decodeMessage(buffer->data, buffer->data_size, batch).ok &&
        !batch.transforms.empty()) {
      recorder_.record(phase_.index(batch.transforms.back().utime), now_us);
    }
  }
  std::int64_t received() const { return received_; }

 private:
  const Phase& phase_;
  Recorder& recorder_;
  std::int64_t received_ = 0;
};

Outcome runRaw(const Phase& phase, const std::string& url) {
  Recorder recorder(phase);
  RawSubscriber subscriber(phase, recorder);
  lcm::LCM lcm(url);
  if (!lcm.good()) throw std::runtime_error("cannot open LCM at " + url);
  lcm::Subscription* subscription =
      lcm.subscribe(kRawChannel, &RawSubscriber::onMessage, &subscriber);
  subscription->setQueueCapacity(lcmtf::ListenerOptions{}.queue_capacity);
  std::atomic<bool> stopping{false};
  std::thread thread([&] {
    while (!stopping) lcm.handleTimeout(50);
  });
  std::cout << "READY" << std::endl;
  awaitEnd();
  stopping = true;
  thread.join();
  recorder.outcome().received = subscriber.received();
  return recorder.outcome();
}

// A TransformListener on its own thread, with one transformable request pending at a time:
// (kRootFrame, kDeepestFrame) at the stamp of the next batch. Its callback runs right after
// the insert that makes the lookup possible, and arms the request for the batch after.
Outcome runTf(const Phase& phase, const std::string& url) {
  Recorder recorder(phase);
  lcmtf::Buffer buffer;
  std::int64_t late = 0;
  std::int64_t lookup_errors = 0;
  std::function<void(int)> arm = [&](int k) {
    for (; k < phase.count; ++k) {
      const lcmtf::TimePoint stamp = lcmtf::fromUtime(phase.stamp(k));
      const auto handle = buffer.addTransformableRequest(
          [&, k, stamp](lcmtf::TransformableRequestHandle, const std::string&, const std::string&,
                        lcmtf::TimePoint, lcmtf::TransformableResult result) {
            const std::int64_t now_us = wallMicros();
            if (result == lcmtf::TransformableResult::kAvailable) {
              recorder.record(k, now_us);
              try {
                buffer.lookupTransform(kRootFrame, kDeepestFrame, stamp);
              } catch (const lcmtf::TransformException&) {
                ++lookup_errors;
              }
            }
            arm(k + 1);
          },
          kRootFrame, kDeepestFrame, stamp);
      if (handle != 0) return;
      recorder.record(k, wallMicros());
      ++late;
    }
  };
  arm(0);
  std::int64_t received = 0;
  {
    lcmtf::ListenerOptions options;
    options.lcm_url = url;
    lcmtf::TransformListener listener(buffer, options);
    std::cout << "READY" << std::endl;
    awaitEnd();
    received = static_cast<std::int64_t>(listener.statistics().messages);
  }
  Outcome& outcome = recorder.outcome();
  outcome.received = received;
  outcome.late = late;
  outcome.lookup_errors = lookup_errors;
  return outcome;
}

void print(const Outcome& outcome) {
  std::cout << "RESULT " << outcome.received << " " << outcome.late << " " << outcome.lookup_errors
            << " " << outcome.cpu_ns << " " << outcome.wall_us << "\n";
  for (std::size_t k = 0; k < outcome.done_us.size(); ++k) {
    if (outcome.done_us[k] != 0) std::cout << k << " " << outcome.done_us[k] << "\n";
  }
  std::cout << "DONE" << std::endl;
}

}  // namespace

int runReceiver(const std::string& url) {
  std::string line;
  while (std::getline(std::cin, line)) {
    Phase phase;
    if (!Phase::parse(line, phase)) {
      std::cerr << "receiver: bad command '" << line << "'\n";
      return 1;
    }
    print(phase.kind == Phase::Kind::kRaw ? runRaw(phase, url) : runTf(phase, url));
  }
  return 0;
}

}  // namespace bench
