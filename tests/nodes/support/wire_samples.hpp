#pragma once

#include <string>
#include <vector>

#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/time.hpp"

namespace lcmtf_test {

/// A fixed instant the tools' tests count from, so stamps in expected text are predictable.
inline constexpr lcmtf::TimePoint kToolsEpoch = lcmtf::fromUtime(1'700'000'000'000'000);

/// parent -> child at `stamp` with the identity pose, as it travels on the wire.
inline lcmtf::transform_t wireTransform(const std::string& parent, const std::string& child,
                                        lcmtf::TimePoint stamp) {
  lcmtf::transform_t transform{};
  transform.utime = lcmtf::toUtime(stamp);
  transform.parent_frame = parent;
  transform.child_frame = child;
  transform.rotation.w = 1.0;
  return transform;
}

/// A batch of `transforms` signed by `authority`.
inline lcmtf::tf_message_t wireBatch(const std::string& authority,
                                     std::vector<lcmtf::transform_t> transforms) {
  lcmtf::tf_message_t batch{};
  batch.authority = authority;
  batch.num_transforms = static_cast<std::int32_t>(transforms.size());
  batch.transforms = std::move(transforms);
  return batch;
}

}  // namespace lcmtf_test
