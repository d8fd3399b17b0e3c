#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf_viewer/page_messages.hpp"
#include "lcmtf_viewer/page_session.hpp"
#include "lcmtf_viewer/robot_view.hpp"
#include "lcmtf_viewer/served_files.hpp"
#include "lcmtf_viewer/web_server.hpp"

namespace lcmtf::viewer {

/// How the hub draws and drives.
struct HubSettings {
  std::string version;
  std::string fixed_frame;  ///< suggested to pages; "" picks the robot's root or largest tree
  double update_hz = 30.0;
  Duration stale_after = std::chrono::seconds(1);
  std::string joint_states_channel;
  std::string authority;  ///< joint states are signed "<authority>/page-<n>"
};

/// What the hub has refused and sent.
struct HubStatistics {
  std::atomic<std::uint64_t> pages_opened{0};
  std::atomic<std::uint64_t> messages_refused{0};
  std::atomic<std::uint64_t> pages_closed_for_refusals{0};
  std::atomic<std::uint64_t> scenes_sent{0};
  std::atomic<std::uint64_t> joint_states_published{0};
};

/// The viewer's heart: serves the page's files and the robot's meshes, sends each open page
/// the scene it asked for, and publishes the joint states its sliders set. Everything but
/// the statistics runs on the web server's thread.
class ViewerHub : public WebHandler {
 public:
  using JointStateSink = std::function<void(const joint_state_t& state)>;

  ViewerHub(const BufferCore& buffer, ServedFiles page_files, HubSettings settings,
            JointStateSink publish);

  const ServedFile* findFile(std::string_view target) override;
  void pageOpened(const std::shared_ptr<PageLink>& page) override;
  void pageMessage(PageLink& page, std::string_view message, bool is_text) override;
  void pageClosed(PageLink& page) override;
  void serverStopping() override;

  /// Draws `robot` from now on (null: none); every page is told, and sliders are switched off.
  void setRobot(std::shared_ptr<const RobotView> robot);
  /// Sends each page that drew its last scene the next one, if anything changed.
  void sendScenes();
  /// Sends every page the tree with rates and ages.
  void sendTree();
  /// Publishes the positions of every page whose sliders are on.
  void publishJoints();

  std::size_t openPages() const { return pages_.size(); }
  const HubStatistics& statistics() const { return statistics_; }

 private:
  struct Page {
    std::shared_ptr<PageLink> link;
    std::size_t number = 0;
    PageSession session;
    bool sliders_on = false;
    std::map<std::string, double> positions;
    std::int64_t sequence = 0;
    std::size_t refused = 0;
  };

  void refuse(Page& page, const std::string& why);
  void send(Page& page, std::string text);
  void handle(Page& page, const AckMessage& ack);
  void handle(Page& page, const ViewMessage& view);
  void handle(Page& page, const JointsMessage& joints);
  void publishJointsOf(Page& page);
  std::string suggestedFixedFrame(const FrameForest& forest) const;

  const BufferCore& buffer_;
  ServedFiles page_files_;
  HubSettings settings_;
  JointStateSink publish_;
  std::shared_ptr<const RobotView> robot_;
  ServedFiles mesh_files_;
  std::map<std::string, std::pair<double, double>> slider_limits_;  ///< joint -> lower, upper
  std::map<PageLink*, Page> pages_;
  std::size_t pages_ever_ = 0;
  HubStatistics statistics_;
};

}  // namespace lcmtf::viewer
