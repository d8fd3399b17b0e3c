// Sends a batch of transforms over LCM, receives it back, and uses it: where is a point seen
// by the camera, in the map frame?
// usage: lcmtf_round_trip [LCM_URL]   (default: udpm with ttl=0, so nothing leaves this machine)
#include <cstdio>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/wire_decode.hpp"

namespace {

lcmtf::transform_t edge(const char* parent, const char* child, const Eigen::Vector3d& translation,
                        double yaw, lcmtf::TimePoint stamp) {
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return lcmtf::toMessage(
      lcmtf::TransformStamped{stamp, parent, child, lcmtf::Transform(translation, rotation)});
}

struct Receiver {
  void onBatch(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    const lcmtf::DecodeResult result = lcmtf::decodeMessage(buffer->data, buffer->data_size, batch);
    received = result.ok;
    if (!result.ok)
      std::fprintf(stderr, "ignored a bad message on %s: %s\n", channel.c_str(),
                   result.error.c_str());
  }
  lcmtf::tf_message_t batch;
  bool received = false;
};

}  // namespace

int main(int argc, char** argv) {
  const std::string url = argc > 1 ? argv[1] : "udpm://239.255.76.67:7667?ttl=0";
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "cannot open LCM at %s\n", url.c_str());
    return 1;
  }
  Receiver receiver;
  lcm.subscribe("TF", &Receiver::onBatch, &receiver);

  const lcmtf::TimePoint stamp = lcmtf::now();
  lcmtf::tf_message_t batch;
  batch.utime = lcmtf::toUtime(stamp);
  batch.authority = "lcmtf_round_trip";
  batch.transforms = {
      edge("map", "odom", Eigen::Vector3d(10, 5, 0), 0.0, stamp),
      edge("odom", "base_link", Eigen::Vector3d(2, 0, 0), 1.5707963267948966, stamp),
      edge("base_link", "camera", Eigen::Vector3d(0.3, 0, 1.2), 0.0, stamp),
  };
  batch.num_transforms = static_cast<std::int32_t>(batch.transforms.size());
  std::printf("publishing %d transforms on TF via %s\n", batch.num_transforms, url.c_str());
  lcm.publish("TF", &batch);

  while (!receiver.received) {
    if (lcm.handleTimeout(2000) <= 0) {
      std::fprintf(stderr, "no TF message came back within 2 s on %s\n", url.c_str());
      return 1;
    }
  }

  lcmtf::Transform map_T_camera;
  std::printf("received from %s:\n", receiver.batch.authority.c_str());
  for (const lcmtf::transform_t& message : receiver.batch.transforms) {
    const lcmtf::TransformStamped t = lcmtf::fromMessage(message);
    std::printf("  %-9s -> %-9s  t=[%6.3f %6.3f %6.3f]  stamp %s\n", t.parent_frame.c_str(),
                t.child_frame.c_str(), t.transform.translation.x(), t.transform.translation.y(),
                t.transform.translation.z(), lcmtf::toString(t.stamp).c_str());
    map_T_camera = map_T_camera * t.transform;
  }
  const Eigen::Vector3d point_in_camera(1.0, 0.0, 0.0);
  const Eigen::Vector3d point_in_map = map_T_camera * point_in_camera;
  std::printf("a point 1 m ahead of the camera is at [%.3f %.3f %.3f] in map\n", point_in_map.x(),
              point_in_map.y(), point_in_map.z());
  return 0;
}
