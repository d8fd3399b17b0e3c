#include "lcmtf_urdf/robot_description.hpp"

#include "lcmtf/programs/report_once.hpp"
#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/subscription_budget.hpp"
#include "lcmtf/wire_decode.hpp"

namespace lcmtf::urdf {

namespace {

class DescriptionCatcher {
 public:
  explicit DescriptionCatcher(const DescriptionWaitOptions& options)
      : reporter_(options.reporter) {}

  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    queue->fit(buffer->data_size);
    if (robot) return;
    ++statistics.received;
    robot_description_t description;
    const DecodeResult decoded = decodeMessage(buffer->data, buffer->data_size, description);
    if (!decoded.ok) {
      refuse("refused a message on " + channel + ": " + decoded.error);
      return;
    }
    try {
      robot = parseRobotModel(description.urdf, channel + " from " + description.authority);
    } catch (const UrdfError& e) {
      refuse(std::string("refused a robot description: ") + e.what());
    }
  }

  std::optional<RobotModel> robot;
  DescriptionWaitStatistics statistics;
  std::optional<SubscriptionBudget> queue;

 private:
  // The same refusal again (a sender that keeps resending it) is counted, not repeated.
  void refuse(const std::string& message) {
    ++statistics.refused;
    reporter_.report(message, message);
  }

  programs::OnceReporter reporter_;
};

}  // namespace

robot_description_t makeRobotDescription(const RobotModel& robot, const std::string& authority,
                                         TimePoint sent) {
  robot_description_t description{};
  description.utime = toUtime(sent);
  description.authority = authority;
  description.robot_name = robot.name;
  description.urdf = robot.urdf;
  return description;
}

std::optional<RobotModel> waitForRobotDescription(lcm::LCM& lcm,
                                                  const DescriptionWaitOptions& options,
                                                  const std::atomic<bool>& stop,
                                                  DescriptionWaitStatistics* statistics) {
  DescriptionCatcher catcher(options);
  catcher.queue.emplace(lcm.subscribe(options.channel, &DescriptionCatcher::onMessage, &catcher),
                        options.channel, kDefaultQueueBytes, kLcmDefaultQueueCapacity);
  resend_request_t request{};
  request.requester = options.authority;
  const auto start = std::chrono::steady_clock::now();
  auto next_request = start;
  const bool forever = options.timeout <= Duration::zero();
  while (!catcher.robot && !stop &&
         (forever || std::chrono::steady_clock::now() - start < options.timeout)) {
    if (std::chrono::steady_clock::now() >= next_request) {
      request.utime = toUtime(now());
      lcm.publish(options.request_channel, &request);
      next_request = std::chrono::steady_clock::now() + options.request_period;
    }
    lcm.handleTimeout(50);
  }
  lcm.unsubscribe(catcher.queue->subscription());
  if (statistics) *statistics = catcher.statistics;
  return std::move(catcher.robot);
}

}  // namespace lcmtf::urdf
