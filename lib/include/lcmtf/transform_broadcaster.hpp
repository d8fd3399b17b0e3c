#pragma once

#include <memory>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/batch_numbering.hpp"
#include "lcmtf/channels.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/transform_stamped.hpp"

namespace lcmtf {

/// The tf_message_t for a batch of transforms: sent at `sent`, signed by `authority`, not
/// numbered (sequence 0; broadcasters number theirs).
tf_message_t makeTfMessage(const std::vector<TransformStamped>& transforms,
                           const std::string& authority, TimePoint sent = now());

/// Publishes dynamic transforms: one tf_message_t per sendTransform call, numbered.
class TransformBroadcaster {
 public:
  /// Publishes through the application's LCM, which must outlive the broadcaster. Throws
  /// std::invalid_argument when `authority` cannot be sent (whyUnsendable()).
  explicit TransformBroadcaster(lcm::LCM& lcm, std::string channel = kTfChannel,
                                std::string authority = defaultAuthority());
  /// Publishes through an LCM of its own on `lcm_url` ("" for LCM's default).
  explicit TransformBroadcaster(const std::string& lcm_url, std::string channel = kTfChannel,
                                std::string authority = defaultAuthority());

  /// False when LCM could not publish. Throws std::invalid_argument, and sends nothing, when
  /// a frame name cannot be sent (whyUnsendable()).
  bool sendTransform(const TransformStamped& transform);
  bool sendTransform(const std::vector<TransformStamped>& transforms);

  const std::string& authority() const { return authority_; }
  const std::string& channel() const { return channel_; }

 private:
  std::unique_ptr<lcm::LCM> owned_lcm_;
  lcm::LCM& lcm_;
  std::string channel_;
  std::string authority_;
  BatchNumbering numbering_;
};

}  // namespace lcmtf
