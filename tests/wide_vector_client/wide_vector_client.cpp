#include "wide_vector_client.hpp"

#include <cstddef>

#include "lcmtf/buffer_core.hpp"
#include "lcmtf/geometry_types.hpp"

namespace lcmtf::test {

#if !defined(__AVX2__)
#error "this file must be built with -mavx2 -mfma"
#endif

Layout layoutSeenWithWideVectors() {
  return Layout{sizeof(Transform),
                alignof(Transform),
                offsetof(Transform, rotation),
                sizeof(TransformStamped),
                alignof(TransformStamped),
                offsetof(TransformStamped, transform),
                sizeof(PoseWithCovariance),
                offsetof(PoseWithCovariance, covariance)};
}

TransformStamped lookupWithWideVectors() {
  BufferCore buffer;
  const auto at = [](double seconds) {
    return fromUtime(static_cast<std::int64_t>(seconds * 1e6));
  };
  TransformStamped moving{at(0), "map", "odom",
                          Transform({1, 0, 0}, Eigen::Quaterniond::Identity())};
  buffer.setTransform(moving, "wide_vector_client");
  moving.stamp = at(1);
  moving.transform =
      Transform({3, 0, 0}, Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())));
  buffer.setTransform(moving, "wide_vector_client");
  const TransformStamped mount{
      at(0), "odom", "base_link",
      Transform({0, 0, 0.5}, Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())))};
  buffer.setTransform(mount, "wide_vector_client", true);
  return buffer.lookupTransform("map", "base_link", at(0.25));
}

}  // namespace lcmtf::test
