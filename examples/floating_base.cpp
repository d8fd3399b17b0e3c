// The pose of a URDF floating joint, which no joint state can carry, published by whatever
// knows it (odometry, localization) under the joint's parent and child link names.
// usage: lcmtf_floating_base [LCM_URL]   (default: LCM's, which keeps traffic on this machine)
#include <cstdio>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"

int main(int argc, char** argv) {
  const std::string url = argc > 1 ? argv[1] : "";
  lcmtf::Buffer buffer;
  lcmtf::ListenerOptions listening;
  listening.lcm_url = url;
  lcmtf::TransformListener listener(buffer, listening);
  lcm::LCM app_lcm(url);
  const lcmtf::TimePoint stamp = lcmtf::now();
  const Eigen::Isometry3d odom_T_base_link =
      Eigen::Translation3d(1.0, 2.0, 0.0) * Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ());

  // The URDF has <joint name="floating_base" type="floating"> from odom to base_link.
  lcmtf::TransformBroadcaster tf(app_lcm);
  tf.sendTransform(lcmtf::toTransformStamped(odom_T_base_link, stamp, "odom", "base_link"));

  try {
    const lcmtf::TransformStamped heard =
        buffer.lookupTransform("odom", "base_link", stamp, std::chrono::seconds(1));
    std::printf("base_link in odom: [%.2f %.2f %.2f]\n", heard.transform.translation.x(),
                heard.transform.translation.y(), heard.transform.translation.z());
    return lcmtf::toIsometry(heard).isApprox(odom_T_base_link) ? 0 : 1;
  } catch (const lcmtf::TransformException& e) {
    std::fprintf(stderr, "lcmtf_floating_base: %s\n", e.what());
    return 1;
  }
}
