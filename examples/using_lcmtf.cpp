// The README's "Using it" as a program: a camera on a robot base that drives in odom; where
// the camera was when it took an image, and where what it saw is now.
// usage: lcmtf_using_lcmtf [LCM_URL]   (default: LCM's, which keeps traffic on this machine)
#include <cstdio>
#include <exception>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"
#include "lcmtf/transform_broadcaster.hpp"
#include "lcmtf/transform_listener.hpp"

int main(int argc, char** argv) {
  const std::string url = argc > 1 ? argv[1] : "";
  if (argc > 2 || url.rfind("-", 0) == 0) {
    std::fprintf(stderr, "usage: lcmtf_using_lcmtf [LCM_URL]\n");
    return url == "--help" || url == "-h" ? 0 : 2;
  }
  try {
    lcmtf::Buffer buffer;  // 10 s of history per edge
    lcmtf::ListenerOptions listening;
    listening.lcm_url = url;                               // "": LCM's default URL
    lcmtf::TransformListener listener(buffer, listening);  // its own LCM and receive thread

    lcm::LCM app_lcm(url);
    lcmtf::TransformBroadcaster tf(app_lcm);  // one tf_message_t per sendTransform call
    lcmtf::StaticBroadcasterOptions mounts;
    mounts.lcm_url = url;
    lcmtf::StaticTransformBroadcaster statics(mounts);  // answers late joiners, resends at 1 Hz

    // A camera 1.2 m up on the base, looking along its x axis; the base drives 1 m in 0.1 s.
    const lcmtf::TimePoint image_time = lcmtf::now();  // microseconds since the Unix epoch
    const lcmtf::TimePoint later = image_time + std::chrono::milliseconds(100);
    const Eigen::Isometry3d base_T_camera(Eigen::Translation3d(0.3, 0.0, 1.2));
    statics.sendTransform(
        lcmtf::toTransformStamped(base_T_camera, image_time, "base_link", "camera"));
    const Eigen::Isometry3d odom_T_base_then(Eigen::Translation3d(2.0, 0.5, 0.0));
    const Eigen::Isometry3d odom_T_base_later(Eigen::Translation3d(3.0, 0.5, 0.0));
    tf.sendTransform(lcmtf::toTransformStamped(odom_T_base_then, image_time, "odom", "base_link"));
    tf.sendTransform(lcmtf::toTransformStamped(odom_T_base_later, later, "odom", "base_link"));

    // Where was the camera, in odom, when the image was taken? Waits up to 1 s for the data.
    const lcmtf::TransformStamped odom_T_camera =
        buffer.lookupTransform("odom", "camera", image_time, std::chrono::seconds(1));

    // Or move the data itself (a point, pose, cloud, twist, wrench or covariance): what the
    // camera saw 2 m ahead, in base_link as it is `later`, through odom, which stays put.
    const lcmtf::Stamped<Eigen::Vector3d> seen{Eigen::Vector3d(2.0, 0.0, 0.0), "camera",
                                               image_time};
    const lcmtf::Stamped<Eigen::Vector3d> seen_in_base_later =
        buffer.transform(seen, "base_link", later, "odom", std::chrono::seconds(1));

    const Eigen::Vector3d& camera = odom_T_camera.transform.translation;
    const Eigen::Vector3d& point = seen_in_base_later.data;
    std::printf("the camera was at [%.2f %.2f %.2f] in odom when it took the image\n", camera.x(),
                camera.y(), camera.z());
    std::printf("what it saw is now at [%.2f %.2f %.2f] in base_link\n", point.x(), point.y(),
                point.z());
    return camera.isApprox(Eigen::Vector3d(2.3, 0.5, 1.2)) &&
                   point.isApprox(Eigen::Vector3d(1.3, 0.0, 1.2))
               ? 0
               : 1;
  } catch (const std::exception& e) {  // a lookup that failed, or an LCM that cannot be opened
    std::fprintf(stderr, "lcmtf_using_lcmtf: %s\n", e.what());
    return 1;
  }
}
