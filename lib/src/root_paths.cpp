#include "root_paths.hpp"

#include <algorithm>

namespace lcmtf {

RootStep stepFrom(const FrameTable& frames, FrameId frame) {
  const FrameRecord& record = frames[frame];
  RootStep step;
  step.child = frame;
  if (record.static_top != frame) {
    step.fixed = &record.static_top_T_frame;
    step.parent = step.next = record.static_top;
    return step;
  }
  if (record.cache.isStatic()) {
    step.fixed = &record.cache.staticTransform();
    step.parent = step.next = record.cache.staticParent();
    return step;
  }
  step.cache = &record.cache;
  step.parent = step.next = record.cache.newestParent();
  if (step.parent != kNoFrame) {
    step.next = frames[step.parent].static_top;
    if (step.next != step.parent) step.anchor = &frames[step.parent].static_top_T_frame;
  }
  return step;
}

// Each frame's path is its own step followed by a copy of the path of the frame that step
// reaches, so frames are settled from the top down: a climb stops at the first frame whose
// path is known, or at a root, and the frames it passed are filled in on the way back.
void RootPaths::rebuild(const FrameTable& frames) {
  entries_.clear();
  step_chunks_.clear();
  last_chunk_size_ = last_chunk_used_ = 0;
  built_for_ = &frames;
  settleFrom(frames, 1);
}

RootStep* RootPaths::allocateSteps(std::size_t count) {
  constexpr std::size_t kFirstChunk = 256;
  constexpr std::size_t kLargestChunk = std::size_t{1} << 16;
  if (step_chunks_.empty() || last_chunk_used_ + count > last_chunk_size_) {
    last_chunk_size_ =
        step_chunks_.empty() ? kFirstChunk : std::min(2 * last_chunk_size_, kLargestChunk);
    last_chunk_size_ = std::max<std::size_t>(last_chunk_size_, count);
    step_chunks_.emplace_back(last_chunk_size_);
    last_chunk_used_ = 0;
  }
  RootStep* const steps = step_chunks_.back().data() + last_chunk_used_;
  last_chunk_used_ += count;
  return steps;
}

void RootPaths::extend(const FrameTable& frames) {
  settleFrom(frames, static_cast<FrameId>(std::max<std::size_t>(entries_.size(), 1)));
}

void RootPaths::settleFrom(const FrameTable& frames, FrameId first) {
  enum class State : std::uint8_t { kUnseen, kClimbing, kDone };
  const std::size_t added = frames.size() > first ? frames.size() - first : 0;
  // Only the frames being settled need a state and a step here.
  std::vector<State> settling(added, State::kUnseen);
  std::vector<RootStep> own(added);
  const auto state = [&](FrameId frame) -> State {
    return frame < first ? State::kDone : settling[frame - first];
  };
  entries_.resize(frames.size());
  std::vector<FrameId> climb;
  for (FrameId start = first; start < frames.size(); ++start) {
    FrameId frame = start;
    while (state(frame) == State::kUnseen) {
      settling[frame - first] = State::kClimbing;
      climb.push_back(frame);
      own[frame - first] = stepFrom(frames, frame);
      if (own[frame - first].next == kNoFrame) break;
      frame = own[frame - first].next;
    }
    // Reaching a frame of this same climb again means a loop: no frame of the climb has a root.
    const bool looped = state(frame) == State::kClimbing && own[frame - first].next != kNoFrame;
    for (auto it = climb.rbegin(); it != climb.rend(); ++it) {
      const FrameId child = *it;
      const RootStep& step = own[child - first];
      settling[child - first] = State::kDone;
      Entry& entry = entries_[child];
      entry = Entry{};
      if (looped) continue;
      entry.usable = true;
      if (step.next == kNoFrame) {
        entry.root = child;
        continue;
      }
      const Entry above = entries_[step.next];
      if (!above.usable || above.size + 1 > kLongestPath) {
        entry.usable = false;
        continue;
      }
      RootStep* const steps = allocateSteps(above.size + 1);
      steps[0] = step;
      std::copy(above.steps, above.steps + above.size, steps + 1);
      entry.steps = steps;
      entry.size = above.size + 1;
      entry.root = above.root;
    }
    climb.clear();
  }
}

}  // namespace lcmtf
