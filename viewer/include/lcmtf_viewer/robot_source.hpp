#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/programs/report_once.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "lcmtf/time.hpp"
#include "lcmtf_viewer/robot_view.hpp"

namespace lcmtf::viewer {

/// Where the robot comes from and who asks for it.
struct RobotSourceOptions {
  std::string description_channel;
  std::string request_channel;
  std::string authority;  ///< signs the requests
  MeshSearch search;      ///< package paths; its folder is set for a file
  Duration request_period = std::chrono::seconds(1);  ///< asks this often until a robot comes
};

/// What the source heard.
struct RobotSourceStatistics {
  std::uint64_t received = 0;  ///< descriptions, refused ones included
  std::uint64_t refused = 0;   ///< that did not decode or make a valid robot
  std::uint64_t robots = 0;    ///< robots passed on
};

/// Gives the viewer its robot: once from a file, or from each new valid description heard on
/// LCM (a repeat of the last text is skipped; a bad one is reported once and the robot kept).
class RobotSource {
 public:
  using RobotSink = std::function<void(std::shared_ptr<const RobotView> robot)>;
  using Reporter = std::function<void(const std::string& message)>;

  RobotSource(lcm::LCM& lcm, RobotSourceOptions options, RobotSink sink, Reporter reporter);
  ~RobotSource();

  /// Reads the URDF file; throws urdf::UrdfError naming it and the problem.
  void loadFile(const std::string& path);
  /// Listens for descriptions on the LCM passed in (handled by its owner's loop).
  void follow();
  /// Asks for the description again when none has come for request_period.
  void askIfWaiting(TimePoint now);
  const RobotSourceStatistics& statistics() const { return statistics_; }

 private:
  void onDescription(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void refuse(const std::string& message);

  lcm::LCM& lcm_;
  RobotSourceOptions options_;
  RobotSink sink_;
  std::unique_ptr<programs::OnceReporter> reporter_;
  std::optional<SubscriptionBudget> description_queue_;
  std::string last_text_;
  bool have_robot_ = false;
  TimePoint last_request_;
  RobotSourceStatistics statistics_;
};

}  // namespace lcmtf::viewer
