#include "lcmtf/nodes/echo.hpp"

#include <algorithm>
#include <optional>
#include <ostream>

#include "lcmtf/nodes/pose_text.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::nodes {

namespace {

constexpr const char* kProgram = "lcmtf-echo";

constexpr const char* kDescription =
    "Prints the pose of FRAME in REFERENCE (the transform that maps points given in FRAME into "
    "REFERENCE) every 1/--rate seconds: its stamp and age, translation, rotation as a "
    "quaternion and as roll, pitch, yaw (rotation = Rz(yaw) Ry(pitch) Rx(roll)) in radians and "
    "degrees, and the 4x4 homogeneous matrix. Until both frames are known and connected it "
    "says on stderr what is missing.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-echo map base_link                  latest pose, once a second\n"
    "  lcmtf-echo --rate 10 --precision 6 base_link camera\n"
    "  lcmtf-echo --time -0.5 odom base_link     as it was half a second ago\n"
    "  lcmtf-echo --time 1700000000.25 --once --timeout 5 map base_link\n"
    "                                            at that instant (a replayed log), then exit";

// Without new data for this long, a pose of the latest data is said to be stale.
constexpr auto kStaleAfter = std::chrono::seconds(2);

class EchoLoop {
 public:
  EchoLoop(const EchoOptions& options, lcm::LCM& lcm, std::ostream& out, std::ostream& err)
      : options_(options),
        lcm_(lcm),
        out_(out),
        err_(err),
        buffer_(std::max(BufferCore::kDefaultCacheTime,
                         options.time.before_now + BufferCore::kDefaultCacheTime)),
        listener_(buffer_, lcm, listenerOptions()) {}

  int run(const std::atomic<bool>& stop) {
    using Clock = std::chrono::steady_clock;
    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(1.0 / options_.rate_hz));
    const auto start = Clock::now();
    auto next_tick = start + period;
    bool printed = false;
    // At a high --rate, "Waiting" would flood the terminal: at most once a second.
    const auto waiting_period = std::max<Clock::duration>(period, std::chrono::seconds(1));
    std::optional<Clock::time_point> last_waiting;
    while (!stop.load()) {
      const auto wait =
          std::chrono::duration_cast<std::chrono::milliseconds>(next_tick - Clock::now());
      if (!handleLcmFor(lcm_, std::min(wait, std::chrono::milliseconds(50)))) {
        err_ << kProgram << ": LCM stopped working at "
             << describeLcmUrl(options_.connection.lcm_url) << '\n';
        return kExitFailure;
      }
      const auto now_steady = Clock::now();
      const bool tick = now_steady >= next_tick;
      if (tick) next_tick = std::max(next_tick + period, now_steady);
      if (printed && !tick) continue;
      const TimePoint time = options_.time.at(now());
      if (tryPrint(time)) {
        if (options_.once) return said_not_finite_ ? kExitFailure : kExitSuccess;
        printed = true;
        next_tick = now_steady + period;
        continue;
      }
      if (const std::optional<std::string> never = neverAvailable(time)) {
        err_ << kProgram << ": " << printable(*never) << std::endl;
        return kExitFailure;
      }
      const bool timed_out =
          options_.timeout && !printed && now_steady - start >= *options_.timeout;
      if (!tick && !timed_out) continue;
      std::string missing = printable(describeMissing(buffer_, options_.reference_frame,
                                                      options_.frame, time, heardAnything()));
      if (!heardAnything()) missing += " on " + channels();
      if (const std::string note = stampedAheadNote(listener_, options_.connection);
          !note.empty()) {
        missing += " (" + note + ")";
      }
      if (timed_out) {
        err_ << kProgram << ": gave up after " << toString(*options_.timeout) << ": " << missing
             << tooShortForTheTimeBeforeNow() << std::endl;
        return kExitFailure;
      }
      if (!last_waiting || now_steady - *last_waiting >= waiting_period) {
        err_ << "Waiting: " << missing << std::endl;
        last_waiting = now_steady;
      }
    }
    if (options_.once && !printed) {
      err_ << kProgram << ": stopped before '" << options_.frame << "' in '"
           << options_.reference_frame << "' could be looked up\n";
      return kExitFailure;
    }
    return kExitSuccess;
  }

 private:
  ListenerOptions listenerOptions() const {
    ListenerOptions listener = listenerOptionsFor(options_.connection, kProgram);
    std::ostream* err = &err_;
    listener.reporter = [err](const std::string& message) {
      *err << kProgram << ": " << message << std::endl;
    };
    return listener;
  }

  std::string tooShortForTheTimeBeforeNow() const {
    if (!options_.timeout || *options_.timeout > options_.time.before_now) return {};
    return " (history begins when lcmtf-echo starts listening: a moving frame's pose " +
           toString(options_.time.before_now) + " ago needs a --timeout longer than that)";
  }

  std::string channels() const {
    return options_.connection.tf_channel + " or " + options_.connection.static_channel + " at " +
           describeLcmUrl(options_.connection.lcm_url);
  }

  bool heardAnything() const {
    const ListenerStatistics statistics = listener_.statistics();
    return statistics.messages > 0 || statistics.malformed > 0;
  }

  bool tryPrint(TimePoint time) {
    if (!buffer_.canTransform(options_.reference_frame, options_.frame, time)) return false;
    try {
      const TransformStamped reference_T_frame =
          buffer_.lookupTransform(options_.reference_frame, options_.frame, time);
      out_ << formatPose(reference_T_frame, now(), options_.precision) << std::flush;
      if (options_.time.kind == EchoTime::Kind::kLatest) noteFreshness(reference_T_frame.stamp);
      noteNotFinite(reference_T_frame);
      return true;
    } catch (const TransformException&) {
      return false;
    }
  }

  // A fixed instant older than the history every edge between the frames still keeps: edges
  // only move forward, so it will never be there. Says why; nothing while it still may come.
  std::optional<std::string> neverAvailable(TimePoint time) const {
    if (options_.time.kind != EchoTime::Kind::kFixed) return std::nullopt;
    TimePoint latest_common;
    try {
      latest_common = buffer_.getLatestCommonTime(options_.reference_frame, options_.frame);
    } catch (const TransformException&) {
      return std::nullopt;
    }
    if (latest_common == kLatestTime) return std::nullopt;
    // Stamps from the network may be anything.
    const TimePoint oldest_kept =
        fromUtime(saturatingSubtract(toUtime(latest_common), buffer_.cacheTime().count()));
    if (time >= oldest_kept) return std::nullopt;
    return "'" + options_.frame + "' in '" + options_.reference_frame + "' at " + toString(time) +
           " can never be looked up: it is older than the " + toString(buffer_.cacheTime()) +
           " of history kept behind the newest data of every edge between them (the oldest "
           "instant all of them hold is " +
           toString(oldest_kept) + ")";
  }

  // Edges each finite may still sum past what a double holds. Said once.
  void noteNotFinite(const TransformStamped& reference_T_frame) {
    if (said_not_finite_ || reference_T_frame.transform.translation.allFinite()) return;
    said_not_finite_ = true;
    err_ << kProgram << ": the translation is not finite: the edges between '"
         << options_.reference_frame << "' and '" << options_.frame
         << "' are each finite but too far to add up in double precision" << std::endl;
  }

  // Says once when the latest data stops changing (its publishers stopped), and once when it
  // changes again.
  void noteFreshness(TimePoint stamp) {
    const auto now_steady = std::chrono::steady_clock::now();
    if (stamp == kLatestTime) return;  // every edge static: there is nothing newer to wait for
    if (!newest_stamp_ || stamp != *newest_stamp_) {
      if (stale_) err_ << kProgram << ": new data again, stamped " << toString(stamp) << std::endl;
      stale_ = false;
      newest_stamp_ = stamp;
      newest_changed_ = now_steady;
      return;
    }
    if (stale_ || now_steady - newest_changed_ < kStaleAfter) return;
    stale_ = true;
    err_ << kProgram << ": warning: no new data for '" << options_.frame << "' in '"
         << options_.reference_frame << "' for "
         << fixedDecimals(std::chrono::duration<double>(now_steady - newest_changed_).count(), 1)
         << " s: the pose printed is from " << toString(stamp) << " ("
         << fixedDecimals(toSeconds(now() - stamp), 1)
         << " s old); are its publishers still running?" << std::endl;
  }

  const EchoOptions& options_;
  lcm::LCM& lcm_;
  std::ostream& out_;
  std::ostream& err_;
  Buffer buffer_;
  TransformListener listener_;
  std::optional<TimePoint> newest_stamp_;
  std::chrono::steady_clock::time_point newest_changed_;
  bool stale_ = false;
  bool said_not_finite_ = false;
};

}  // namespace

TimePoint EchoTime::at(TimePoint now) const {
  switch (kind) {
    case Kind::kFixed:
      return fixed;
    case Kind::kBeforeNow:
      return now - before_now;
    case Kind::kLatest:
      break;
  }
  return kLatestTime;
}

EchoTime parseEchoTime(const std::string& text) {
  const double seconds = parseFiniteNumber(text, "--time");
  EchoTime time;
  if (seconds > 0.0) {
    if (seconds > 1e11) throw CommandLineError("--time: '" + text + "' is past the year 5000");
    time.kind = EchoTime::Kind::kFixed;
    time.fixed = fromSeconds(seconds);
  } else if (seconds < 0.0) {
    if (seconds < -86400.0) {
      throw CommandLineError("--time: '" + text + "' is more than a day before now");
    }
    time.kind = EchoTime::Kind::kBeforeNow;
    time.before_now = secondsToDuration(-seconds);
  }
  return time;
}

std::optional<int> parseEchoCommandLine(const std::vector<std::string>& args, EchoOptions& options,
                                        std::ostream& out, std::ostream& err) {
  auto app = makeToolApp(kProgram, kDescription, kExamples);
  std::string time_text;
  double timeout_seconds = 0.0;
  app->add_option("REFERENCE", options.reference_frame, "Frame the pose is expressed in")
      ->required()
      ->check(nonEmptyName());
  app->add_option("FRAME", options.frame, "Frame whose pose is printed")
      ->required()
      ->check(nonEmptyName());
  app->add_option("--rate", options.rate_hz, "Poses printed per second")
      ->check(positiveFiniteNumberUpTo(1000.0))
      ->type_name("HZ")
      ->capture_default_str();
  app->add_option("--time", time_text,
                  "Instant to look up: seconds since the Unix epoch, or negative seconds "
                  "before now (default: the latest data)")
      ->type_name("SECONDS");
  app->add_flag("--once", options.once, "Print one pose, then exit");
  app->add_option("--precision", options.precision, "Digits after the decimal point")
      ->check(CLI::Range(0, 15))
      ->type_name("DIGITS")
      ->capture_default_str();
  auto* timeout =
      app->add_option(
             "--timeout", timeout_seconds,
             "Exit with status 1 if no pose could be printed within this "
             "time (default with --once: " +
                 std::to_string(
                     std::chrono::duration_cast<std::chrono::seconds>(kOnceTimeout).count()) +
                 " s more than the seconds before now of a negative --time; "
                 "else keep waiting)")
          ->check(positiveFiniteNumber())
          ->type_name("SECONDS");
  addConnectionOptions(*app, options.connection);
  addStampAheadOption(*app, options.connection.max_stamp_ahead_s);
  if (auto status = parseCommandLine(*app, args, out, err)) return status;
  try {
    if (!time_text.empty()) options.time = parseEchoTime(time_text);
  } catch (const CommandLineError& e) {
    return reportBadArguments(*app, e.what(), err);
  }
  if (timeout->count() > 0) {
    options.timeout = secondsToDuration(timeout_seconds);
  } else if (options.once) {
    // History begins when the listening does: a moving frame's pose N s ago needs N s of it.
    options.timeout = kOnceTimeout + options.time.before_now;
  }
  return std::nullopt;
}

std::string describeMissing(const BufferCore& buffer, const std::string& reference_frame,
                            const std::string& frame, TimePoint time, bool heard_anything) {
  if (!heard_anything) return "no transforms received yet";
  const std::vector<std::string> known = buffer.getAllFrameNames();
  std::vector<std::string> unknown;
  for (const std::string* name : {&reference_frame, &frame}) {
    if (!buffer.frameExists(*name) &&
        std::find(unknown.begin(), unknown.end(), *name) == unknown.end()) {
      unknown.push_back(*name);
    }
  }
  if (!unknown.empty()) {
    std::string text;
    for (const std::string& name : unknown) {
      text += (text.empty() ? "frame '" : " and frame '") + name + "'" + didYouMean(name, known);
    }
    return text + (unknown.size() == 1 ? " is" : " are") + " unknown; frames heard so far: " +
           (known.empty() ? std::string("none") : listOfNames(unknown.front(), known));
  }
  std::string why;
  if (buffer.canTransform(reference_frame, frame, time, &why)) return "available";
  return why;
}

int runEcho(const EchoOptions& options, lcm::LCM& lcm, std::ostream& out, std::ostream& err,
            const std::atomic<bool>& stop) {
  EchoLoop loop(options, lcm, out, err);
  return loop.run(stop);
}

int echoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                const std::atomic<bool>& stop) {
  return parseOpenAndRun(args, kProgram, out, err, stop, &parseEchoCommandLine, &runEcho);
}

}  // namespace lcmtf::nodes
