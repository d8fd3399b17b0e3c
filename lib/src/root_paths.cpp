#include "root_paths.hpp"

#include <algorithm>

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
    if (step.next != step.parent) step.anchor = &frames[step.parent].static_top_T_frame;
  }
  return step;
}

// Each frame's path is its own step followed by a copy of the path of the frame that step
// reaches, so frames are settled from the top down: a climb stops at the first frame whose
// path is known, or at a root, and the frames it passed are filled in on the way back.
void RootPaths::rebuild(const std::vector<FrameRecord>& frames) {
  entries_.clear();
  steps_.clear();
  built_for_ = frames.data();
  settleFrom(frames, 1);
}

void RootPaths::extend(const std::vector<FrameRecord>& frames) {
  settleFrom(frames, static_cast<FrameId>(std::max<std::size_t>(entries_.size(), 1)));
}

void RootPaths::settleFrom(const std::vector<FrameRecord>& frames, FrameId first) {
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
      entry.offset = static_cast<std::uint32_t>(steps_.size());
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
      steps_.push_back(step);
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
