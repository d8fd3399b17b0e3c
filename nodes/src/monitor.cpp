#include "lcmtf/nodes/monitor.hpp"

#include <unistd.h>

#include <algorithm>
#include <iostream>

#include "lcmtf/nodes/chain_delay.hpp"
#include "lcmtf/nodes/monitor_report.hpp"
#include "lcmtf/nodes/tf_traffic_subscriber.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::nodes {

namespace {

constexpr const char* kProgram = "lcmtf-monitor";

constexpr const char* kDescription =
    "Listens to the transform channels and reports, per frame: its parent, who sends it "
    "(authority), how often, how late (delay = receive time minus the transform's stamp, "
    "average and max), and how many samples a listener's buffer holds; per authority: its "
    "message rate and delays; and every conflict (one frame sent by two authorities). Given "
    "two frames A and B, it also shows the chain between them and its net delay: at each "
    "update of the chain, the receive time minus the newest time at which the whole chain "
    "has data.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-monitor                           one report after 5 s\n"
    "  lcmtf-monitor map camera_optical        with the chain map -> ... -> camera_optical\n"
    "  lcmtf-monitor --continuous --duration 2 a fresh report every 2 s until Ctrl-C";

constexpr const char* kClearScreen = "\033[H\033[2J";

ListenerOptions listenerWithoutRequest(const TfConnection& connection) {
  ListenerOptions options = listenerOptionsFor(connection, kProgram);
  options.request_statics_at_start = false;
  return options;
}

class MonitorLoop {
 public:
  MonitorLoop(const MonitorOptions& options, lcm::LCM& lcm)
      : started_(now()),
        options_(options),
        lcm_(lcm),
        listener_(buffer_, lcm, listenerWithoutRequest(options.connection)),
        subscriber_(lcm, options.connection, traffic_,
                    [this](const tf_message_t& batch, bool is_static, TimePoint received) {
                      if (chain_) chain_->onBatch(batch, is_static, received);
                    }) {
    if (!options.frame_a.empty()) chain_.emplace(buffer_, options.frame_a, options.frame_b);
    // Only now: LCM hands a message to the subscriptions that exist when it arrives.
    listener_.requestStatics();
  }

  int run(std::ostream& out, std::ostream& err, const std::atomic<bool>& stop) {
    using Clock = std::chrono::steady_clock;
    TimePoint window_start = started_;
    auto deadline = Clock::now() + options_.duration;
    while (!stop.load()) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (!handleLcmFor(lcm_, std::min(left, std::chrono::milliseconds(50)))) {
        err << kProgram << ": LCM stopped working at " << source() << '\n';
        return kExitFailure;
      }
      if (Clock::now() < deadline) continue;
      const TimePoint window_end = now();
      report(out, window_start, window_end);
      if (!options_.continuous) return exitStatus(err);
      traffic_.forgetBefore(window_end - std::max(options_.duration, buffer_.cacheTime()));
      if (chain_) chain_->reset();
      window_start = window_end;
      deadline += options_.duration;
      // After a stall (a suspended process, an overloaded machine) the next window still
      // spans a whole duration instead of reporting an instant.
      if (deadline < Clock::now() + options_.duration / 2)
        deadline = Clock::now() + options_.duration;
    }
    if (!options_.continuous) {  // stopped early: report what was heard so far
      report(out, window_start, now());
      return exitStatus(err);
    }
    return kExitSuccess;
  }

 private:
  std::string source() const {
    return options_.connection.tf_channel + " and " + options_.connection.static_channel + " at " +
           describeLcmUrl(options_.connection.lcm_url);
  }

  void report(std::ostream& out, TimePoint window_start, TimePoint window_end) {
    TrafficSummary summary = traffic_.summarize(window_start, window_end, buffer_.cacheTime());
    if (std::string note = stampedAheadNote(listener_, options_.connection); !note.empty()) {
      summary.problems.push_back(std::move(note));
    }
    const std::optional<ChainReport> chain =
        chain_ ? std::optional<ChainReport>(chain_->report()) : std::nullopt;
    if (options_.continuous && options_.clear_screen) out << kClearScreen;
    out << formatMonitorReport(summary, source(), chain ? &*chain : nullptr);
    if (options_.continuous && !options_.clear_screen) out << "----\n";
    out << std::flush;
    heard_anything_ = heard_anything_ || summary.messages > 0 || summary.malformed > 0;
  }

  int exitStatus(std::ostream& err) const {
    if (!heard_anything_) {
      err << kProgram << ": nothing heard on " << source()
          << "; is a broadcaster running on that URL and those channels?\n";
      return kExitFailure;
    }
    if (chain_) {
      const ChainReport chain = chain_->report();
      if (!chain.problem.empty()) {
        err << kProgram << ": no chain from '" << chain.frame_a << "' to '" << chain.frame_b
            << "': " << printable(chain.problem);
        if (const std::string note = stampedAheadNote(listener_, options_.connection);
            !note.empty()) {
          err << " (" << note << ')';
        }
        err << '\n';
        return kExitFailure;
      }
    }
    return kExitSuccess;
  }

  // Before the listener asks for the statics: answers may be stamped before the request's
  // publish call returns.
  const TimePoint started_;
  const MonitorOptions& options_;
  lcm::LCM& lcm_;
  Buffer buffer_;
  TransformListener listener_;  // subscribed first, so the buffer holds a batch before chain_
  TfTraffic traffic_;
  TfTrafficSubscriber subscriber_;
  std::optional<ChainDelayMeter> chain_;
  bool heard_anything_ = false;
};

}  // namespace

std::optional<int> parseMonitorCommandLine(const std::vector<std::string>& args,
                                           MonitorOptions& options, std::ostream& out,
                                           std::ostream& err) {
  auto app = makeToolApp(kProgram, kDescription, kExamples);
  std::vector<std::string> frames;
  double duration_seconds = 5.0;
  app->add_option("frames", frames, "Two frames A B: also report the chain between them")
      ->type_name("A B")
      ->check(nonEmptyName());
  app->add_option("--duration", duration_seconds,
                  "Seconds to listen before reporting (with --continuous: between reports, "
                  "each over the last window)")
      ->check(positiveFiniteNumberUpTo(86400.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  app->add_flag("-c,--continuous", options.continuous,
                "Keep listening and print a fresh report every --duration seconds");
  addConnectionOptions(*app, options.connection);
  addStampAheadOption(*app, options.connection.max_stamp_ahead_s);
  if (auto status = parseCommandLine(*app, args, out, err)) return status;
  if (!frames.empty() && frames.size() != 2) {
    return reportBadArguments(*app,
                              "got " + std::to_string(frames.size()) +
                                  " frame arguments: give two frames (A B) for a chain, or none",
                              err);
  }
  if (frames.size() == 2) {
    options.frame_a = frames[0];
    options.frame_b = frames[1];
  }
  options.duration = secondsToDuration(duration_seconds);
  options.clear_screen = &out == &std::cout && isatty(STDOUT_FILENO);
  return std::nullopt;
}

int runMonitor(const MonitorOptions& options, lcm::LCM& lcm, std::ostream& out, std::ostream& err,
               const std::atomic<bool>& stop) {
  MonitorLoop loop(options, lcm);
  return loop.run(out, err, stop);
}

int monitorCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                   const std::atomic<bool>& stop) {
  return parseOpenAndRun(args, kProgram, out, err, stop, &parseMonitorCommandLine, &runMonitor);
}

}  // namespace lcmtf::nodes
