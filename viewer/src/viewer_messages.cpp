#include "lcmtf_viewer/viewer_messages.hpp"

#include <nlohmann/json.hpp>

#include "lcmtf_viewer/json_text.hpp"

#include "lcmtf_viewer/page_messages.hpp"

namespace lcmtf::viewer {

using nlohmann::json;

std::string helloMessage(const HelloFacts& facts) {
  return jsonText(json{{"type", "hello"},
                       {"version", facts.version},
                       {"fixed_frame", facts.fixed_frame},
                       {"update_hz", facts.update_hz},
                       {"joint_states_channel", facts.joint_states_channel},
                       {"max_message_bytes", kMaxPageMessageBytes}});
}

std::string robotMessage(const RobotView* robot) {
  return jsonText(json{{"type", "robot"}, {"robot", robot ? robot->robot : json(nullptr)}});
}

std::string treeMessage(const FrameForest& forest, Duration stale_after) {
  json frames = json::array();
  for (const EdgeDescription& edge : forest.edges) {
    const double age_s = edge.is_static ? 0.0 : toSeconds(forest.now - edge.newest);
    frames.push_back({{"name", edge.child},
                      {"parent", edge.parent},
                      {"authority", edge.authority},
                      {"static", edge.is_static},
                      {"rate_hz", edge.rate_hz},
                      {"age_s", age_s},
                      {"stale", !edge.is_static && forest.now - edge.newest > stale_after}});
  }
  return jsonText(json{{"type", "tree"}, {"frames", std::move(frames)}, {"roots", forest.roots}});
}

std::string jointsMessage(bool publishing, const std::map<std::string, double>& positions) {
  return jsonText(json{{"type", "joints"}, {"publishing", publishing}, {"positions", positions}});
}

std::string errorMessage(const std::string& text) {
  return jsonText(json{{"type", "error"}, {"message", text}});
}

}  // namespace lcmtf::viewer
