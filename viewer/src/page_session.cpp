#include "lcmtf_viewer/page_session.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "lcmtf_viewer/json_text.hpp"

namespace lcmtf::viewer {

namespace {

using nlohmann::json;

// Below this a pose is the same as drawn: a micrometre, or a microradian's worth of quaternion.
constexpr double kUnchanged = 1e-6;

bool samePose(const FramePose& a, const FramePose& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::abs(a[i] - b[i]) > kUnchanged) return false;
  }
  return true;
}

json treesJson(const std::vector<UnconnectedTree>& trees) {
  json list = json::array();
  for (const UnconnectedTree& tree : trees)
    list.push_back({{"root", tree.root}, {"frames", tree.frames}});
  return list;
}

}  // namespace

void PageSession::view(const std::string& fixed_frame, std::optional<TimePoint> paused_at) {
  fixed_frame_ = fixed_frame;
  paused_at_ = paused_at;
  next_is_full_ = true;
}

bool PageSession::acknowledge(std::int64_t seq) {
  if (!awaiting_ack_ || seq != seq_) return false;
  awaiting_ack_ = false;
  return true;
}

std::optional<std::string> PageSession::sceneMessage(const SceneSnapshot& scene,
                                                     TimePoint history_oldest,
                                                     TimePoint history_newest) {
  const bool full = next_is_full_ || scene.fixed_frame != sent_fixed_frame_;
  json poses = json::object();
  json removed = json::array();
  for (const auto& [frame, pose] : scene.poses) {
    const auto sent = sent_poses_.find(frame);
    if (full || sent == sent_poses_.end() || !samePose(sent->second, pose)) {
      poses[frame] = pose;
      sent_poses_[frame] = pose;
    }
  }
  for (auto sent = sent_poses_.begin(); sent != sent_poses_.end();) {
    if (scene.poses.count(sent->first)) {
      ++sent;
      continue;
    }
    if (!full) removed.push_back(sent->first);
    sent = sent_poses_.erase(sent);
  }
  const bool unconnected_changed = full || scene.unconnected != sent_unconnected_;
  const bool stale_changed = full || scene.stale != sent_stale_;
  const bool time_changed =
      scene.time != sent_time_ || history_oldest != sent_oldest_ || history_newest != sent_newest_;
  if (!full && poses.empty() && removed.empty() && !unconnected_changed && !stale_changed &&
      !time_changed) {
    return std::nullopt;
  }
  json message = {
      {"type", "scene"},
      {"seq", ++seq_},
      {"full", full},
      {"fixed_frame", scene.fixed_frame},
      {"live", scene.live},
      {"time", toUtime(scene.time)},
      {"history", {{"oldest", toUtime(history_oldest)}, {"newest", toUtime(history_newest)}}},
      {"poses", std::move(poses)},
      {"removed", std::move(removed)},
      {"unconnected", treesJson(scene.unconnected)},
      {"stale", scene.stale}};
  next_is_full_ = false;
  awaiting_ack_ = true;
  sent_fixed_frame_ = scene.fixed_frame;
  sent_time_ = scene.time;
  sent_oldest_ = history_oldest;
  sent_newest_ = history_newest;
  sent_unconnected_ = scene.unconnected;
  sent_stale_ = scene.stale;
  return jsonText(message);
}

}  // namespace lcmtf::viewer
