#include "lcmtf_viewer/viewer_hub.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include "lcmtf_viewer/viewer_messages.hpp"

namespace lcmtf::viewer {

namespace {

// A page that sends this many refused messages is closed: it is broken or hostile.
constexpr std::size_t kMostRefusalsPerPage = 100;
constexpr std::uint16_t kPolicyViolation = 1008;

std::string stampText(TimePoint t) { return std::to_string(toUtime(t)); }

}  // namespace

ViewerHub::ViewerHub(const BufferCore& buffer, ServedFiles page_files, HubSettings settings,
                     JointStateSink publish)
    : buffer_(buffer),
      page_files_(std::move(page_files)),
      settings_(std::move(settings)),
      publish_(std::move(publish)) {}

const ServedFile* ViewerHub::findFile(std::string_view target) {
  if (const ServedFile* file = page_files_.find(target)) return file;
  return mesh_files_.find(target);
}

void ViewerHub::pageOpened(const std::shared_ptr<PageLink>& link) {
  Page& page = pages_[link.get()];
  page.link = link;
  page.number = ++pages_ever_;
  ++statistics_.pages_opened;
  const FrameForest forest = readForest(buffer_, now());
  send(page, helloMessage({settings_.version, suggestedFixedFrame(forest), settings_.update_hz,
                           settings_.joint_states_channel}));
  send(page, robotMessage(robot_.get()));
  send(page, jointsMessage(false, {}));
  send(page, treeMessage(forest, settings_.stale_after));
}

void ViewerHub::pageMessage(PageLink& link, std::string_view message, bool is_text) {
  const auto found = pages_.find(&link);
  if (found == pages_.end()) return;
  Page& page = found->second;
  if (!is_text) {
    refuse(page, "binary messages are refused; send JSON text");
    return;
  }
  auto parsed = parsePageMessage(message);
  if (const std::string* why = std::get_if<std::string>(&parsed)) {
    refuse(page, *why);
    return;
  }
  std::visit([&](const auto& request) { handle(page, request); }, std::get<PageMessage>(parsed));
}

void ViewerHub::pageClosed(PageLink& link) { pages_.erase(&link); }

void ViewerHub::serverStopping() { pages_.clear(); }

void ViewerHub::refuse(Page& page, const std::string& why) {
  ++statistics_.messages_refused;
  send(page, errorMessage(why));
  if (++page.refused == kMostRefusalsPerPage) {
    ++statistics_.pages_closed_for_refusals;
    page.link->close(kPolicyViolation, "too many refused messages");
  }
}

void ViewerHub::send(Page& page, std::string text) {
  page.link->send(std::make_shared<const std::string>(std::move(text)));
}

void ViewerHub::handle(Page& page, const AckMessage& ack) {
  if (!page.session.acknowledge(ack.seq)) {
    refuse(page, "ack.seq: no scene " + std::to_string(ack.seq) + " is waiting to be drawn");
  }
}

void ViewerHub::handle(Page& page, const ViewMessage& view) {
  std::optional<TimePoint> paused_at;
  if (view.time_us) {
    paused_at = fromUtime(*view.time_us);
    const FrameForest forest = readForest(buffer_, now());
    if (forest.newest == TimePoint() || *paused_at < forest.oldest || *paused_at > forest.newest) {
      refuse(page, "view.time: " + std::to_string(*view.time_us) + " is outside the history [" +
                       stampText(forest.oldest) + ", " + stampText(forest.newest) + "]");
      return;
    }
  }
  page.session.view(view.fixed_frame, paused_at);
}

void ViewerHub::handle(Page& page, const JointsMessage& joints) {
  if (!robot_ && !joints.positions.empty()) {
    refuse(page, "joints.positions: no robot is loaded");
    return;
  }
  std::map<std::string, double> positions;
  for (const auto& [name, value] : joints.positions) {
    const auto limits = slider_limits_.find(name);
    if (limits == slider_limits_.end()) {
      refuse(page, "joints.positions: '" + name.substr(0, 64) +
                       "' is not a joint the sliders move (movable, following no other) of '" +
                       robot_->robot.value("name", std::string()) + "'");
      return;
    }
    positions[name] = std::clamp(value, limits->second.first, limits->second.second);
  }
  for (const auto& [name, value] : positions) page.positions[name] = value;
  page.sliders_on = joints.enabled;
  send(page, jointsMessage(page.sliders_on, page.positions));
  if (page.sliders_on) publishJointsOf(page);
}

void ViewerHub::setRobot(std::shared_ptr<const RobotView> robot) {
  robot_ = std::move(robot);
  mesh_files_ = ServedFiles();
  slider_limits_.clear();
  if (robot_) {
    for (std::size_t i = 0; i < robot_->meshes.size(); ++i) {
      mesh_files_.add(meshUrlPath(i, robot_->meshes[i]), robot_->meshes[i]);
    }
    for (const auto& joint : robot_->robot.at("joints")) {
      if (joint.at("slider").get<bool>()) {
        slider_limits_[joint.at("name").get<std::string>()] = {joint.at("lower").get<double>(),
                                                               joint.at("upper").get<double>()};
      }
    }
  }
  const std::string robot_text = robotMessage(robot_.get());
  const std::string sliders_off = jointsMessage(false, {});
  for (auto& [link, page] : pages_) {
    page.sliders_on = false;
    page.positions.clear();
    send(page, robot_text);
    send(page, sliders_off);
  }
}

std::string ViewerHub::suggestedFixedFrame(const FrameForest& forest) const {
  if (!settings_.fixed_frame.empty()) return settings_.fixed_frame;
  const std::string root = robot_ ? robot_->robot.value("root_link", std::string()) : "";
  return automaticFixedFrame(forest, root);
}

void ViewerHub::sendScenes() {
  if (pages_.empty()) return;
  const FrameForest forest = readForest(buffer_, now());
  const std::string suggested = suggestedFixedFrame(forest);
  // Pages that draw the same frame at the same time share one set of lookups.
  std::map<std::tuple<std::string, bool, std::int64_t>, SceneSnapshot> scenes;
  for (auto& [link, page] : pages_) {
    if (!page.session.readyForScene()) continue;
    const std::string& chosen = page.session.chosenFixedFrame();
    const std::string& fixed = chosen.empty() ? suggested : chosen;
    const std::optional<TimePoint> paused = page.session.pausedAt();
    const auto key = std::make_tuple(fixed, paused.has_value(), paused ? toUtime(*paused) : 0);
    auto scene = scenes.find(key);
    if (scene == scenes.end()) {
      scene =
          scenes.emplace(key, takeSnapshot(buffer_, forest, fixed, paused, settings_.stale_after))
              .first;
    }
    if (auto message = page.session.sceneMessage(scene->second, forest.oldest, forest.newest)) {
      ++statistics_.scenes_sent;
      send(page, std::move(*message));
    }
  }
}

void ViewerHub::sendTree() {
  if (pages_.empty()) return;
  const auto text = std::make_shared<const std::string>(
      treeMessage(readForest(buffer_, now()), settings_.stale_after));
  for (auto& [link, page] : pages_) page.link->send(text);
}

void ViewerHub::publishJoints() {
  for (auto& [link, page] : pages_) {
    if (page.sliders_on) publishJointsOf(page);
  }
}

void ViewerHub::publishJointsOf(Page& page) {
  if (page.positions.empty()) return;
  joint_state_t state{};
  state.utime = toUtime(now());
  state.authority = settings_.authority + "/page-" + std::to_string(page.number);
  state.sequence = ++page.sequence;
  for (const auto& [name, position] : page.positions) {
    state.name.push_back(name);
    state.position.push_back(position);
  }
  state.num_joints = static_cast<std::int32_t>(state.name.size());
  state.num_positions = state.num_joints;
  state.num_velocities = 0;
  state.num_efforts = 0;
  ++statistics_.joint_states_published;
  publish_(state);
}

}  // namespace lcmtf::viewer
