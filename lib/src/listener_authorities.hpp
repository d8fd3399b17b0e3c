#pragma once

#include <algorithm>
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
#include "name_hash.hpp"

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

/// The senders a listener follows, at most `capacity` of them. A name heard once waits on
/// probation; heard again, it is established. A new name when full forgets the name on probation
/// heard least recently (an established one only when none is on probation), so a flood of names
/// used once each never makes the listener forget a sender it keeps hearing. Finding a sender
/// costs one hash of its name.
class ListenerAuthorities {
 public:
  explicit ListenerAuthorities(std::size_t capacity)
      : capacity_(std::max<std::size_t>(capacity, 1)),
        most_established_(std::max<std::size_t>(capacity_ - capacity_ / 4, 1)) {}

  /// The sender named `name`, now the most recently heard; new ones start empty. Sets
  /// `forgot_one` when another had to be forgotten to make room.
  HeardAuthority& hear(const std::string& name, bool& forgot_one) {
    const auto found = index_.find(name);
    if (found != index_.end()) {
      established_.splice(established_.begin(),
                          found->second.established ? established_ : probation_,
                          found->second.node);
      found->second.established = true;
      if (established_.size() > most_established_) demoteLeastRecent();
      return established_.front();
    }
    if (size() >= capacity_) {
      std::list<HeardAuthority>& victims = probation_.empty() ? established_ : probation_;
      index_.erase(victims.back().statistics.authority);
      victims.back() = HeardAuthority{};  // the list node is reused for the newcomer
      probation_.splice(probation_.begin(), victims, std::prev(victims.end()));
      forgot_one = true;
    } else {
      probation_.emplace_front();
    }
    HeardAuthority& heard = probation_.front();
    heard.statistics.authority = name;
    index_.emplace(heard.statistics.authority, Place{probation_.begin(), false});
    return heard;
  }

  std::size_t size() const { return established_.size() + probation_.size(); }

  /// Calls `visit` on every sender followed: the established ones first, each group the most
  /// recently heard first.
  template <class Visit>
  void forEach(Visit visit) const {
    for (const HeardAuthority& heard : established_) visit(heard);
    for (const HeardAuthority& heard : probation_) visit(heard);
  }

 private:
  struct Place {
    std::list<HeardAuthority>::iterator node;
    bool established = false;
  };

  void demoteLeastRecent() {
    const auto last = std::prev(established_.end());
    index_.find(last->statistics.authority)->second.established = false;
    probation_.splice(probation_.begin(), established_, last);
  }

  std::size_t capacity_;
  std::size_t most_established_;
  std::list<HeardAuthority> established_;  // the most recently heard first
  std::list<HeardAuthority> probation_;    // the most recently heard first
  // Keys view the names held in the lists' nodes, which never move.
  std::unordered_map<std::string_view, Place, NameHash> index_;
};

}  // namespace lcmtf::detail
