#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
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
    double slowest_time = 0;  // the slowest of the runs registered under the name
  };

  RecordingReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      if (run.error_occurred || (run.run_type == Run::RT_Aggregate && !median)) continue;
      std::string name = run.run_name.function_name;
      if (!run.run_name.args.empty()) name += "/" + run.run_name.args;
      const Result result{run.GetAdjustedRealTime(), run.counters, run.GetAdjustedRealTime()};
      const auto [kept, first] = results_.try_emplace(name, result);
      if (first) continue;
      const double slowest = std::max(kept->second.slowest_time, result.real_time);
      if (median || better(result, kept->second)) kept->second = result;
      kept->second.slowest_time = slowest;
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

}  // namespace bench
