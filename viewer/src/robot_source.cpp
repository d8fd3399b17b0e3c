#include "lcmtf_viewer/robot_source.hpp"

#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/robot_description_t.hpp"
#include "lcmtf/wire_decode.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::viewer {

RobotSource::RobotSource(lcm::LCM& lcm, RobotSourceOptions options, RobotSink sink,
                         Reporter reporter)
    : lcm_(lcm),
      options_(std::move(options)),
      sink_(std::move(sink)),
      reporter_(std::make_unique<programs::OnceReporter>(std::move(reporter))) {}

RobotSource::~RobotSource() {
  if (description_queue_) lcm_.unsubscribe(description_queue_->subscription());
}

void RobotSource::loadFile(const std::string& path) {
  const urdf::RobotModel model = urdf::loadRobotModel(path);
  MeshSearch search = options_.search;
  search.description_folder = std::filesystem::absolute(path).parent_path();
  have_robot_ = true;
  ++statistics_.robots;
  sink_(std::make_shared<const RobotView>(makeRobotView(model, search)));
}

void RobotSource::follow() {
  // Descriptions are a few hundred kilobytes at most; there is no need to keep many.
  description_queue_.emplace(
      lcm_.subscribe(options_.description_channel, &RobotSource::onDescription, this),
      options_.description_channel, kDefaultQueueBytes, 4);
}

void RobotSource::askIfWaiting(TimePoint now) {
  if (have_robot_ || !description_queue_ || now - last_request_ < options_.request_period) return;
  last_request_ = now;
  resend_request_t request{};
  request.utime = toUtime(now);
  request.requester = options_.authority;
  lcm_.publish(options_.request_channel, &request);
}

void RobotSource::onDescription(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  description_queue_->fit(buffer->data_size);
  ++statistics_.received;
  robot_description_t description;
  const DecodeResult decoded = decodeMessage(buffer->data, buffer->data_size, description);
  if (!decoded.ok) {
    refuse("refused a message on " + channel + ": " + decoded.error);
    return;
  }
  if (description.urdf == last_text_) return;
  last_text_ = description.urdf;
  try {
    const urdf::RobotModel model =
        urdf::parseRobotModel(description.urdf, channel + " from " + description.authority);
    auto view = std::make_shared<const RobotView>(makeRobotView(model, options_.search));
    have_robot_ = true;
    ++statistics_.robots;
    sink_(std::move(view));
  } catch (const urdf::UrdfError& e) {
    refuse(std::string("refused a robot description: ") + e.what());
  }
}

void RobotSource::refuse(const std::string& message) {
  ++statistics_.refused;
  reporter_->report(message, message);
}

}  // namespace lcmtf::viewer
