#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/tf_message_t.hpp"

namespace lcmtf::nodes {

/// The chain between two frames and how stale its newest data is when it arrives.
struct ChainReport {
  std::string frame_a;
  std::string frame_b;
  std::vector<std::string> frames;  ///< from frame_a through the common ancestor to frame_b
  std::string problem;              ///< why there is no chain (empty when there is one)
  std::size_t samples = 0;          ///< arrivals of the chain's dynamic edges measured
  double average_delay_s = 0.0;
  double max_delay_s = 0.0;
};

/// The net delay of a chain: at each arrival of one of its dynamic edges, the receive time
/// minus the latest time at which every edge of the chain has data.
class ChainDelayMeter {
 public:
  /// Reads `buffer`, which must already hold each batch passed to onBatch.
  ChainDelayMeter(const BufferCore& buffer, std::string frame_a, std::string frame_b);

  void onBatch(const tf_message_t& batch, bool is_static, TimePoint received);
  /// The chain as it is now, with the delays measured since the last reset.
  ChainReport report() const;
  void reset();

 private:
  const BufferCore& buffer_;
  std::string frame_a_;
  std::string frame_b_;
  std::size_t samples_ = 0;
  double delay_sum_s_ = 0.0;
  double delay_max_s_ = 0.0;
};

}  // namespace lcmtf::nodes
