#include "lcmtf/nodes/chain_delay.hpp"

#include <algorithm>

#include "lcmtf/frame_name.hpp"
#include "lcmtf/programs/closest_names.hpp"

namespace lcmtf::nodes {

using programs::didYouMean;

ChainDelayMeter::ChainDelayMeter(const BufferCore& buffer, std::string frame_a, std::string frame_b)
    : buffer_(buffer), frame_a_(std::move(frame_a)), frame_b_(std::move(frame_b)) {}

void ChainDelayMeter::onBatch(const tf_message_t& batch, bool is_static, TimePoint received) {
  if (is_static) return;
  std::vector<std::string> chain;
  TimePoint latest;
  try {
    chain = buffer_.getFrameChain(frame_b_, frame_a_);
    latest = buffer_.getLatestCommonTime(frame_b_, frame_a_);
  } catch (const TransformException&) {
    return;  // not connected yet: report() says why
  }
  if (latest == kLatestTime) return;  // every edge static
  const std::set<std::string> on_chain(chain.begin(), chain.end());
  const bool touches_chain = std::any_of(
      batch.transforms.begin(), batch.transforms.end(), [&on_chain](const transform_t& edge) {
        return on_chain.count(std::string(canonicalFrameName(edge.child_frame))) &&
               on_chain.count(std::string(canonicalFrameName(edge.parent_frame)));
      });
  if (!touches_chain) return;
  const double delay = toSeconds(received - latest);
  delay_max_s_ = samples_ == 0 ? delay : std::max(delay_max_s_, delay);
  delay_sum_s_ += delay;
  ++samples_;
}

ChainReport ChainDelayMeter::report() const {
  ChainReport report;
  report.frame_a = frame_a_;
  report.frame_b = frame_b_;
  try {
    report.frames = buffer_.getFrameChain(frame_b_, frame_a_);
  } catch (const TransformException& e) {
    report.problem = e.what();
    const std::vector<std::string> known = buffer_.getAllFrameNames();
    for (const std::string* frame : {&frame_a_, &frame_b_}) {
      if (buffer_.frameExists(*frame)) continue;
      const std::string suggestion = didYouMean(*frame, known);
      if (!suggestion.empty()) report.problem += "; '" + *frame + "'" + suggestion;
    }
  }
  report.samples = samples_;
  report.average_delay_s = samples_ ? delay_sum_s_ / static_cast<double>(samples_) : 0.0;
  report.max_delay_s = delay_max_s_;
  return report;
}

void ChainDelayMeter::reset() {
  samples_ = 0;
  delay_sum_s_ = 0.0;
  delay_max_s_ = 0.0;
}

}  // namespace lcmtf::nodes
