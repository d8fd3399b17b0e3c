#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/subscription_budget.hpp"

namespace lcmtf::urdf {

/// The latest position of each joint of a list, as other programs' joint states give them
/// (joint_state_publisher's source_list). It holds one position a joint, whatever is sent.
class JointStateSources {
 public:
  /// Keeps positions for `joint_names` only; subscribes to `channels` on `lcm`, which the
  /// caller handles and which must outlive it.
  JointStateSources(lcm::LCM& lcm, const std::vector<std::string>& channels,
                    const std::vector<std::string>& joint_names);
  ~JointStateSources();
  JointStateSources(const JointStateSources&) = delete;
  JointStateSources& operator=(const JointStateSources&) = delete;

  /// Takes the finite positions of the joints it keeps from an encoded joint state.
  void take(const void* data, std::size_t size);
  /// Per joint name given at construction, in that order: its latest position, if any came.
  const std::vector<std::optional<double>>& positions() const { return positions_; }
  /// Messages that did not decode, and entries naming a joint it does not keep.
  std::uint64_t malformed() const { return malformed_; }
  std::uint64_t unknownJoints() const { return unknown_joints_; }

 private:
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  std::vector<SubscriptionBudget> queues_;
  std::unordered_map<std::string, std::size_t> index_of_;
  std::vector<std::optional<double>> positions_;
  joint_state_t decoded_;
  std::uint64_t malformed_ = 0;
  std::uint64_t unknown_joints_ = 0;
};

}  // namespace lcmtf::urdf
