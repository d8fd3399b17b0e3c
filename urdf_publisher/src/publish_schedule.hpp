#pragma once

#include <cstdint>

#include "lcmtf/programs/saturating.hpp"

namespace lcmtf::urdf {

/// When a joint is next due under a rate cap, on the stamps of its joint states. Due times
/// advance by whole periods, so jittery input still averages the capped rate; a stamp that
/// goes back (a log replayed again) or skips a whole period starts the schedule afresh.
class PublishSchedule {
 public:
  bool due(std::int64_t stamp, std::int64_t period) const {
    return !started_ || stamp >= next_due_ || stamp < last_ || period <= 0;
  }

  void published(std::int64_t stamp, std::int64_t period) {
    if (!started_ || stamp < last_ || stamp >= plus(next_due_, period)) {
      next_due_ = plus(stamp, period);
    } else if (stamp >= next_due_) {
      next_due_ = plus(next_due_, period);
    }
    started_ = true;
    last_ = stamp;
  }

 private:
  // Stamps come from the network and may be anything.
  static constexpr std::int64_t plus(std::int64_t a, std::int64_t b) {
    return programs::saturatingAdd(a, b);
  }

  bool started_ = false;
  std::int64_t next_due_ = 0;
  std::int64_t last_ = 0;
};

}  // namespace lcmtf::urdf
