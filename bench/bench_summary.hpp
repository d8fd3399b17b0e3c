#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace bench {

// Prints runs as the console reporter does and keeps each benchmark's time and counters: the
// median when repeated, else the best of the runs registered under that name (the most
// lookups per second where a run counts them, else the fastest).
class RecordingReporter : public benchmark::ConsoleReporter {
 public:
  struct Result {
    double real_time = 0;
    benchmark::UserCounters counters;
  };

  RecordingReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (run.error_occurred || (run.run_type == Run::RT_Aggregate && !median)) continue;
      std::string name = run.run_name.function_name;
      if (!run.run_name.args.empty()) name += "/" + run.run_name.args;
      const Result result{run.GetAdjustedRealTime(), run.counters};
      const auto [kept, first] = results_.try_emplace(name, result);
      if (!first && (median || better(result, kept->second))) kept->second = result;
    }
  }

  static bool better(const Result& a, const Result& b) {
    const auto a_rate = a.counters.find("lookups_per_s");
    const auto b_rate = b.counters.find("lookups_per_s");
    if (a_rate != a.counters.end() && b_rate != b.counters.end()) {
      return a_rate->second.value > b_rate->second.value;
    }
    return a.real_time < b.real_time;
  }

  const Result* find(const std::string& name) const {
    const auto found = results_.find(name);
    return found == results_.end() ? nullptr : &found->second;
  }

 private:
  std::map<std::string, Result> results_;
};

inline double counter(const RecordingReporter::Result* result, const char* name) {
  if (!result) return NAN;
  const auto found = result->counters.find(name);
  return found == result->counters.end() ? NAN : found->second.value;
}

inline void printSummary(const RecordingReporter& reporter) {
  struct Row {
    const char* label;
    const char* ours;
    const char* theirs;
    double target;
  };
  static const Row kRows[] = {
      {"insert", "insert", "insert", 5},
      {"lookup, random pair and time", "lookup_random", "lookup_random", 10},
      {"lookup at t = 0 (latest)", "lookup_latest", "lookup_latest", 10},
      {"lookup, root <-> deepest leaf", "lookup_deepest", "lookup_deepest", 10},
      {"time-travel lookup", "lookup_time_travel", "lookup_time_travel", 10},
      {"canTransform", "can_transform", "can_transform", 10},
      {"lookup by FrameHandle (tf2: by name)", "lookup_by_handle", "lookup_random", 10},
      {"  ... into a reused result", "lookup_by_handle_into", "lookup_random", 10},
  };
  auto time = [&](const std::string& name) {
    const RecordingReporter::Result* result = reporter.find(name);
    return result ? result->real_time : NAN;
  };
  std::printf("\n%-38s %10s %10s %10s %8s\n", "ns per call (fastest round)", "lcmtf", "tf2",
              "tf2/lcmtf", "target");
  for (const Row& row : kRows) {
    const double ours = time(std::string("lcmtf/") + row.ours);
    const double theirs = time(std::string("tf2/") + row.theirs);
    if (std::isnan(ours)) continue;
    if (std::isnan(theirs)) {
      std::printf("%-38s %10.1f %10s\n", row.label, ours, "-");
      continue;
    }
    std::printf("%-38s %10.1f %10.1f %10.2f %7.0fx %s\n", row.label, ours, theirs, theirs / ours,
                row.target, theirs / ours >= row.target ? "met" : "MISSED");
  }
  for (const char* library : {"lcmtf", "tf2"}) {
    const std::string prefix = std::string(library) + "/";
    const double bytes = counter(reporter.find(prefix + "memory"), "bytes_per_sample");
    const double one =
        counter(reporter.find(prefix + "lookups_with_writer/readers:1"), "lookups_per_s");
    const double two =
        counter(reporter.find(prefix + "lookups_with_writer/readers:2"), "lookups_per_s");
    if (!std::isnan(bytes))
      std::printf("%-6s heap per stored sample: %.1f bytes\n", library, bytes);
    if (!std::isnan(one) && !std::isnan(two)) {
      std::printf(
          "%-6s lookups/s with a writer: 1 reader %.3g, 2 readers %.3g, 2/1 = %.2f (target 1.8)\n",
          library, one, two, two / one);
    }
  }
}

}  // namespace bench
