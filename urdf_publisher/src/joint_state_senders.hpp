#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lcmtf/sequence_tracker.hpp"

namespace lcmtf::urdf {

/// The numbering of each sender of joint states (joint_state_t::authority), for at most
/// `capacity` senders: a new one when full takes the place of the one heard least recently.
class JointStateSenders {
 public:
  explicit JointStateSenders(std::size_t capacity = 64) : capacity_(capacity) {}

  /// Notes a joint state's number; returns the change in the counts over all senders (the
  /// unsigned differences wrap, so adding them keeps a total exact when a loss is taken back).
  SequenceCounts observe(const std::string& authority, std::int64_t sequence) {
    Sender& sender = find(authority);
    const SequenceCounts before = sender.sequence.counts();
    sender.sequence.observe(sequence);
    const SequenceCounts& after = sender.sequence.counts();
    SequenceCounts change;
    change.lost = after.lost - before.lost;
    change.reordered = after.reordered - before.reordered;
    change.duplicated = after.duplicated - before.duplicated;
    change.restarts = after.restarts - before.restarts;
    return change;
  }

 private:
  struct Sender {
    std::string authority;
    SequenceTracker sequence;
    std::uint64_t last_heard = 0;
  };

  Sender& find(const std::string& authority) {
    ++clock_;
    Sender* oldest = nullptr;
    for (Sender& sender : senders_) {  // a few senders: a scan beats a map
      if (sender.authority == authority) {
        sender.last_heard = clock_;
        return sender;
      }
      if (!oldest || sender.last_heard < oldest->last_heard) oldest = &sender;
    }
    if (senders_.size() < capacity_ || !oldest) {
      senders_.push_back({authority, {}, clock_});
      return senders_.back();
    }
    *oldest = Sender{authority, {}, clock_};
    return *oldest;
  }

  std::size_t capacity_;
  std::vector<Sender> senders_;
  std::uint64_t clock_ = 0;
};

}  // namespace lcmtf::urdf
