#pragma once

// The closing table of buffer_core_bench: for each tree shape, lcmtf against tf2 call by call,
// each library's fastest round with the spread over its rounds, and the targets.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_summary.hpp"

namespace bench {

namespace detail {

struct SummaryRow {
  const char* label;
  const char* ours;
  const char* theirs;
  double target;         // tf2 / lcmtf at least this; 0 for none
  double forest_target;  // the same on the 100,000-frame forest
};

constexpr SummaryRow kSummaryRows[] = {
    {"insert", "insert", "insert", 5, 5},
    {"lookup, random pair and time", "lookup_random", "lookup_random", 10, 3},
    {"lookup at t = 0 (latest)", "lookup_latest", "lookup_latest", 10, 3},
    {"lookup, root <-> deepest leaf", "lookup_deepest", "lookup_deepest", 10, 3},
    {"time-travel lookup", "lookup_time_travel", "lookup_time_travel", 10, 3},
    {"canTransform", "can_transform", "can_transform", 15, 3},
    {"lookup by FrameHandle (tf2: by name)", "lookup_by_handle", "lookup_random", 0, 0},
    {"  ... into a reused result", "lookup_by_handle_into", "lookup_random", 0, 0},
    {"adding a frame", "add_frames", "add_frames", 2, 2},
};

// (slowest - fastest) / fastest over the rounds, in percent.
inline double spreadPercent(const RecordingReporter::Result& result) {
  return 100.0 * (result.slowest_time - result.real_time) / result.real_time;
}

inline void printShapeRows(const RecordingReporter& reporter, const std::string& shape, bool forest,
                           double memory_latency_ns) {
  std::printf("\n%-38s %9s %7s %9s %7s %9s %7s\n", (shape + ": ns per call").c_str(), "lcmtf",
              "spread", "tf2", "spread", "tf2/lcmtf", "target");
  for (const SummaryRow& row : kSummaryRows) {
    const RecordingReporter::Result* ours = reporter.find("lcmtf/" + shape + "/" + row.ours);
    const RecordingReporter::Result* theirs = reporter.find("tf2/" + shape + "/" + row.theirs);
    if (!ours) continue;
    if (!theirs) {
      std::printf("%-38s %9.1f %6.1f%%\n", row.label, ours->real_time, spreadPercent(*ours));
      continue;
    }
    const double ratio = theirs->real_time / ours->real_time;
    const double target = forest ? row.forest_target : row.target;
    std::printf("%-38s %9.1f %6.1f%% %9.1f %6.1f%% %9.2f", row.label, ours->real_time,
                spreadPercent(*ours), theirs->real_time, spreadPercent(*theirs), ratio);
    if (target > 0) std::printf(" %6.0fx %s", target, ratio >= target ? "met" : "MISSED");
    if (forest && memory_latency_ns > 0 && std::string(row.ours).rfind("lookup", 0) == 0) {
      std::printf("  (%.1f memory latencies)", ours->real_time / memory_latency_ns);
    }
    std::printf("\n");
  }
  const RecordingReporter::Result* ours_adding = reporter.find("lcmtf/" + shape + "/add_frames");
  const RecordingReporter::Result* theirs_adding = reporter.find("tf2/" + shape + "/add_frames");
  if (ours_adding) {
    std::printf("page faults per frame added (fastest round): lcmtf %.3f, tf2 %.3f\n",
                counter(ours_adding, "page_faults_per_frame"),
                counter(theirs_adding, "page_faults_per_frame"));
    std::printf("time in the kernel per frame added (same round): lcmtf %.0f ns, tf2 %.0f ns\n",
                counter(ours_adding, "kernel_ns_per_frame"),
                counter(theirs_adding, "kernel_ns_per_frame"));
  }
  const RecordingReporter::Result* ours_memory = reporter.find("lcmtf/" + shape + "/memory");
  const RecordingReporter::Result* theirs_memory = reporter.find("tf2/" + shape + "/memory");
  const double ours_sample = counter(ours_memory, "bytes_per_sample");
  const double theirs_sample = counter(theirs_memory, "bytes_per_sample");
  const double ours_frame = counter(ours_memory, "bytes_per_frame");
  const double theirs_frame = counter(theirs_memory, "bytes_per_frame");
  if (!std::isnan(ours_sample)) {
    std::printf(
        "heap per stored sample: lcmtf %.1f B, tf2 %.1f B (target: no more than tf2's; "
        "aim 64 B) %s\n",
        ours_sample, theirs_sample, ours_sample <= theirs_sample ? "met" : "MISSED");
    std::printf("heap per frame:         lcmtf %.0f B, tf2 %.0f B%s\n", ours_frame, theirs_frame,
                forest ? (ours_frame <= theirs_frame ? " (target: no more than tf2's) met"
                                                     : " (target: no more than tf2's) MISSED")
                       : "");
  }
}

}  // namespace detail

/// `memory_latency_ns` is the time of a load that misses every cache (memory_latency.hpp): the
/// lookups in the forest, far larger than the caches, are given in those too.
inline void printSummary(const RecordingReporter& reporter, const std::vector<std::string>& shapes,
                         double memory_latency_ns) {
  std::printf(
      "\nEach figure is the fastest of the alternating rounds; spread is how much slower "
      "the slowest round was.\n");
  for (const std::string& shape : shapes) {
    detail::printShapeRows(reporter, shape, shape == shapes.back(), memory_latency_ns);
  }
  std::printf(
      "\nA load that misses every cache takes %.1f ns here (a pointer chase through 256 "
      "MB).\n",
      memory_latency_ns);
  std::printf("\n");
  for (const char* library : {"lcmtf", "tf2"}) {
    const std::string prefix = std::string(library) + "/" + shapes.front() + "/";
    const double one =
        counter(reporter.find(prefix + "lookups_with_writer/readers:1"), "lookups_per_s");
    const double two =
        counter(reporter.find(prefix + "lookups_with_writer/readers:2"), "lookups_per_s");
    if (!std::isnan(one) && !std::isnan(two)) {
      std::printf(
          "%-6s lookups/s with a writer (%s): 1 reader %.3g, 2 readers %.3g, 2/1 = %.2f "
          "(target 1.8)\n",
          library, shapes.front().c_str(), one, two, two / one);
    }
  }
}

}  // namespace bench
