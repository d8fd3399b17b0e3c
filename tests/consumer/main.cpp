// Uses only what `make install` puts under the prefix.
#include <cstdio>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include <lcmtf/message_conversions.hpp>
#include <lcmtf/tf_message_t.hpp>
#include <lcmtf/time.hpp>
#include <lcmtf/transform.hpp>

namespace {

class Receiver {
 public:
  void onTf(const lcm::ReceiveBuffer*, const std::string&, const lcmtf::tf_message_t* message) {
    received.push_back(*message);
  }
  std::vector<lcmtf::tf_message_t> received;
};

int fail(const char* what) {
  std::fprintf(stderr, "lcmtf consumer: %s\n", what);
  return 1;
}

}  // namespace

int main() {
  const lcmtf::Transform world_T_base(
      Eigen::Vector3d(1.0, 2.0, 3.0),
      Eigen::Quaterniond(Eigen::AngleAxisd(EIGEN_PI / 2.0, Eigen::Vector3d::UnitZ())));
  const lcmtf::Transform base_T_camera(Eigen::Vector3d(0.5, 0.0, 0.0),
                                       Eigen::Quaterniond::Identity());
  const lcmtf::Transform world_T_camera = world_T_base * base_T_camera;
  if (!world_T_camera.translation.isApprox(Eigen::Vector3d(1.0, 2.5, 3.0), 1e-12)) {
    return fail("composition gave the wrong translation");
  }
  if (!(world_T_camera * world_T_camera.inverse()).isApprox(lcmtf::Transform::identity())) {
    return fail("a transform times its inverse is not the identity");
  }

  lcmtf::TransformStamped stamped;
  stamped.stamp = lcmtf::fromUtime(1700000000000250);
  stamped.parent_frame = "world";
  stamped.child_frame = "camera";
  stamped.transform = world_T_camera;

  lcmtf::tf_message_t sent{};
  sent.utime = 1700000000000300;
  sent.authority = "consumer";
  sent.transforms.push_back(lcmtf::toMessage(stamped));
  sent.num_transforms = static_cast<int32_t>(sent.transforms.size());

  std::vector<unsigned char> bytes(static_cast<std::size_t>(sent.getEncodedSize()));
  if (sent.encode(bytes.data(), 0, static_cast<int>(bytes.size())) !=
      static_cast<int>(bytes.size())) {
    return fail("encode wrote the wrong number of bytes");
  }

  lcm::LCM lcm("memq://");
  if (!lcm.good()) {
    return fail("memq:// did not start");
  }
  Receiver receiver;
  lcm.subscribe("TF", &Receiver::onTf, &receiver);
  if (lcm.publish("TF", bytes.data(), static_cast<unsigned int>(bytes.size())) != 0) {
    return fail("publish failed");
  }
  if (lcm.handleTimeout(1000) <= 0 || receiver.received.size() != 1) {
    return fail("the message did not come back");
  }

  const lcmtf::tf_message_t& got = receiver.received.front();
  if (got.utime != sent.utime || got.authority != sent.authority || got.num_transforms != 1) {
    return fail("tf_message_t header differs after the round trip");
  }
  const lcmtf::TransformStamped back = lcmtf::fromMessage(got.transforms.front());
  if (back.stamp != stamped.stamp || back.parent_frame != "world" || back.child_frame != "camera") {
    return fail("transform_t stamp or frames differ after the round trip");
  }
  if (!back.transform.isApprox(world_T_camera)) {
    return fail("transform values differ after the round trip");
  }
  std::printf("lcmtf consumer: ok\n");
  return 0;
}
