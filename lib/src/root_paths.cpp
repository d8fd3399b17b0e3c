#include "root_paths.hpp"

namespace lcmtf {

RootStep stepFrom(const std::vector<FrameRecord>& frames, FrameId frame) {
  const FrameRecord& record = frames[frame];
  RootStep step;
  step.child = frame;
  if (record.static_top != frame) {
    step.fixed = &record.static_top_T_frame;
    step.parent = step.next = record.static_top;
    return step;
  }
  if (record.cache.isStatic()) {
    step.fixed = &record.cache.staticValue().transform;
    step.parent = step.next = record.cache.staticValue().parent;
    return step;
  }
  step.cache = &record.cache;
  step.parent = step.next = record.cache.newestParent();
  if (step.parent != kNoFrame) {
    step.next = frames[step.parent].static_top;
    step.anchored = step.next != step.parent;
  }
  return step;
}

// Each frame's path is its own step followed by a copy of the path of the frame that step
// reaches, so frames are settled from the top down: a climb stops at the first frame whose
// path is known, or at a root, and the frames it passed are filled in on the way back.
void RootPaths::rebuild(const std::vector<FrameRecord>& frames) {
  enum class State : std::uint8_t { kUnseen, kClimbing, kDone };
  std::vector<State> state(frames.size(), State::kUnseen);
  std::vector<RootStep> own(frames.size());
  entries_.assign(frames.size(), Entry{});
  steps_.clear();
  built_for_ = frames.data();
  std::vector<FrameId> climb;
  for (FrameId start = 1; start < frames.size(); ++start) {
    FrameId frame = start;
    while (state[frame] == State::kUnseen) {
      state[frame] = State::kClimbing;
      climb.push_back(frame);
      own[frame] = stepFrom(frames, frame);
      if (own[frame].next == kNoFrame) break;
      frame = own[frame].next;
    }
    // Reaching a frame of this same climb again means a loop: no frame of the climb has a root.
    const bool looped = state[frame] == State::kClimbing && own[frame].next != kNoFrame;
    for (auto it = climb.rbegin(); it != climb.rend(); ++it) {
      const FrameId child = *it;
      state[child] = State::kDone;
      Entry& entry = entries_[child];
      if (looped) continue;
      entry.offset = static_cast<std::uint32_t>(steps_.size());
      entry.usable = true;
      if (own[child].next == kNoFrame) {
        entry.root = child;
        continue;
      }
      const Entry above = entries_[own[child].next];
      if (!above.usable) {
        entry.usable = false;
        continue;
      }
      steps_.push_back(own[child]);
      for (std::uint32_t i = 0; i < above.size; ++i) {
        const RootStep copy = steps_[above.offset + i];
        steps_.push_back(copy);
      }
      entry.size = above.size + 1;
      entry.root = above.root;
    }
    climb.clear();
  }
}

}  // namespace lcmtf
