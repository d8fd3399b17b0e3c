#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "lcmtf/sequence_tracker.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/time.hpp"

namespace lcmtf::nodes {

/// Bounds on what TfTraffic keeps, so that a flood of names or messages cannot exhaust memory.
struct TrafficLimits {
  std::size_t max_edges = 10000;
  std::size_t max_authorities = 1000;
  std::size_t max_arrivals_per_edge = 200000;
  std::size_t max_arrivals = 5000000;  ///< over all edges (about 120 MB)
};

/// One edge parent -> child as heard in a window.
struct EdgeTraffic {
  std::string parent;
  std::string child;
  bool is_static = false;
  std::vector<std::string> authorities;  ///< every sender, the most frequent first
  std::size_t samples = 0;               ///< transforms received in the window
  double rate_hz = 0.0;                  ///< samples per second between the first and last
  double average_delay_s = 0.0;          ///< receive time minus stamp (dynamic edges only)
  double max_delay_s = 0.0;
  TimePoint oldest_stamp;  ///< of the history a Buffer would hold
  TimePoint newest_stamp;
  std::size_t buffered = 0;  ///< distinct stamps within the cache time behind the newest
  TimePoint last_received;   ///< when the last of the window's samples arrived
};

/// One sender as heard in a window.
struct AuthorityTraffic {
  std::string authority;
  std::size_t messages = 0;         ///< batches received
  double rate_hz = 0.0;             ///< batches per second between the first and last
  std::size_t dynamic_samples = 0;  ///< dynamic transforms, over which delays are taken
  double average_delay_s = 0.0;
  double max_delay_s = 0.0;
  std::vector<std::string> frames;  ///< child frames it sent
  SequenceCounts sequence;          ///< numbered batches lost, reordered, duplicated since start
};

/// A child frame sent by more than one authority in the window: one line per sender.
struct FrameConflict {
  std::string child;
  std::vector<std::string> senders;  ///< "'alpha' (parent 'odom', dynamic, 120 transforms)",
                                     ///< the sender heard most first
};

/// What was heard between `window_start` and `window_end`; the counts run from the start.
struct TrafficSummary {
  TimePoint window_start;
  TimePoint window_end;
  std::vector<EdgeTraffic> edges;  ///< sorted by child, then parent
  std::vector<AuthorityTraffic> authorities;
  std::vector<FrameConflict> conflicts;
  std::uint64_t messages = 0;            ///< batches decoded
  std::uint64_t malformed = 0;           ///< messages that did not decode
  std::uint64_t invalid_transforms = 0;  ///< empty or self-parented names, NaN, bad quaternion
  std::uint64_t refused = 0;             ///< transforms beyond the limits
  std::vector<std::string> problems;     ///< the first of each kind above, described
};

/// Records every transform heard with its receive time and sums it up per edge, per sender
/// and per frame. No I/O: the caller says when each batch was received.
class TfTraffic {
 public:
  explicit TfTraffic(TrafficLimits limits = {});

  /// Records a decoded batch received at `received`.
  void record(const tf_message_t& batch, bool is_static, TimePoint received);
  /// Counts a message that did not decode; the first is kept as a problem.
  void recordMalformed(const std::string& channel, const std::string& error);
  /// Forgets arrivals received before `cutoff` (a sliding window).
  void forgetBefore(TimePoint cutoff);

  /// Rates and delays over arrivals in [window_start, window_end]; `cache_time` is the
  /// history a Buffer keeps, for EdgeTraffic::buffered.
  TrafficSummary summarize(TimePoint window_start, TimePoint window_end, Duration cache_time) const;

 private:
  struct Arrival {
    std::int64_t received;
    std::int64_t stamp;
    std::uint32_t authority;
  };
  struct Edge {
    std::string parent;
    std::string child;
    bool is_static = false;
    std::deque<Arrival> arrivals;
  };
  struct Sender {
    std::string name;
    std::deque<std::int64_t> batches_received;
    SequenceTracker dynamic_sequence;
    SequenceTracker static_sequence;
  };

  struct WindowTally;  // per-sender delays and frames, per-frame senders, in one pass

  bool validate(const transform_t& transform, const std::string& authority);
  void noteProblem(const std::string& kind, const std::string& description);
  EdgeTraffic summarizeEdge(const Edge& edge, std::int64_t start, std::int64_t end,
                            Duration cache_time, WindowTally& tally) const;
  AuthorityTraffic summarizeSender(std::uint32_t id, std::int64_t start, std::int64_t end,
                                   const WindowTally& tally) const;
  std::vector<FrameConflict> findConflicts(const WindowTally& tally) const;

  TrafficLimits limits_;
  std::map<std::tuple<std::string, std::string, bool>, Edge> edges_;  // (child, parent, static)
  std::vector<Sender> senders_;
  std::size_t arrivals_ = 0;  // over all edges
  std::map<std::string, std::uint32_t> sender_ids_;
  std::uint64_t messages_ = 0;
  std::uint64_t malformed_ = 0;
  std::uint64_t invalid_ = 0;
  std::uint64_t refused_ = 0;
  std::map<std::string, std::string> problems_;  // first description of each kind
};

}  // namespace lcmtf::nodes
