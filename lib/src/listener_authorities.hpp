#pragma once

#include <chrono>
#include <cstdint>
#include <list>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lcmtf/sequence_tracker.hpp"
#include "lcmtf/transform_listener.hpp"

namespace lcmtf::detail {

/// What a listener keeps about one sender.
struct HeardAuthority {
  AuthorityStatistics statistics;  // names the sender
  SequenceTracker dynamic_sequence;
  SequenceTracker static_sequence;
  std::optional<std::int64_t> newest;  // stamp, on the dynamic channel
  int stale_in_a_row = 0;
  std::optional<std::chrono::steady_clock::time_point> last_reset;
  bool reset_reported = false;

  SequenceCounts sequenceCounts() const {
    SequenceCounts counts = dynamic_sequence.counts();
    counts += static_sequence.counts();
    return counts;
  }
};

/// The senders a listener follows, at most `capacity` of them: hearing a new one when full
/// forgets the one heard least recently. Finding a sender costs one hash of its name.
class ListenerAuthorities {
 public:
  explicit ListenerAuthorities(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  /// The sender named `name`, now the most recently heard; new ones start empty. Sets
  /// `forgot_one` when another had to be forgotten to make room.
  HeardAuthority& hear(const std::string& name, bool& forgot_one) {
    const auto found = index_.find(name);
    if (found != index_.end()) {
      by_recency_.splice(by_recency_.begin(), by_recency_, found->second);
      return by_recency_.front();
    }
    if (by_recency_.size() >= capacity_) {
      index_.erase(by_recency_.back().statistics.authority);
      by_recency_.back() = HeardAuthority{};  // the list node is reused for the newcomer
      forgot_one = true;
      by_recency_.splice(by_recency_.begin(), by_recency_, std::prev(by_recency_.end()));
    } else {
      by_recency_.emplace_front();
    }
    HeardAuthority& heard = by_recency_.front();
    heard.statistics.authority = name;
    index_.emplace(heard.statistics.authority, by_recency_.begin());
    return heard;
  }

  std::size_t size() const { return by_recency_.size(); }

  /// Every sender followed, the most recently heard first.
  const std::list<HeardAuthority>& byRecency() const { return by_recency_; }

 private:
  std::size_t capacity_;
  std::list<HeardAuthority> by_recency_;  // the most recently heard first
  // Keys view the names held in by_recency_, whose nodes never move.
  std::unordered_map<std::string_view, std::list<HeardAuthority>::iterator> index_;
};

}  // namespace lcmtf::detail
