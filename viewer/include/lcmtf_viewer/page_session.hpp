#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lcmtf/time.hpp"
#include "lcmtf_viewer/scene_snapshot.hpp"

namespace lcmtf::viewer {

/// One open page's view and what it has been sent, so each scene carries only what changed.
/// No I/O: the hub asks it for messages and passes it the page's answers.
class PageSession {
 public:
  /// The fixed frame the page chose ("" while it has not: the server picks one).
  const std::string& chosenFixedFrame() const { return fixed_frame_; }
  /// The stamp the page paused at; nothing while live.
  std::optional<TimePoint> pausedAt() const { return paused_at_; }

  /// Draw in `fixed_frame` ("" for the server's choice), live or paused; the next scene is
  /// whole.
  void view(const std::string& fixed_frame, std::optional<TimePoint> paused_at);
  /// Whether the last scene sent has been acknowledged (so another may be sent).
  bool readyForScene() const { return !awaiting_ack_; }
  /// Takes an ack; false when it names no scene in flight (it is then ignored).
  bool acknowledge(std::int64_t seq);

  /// The scene message for `scene`, holding only what changed since the last one sent, and
  /// counted as in flight; nothing when nothing changed since (and it is not the first).
  std::optional<std::string> sceneMessage(const SceneSnapshot& scene, TimePoint history_oldest,
                                          TimePoint history_newest);

 private:
  std::string fixed_frame_;
  std::optional<TimePoint> paused_at_;
  bool next_is_full_ = true;
  bool awaiting_ack_ = false;
  std::int64_t seq_ = 0;
  std::string sent_fixed_frame_;
  TimePoint sent_time_;
  TimePoint sent_oldest_;
  TimePoint sent_newest_;
  std::map<std::string, FramePose> sent_poses_;
  std::vector<UnconnectedTree> sent_unconnected_;
  std::vector<std::string> sent_stale_;
};

}  // namespace lcmtf::viewer
