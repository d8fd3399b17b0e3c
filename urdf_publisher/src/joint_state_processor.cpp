#include "lcmtf_urdf/joint_state_processor.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "joint_state_senders.hpp"
#include "lcmtf/programs/report_once.hpp"
#include "lcmtf_urdf/joint_motion.hpp"
#include "publish_schedule.hpp"

namespace lcmtf::urdf {

namespace {

enum class EntryKind : std::uint8_t { kUnknown, kDriven, kMimic, kFixed, kUnsupported };

// What a joint name in a joint state refers to; `index` into the list of its kind.
struct Entry {
  EntryKind kind = EntryKind::kUnknown;
  std::uint32_t index = 0;
};

// A movable joint with the frame names its transforms carry.
struct Output {
  MovableJoint joint;
  std::string parent_frame;
  std::string child_frame;
};

struct Follower {
  std::size_t output = 0;
  Mimic relation;
  std::uint32_t given = 0;  // index of its GivenMimic
};

// A movable joint that follows no other: joint states set it, and it carries its followers.
struct Driven {
  std::size_t output = 0;
  std::vector<Follower> followers;
  PublishSchedule schedule;
  std::uint64_t seen_in_message = 0;
};

struct Selected {
  std::uint32_t driven = 0;
  double position = 0.0;
};

// A mimic joint as a joint state may give it: its own position wins over its leader's relation.
struct GivenMimic {
  std::size_t output = 0;
  std::uint32_t leader = 0;  // index into the driven joints
  std::uint64_t seen_in_message = 0;
  double position = 0.0;
  PublishSchedule schedule;  // when it is given without its leader
};

const char* kOnce = " (reported once; later ones are only counted)";

std::int64_t periodMicros(double frequency_hz) {
  if (!(frequency_hz > 0.0) || !std::isfinite(frequency_hz)) return 0;
  return std::max<std::int64_t>(1, std::llround(1e6 / frequency_hz));
}

void set(transform_t& out, const Output& output, const Transform& parent_T_child,
         std::int64_t stamp) {
  out.utime = stamp;
  out.parent_frame = output.parent_frame;
  out.child_frame = output.child_frame;
  out.translation.x = parent_T_child.translation.x();
  out.translation.y = parent_T_child.translation.y();
  out.translation.z = parent_T_child.translation.z();
  out.rotation.x = parent_T_child.rotation.x();
  out.rotation.y = parent_T_child.rotation.y();
  out.rotation.z = parent_T_child.rotation.z();
  out.rotation.w = parent_T_child.rotation.w();
}

}  // namespace

class JointStateProcessor::Impl {
 public:
  Impl(const RobotModel& robot, JointStateOptions options_in)
      : options(std::move(options_in)),
        period_us_(periodMicros(options.publish_frequency)),
        reporter_(options.reporter) {
    setRobot(robot);
    batch_.authority = options.authority;
  }

  // The joints of `robot` take the place of the previous robot's; statistics and senders stay.
  void setRobot(const RobotModel& robot) {
    robot_name_ = robot.name;
    outputs_.clear();
    driven_.clear();
    given_mimics_.clear();
    unsupported_types_.clear();
    entries_.clear();
    cached_names_.clear();
    cached_entries_.clear();
    std::unordered_map<std::string, std::size_t> output_of;
    for (const MovableJoint& joint : robot.movable_joints) {
      output_of[joint.name] = outputs_.size();
      outputs_.push_back({joint, options.frame_prefix + joint.parent_link,
                          options.frame_prefix + joint.child_link});
    }
    for (std::size_t o = 0; o < outputs_.size(); ++o) {
      const MovableJoint& joint = outputs_[o].joint;
      if (joint.resolved_mimic) {
        entries_[joint.name] = {EntryKind::kMimic,
                                static_cast<std::uint32_t>(given_mimics_.size())};
        given_mimics_.push_back({o, 0, 0, 0.0, {}});
      } else {
        entries_[joint.name] = {EntryKind::kDriven, static_cast<std::uint32_t>(driven_.size())};
        driven_.push_back({o, {}, {}, 0});
      }
    }
    for (const Output& output : outputs_) {
      const auto& mimic = output.joint.resolved_mimic;
      if (!mimic) continue;
      const std::uint32_t leader = entries_.at(mimic->leader).index;
      const std::uint32_t given = entries_.at(output.joint.name).index;
      driven_[leader].followers.push_back({output_of.at(output.joint.name), *mimic, given});
      given_mimics_[given].leader = leader;
    }
    for (const FixedJoint& joint : robot.fixed_joints)
      entries_[joint.name] = {EntryKind::kFixed, 0};
    for (std::uint32_t u = 0; u < robot.unsupported_joints.size(); ++u) {
      entries_[robot.unsupported_joints[u].name] = {EntryKind::kUnsupported, u};
      unsupported_types_.push_back(robot.unsupported_joints[u].type);
    }
  }

  tf_message_t* process(const void* data, std::size_t size, TimePoint arrival) {
    const DecodeResult decoded = decodeMessage(data, size, decoded_, options.limits);
    if (!decoded.ok) {
      ++statistics.received;
      ++statistics.malformed;
      reporter_.report("malformed",
                       "refused a joint state that does not decode: " + decoded.error + kOnce);
      return nullptr;
    }
    return process(decoded_, arrival);
  }

  tf_message_t* process(const joint_state_t& state, TimePoint arrival) {
    ++statistics.received;
    const SequenceCounts change = senders_.observe(state.authority, state.sequence);
    statistics.lost += change.lost;
    statistics.reordered += change.reordered;
    statistics.duplicated += change.duplicated;
    if (state.name.size() != state.position.size()) {
      ++statistics.length_mismatches;
      reporter_.report("length", "refused a joint state with " + std::to_string(state.name.size()) +
                                     " names but " + std::to_string(state.position.size()) +
                                     " positions" + kOnce);
      return nullptr;
    }
    if (!options.ignore_timestamp && state.utime <= 0) {
      ++statistics.unstamped;
      reporter_.report("unstamped", "refused a joint state stamped utime " +
                                        std::to_string(state.utime) +
                                        ": stamp it, or run with --ignore-timestamp" + kOnce);
      return nullptr;
    }
    const std::int64_t stamp = options.ignore_timestamp ? toUtime(arrival) : state.utime;
    select(state);
    if (selected_.empty() && given_alone_.empty()) return nullptr;
    if (period_us_ > 0) {
      keepOnlyDue(stamp);
      if (selected_.empty() && given_alone_.empty()) {
        ++statistics.rate_limited;
        return nullptr;
      }
    }
    if (!fill(stamp, arrival)) return nullptr;
    ++statistics.batches;
    statistics.transforms += batch_.transforms.size();
    return &batch_;
  }

  JointStateOptions options;
  JointStateStatistics statistics;

 private:
  // Joint states usually list the same names in the same order every time: a name equal to
  // the one at the same place last time skips the hash lookup.
  Entry entryFor(std::size_t i, const std::string& name) {
    if (i < cached_names_.size() && cached_names_[i] == name) return cached_entries_[i];
    if (i >= cached_names_.size()) {
      cached_names_.resize(i + 1);
      cached_entries_.resize(i + 1);
    }
    const auto found = entries_.find(name);
    cached_names_[i] = name;
    cached_entries_[i] = found == entries_.end() ? Entry{} : found->second;
    return cached_entries_[i];
  }

  void select(const joint_state_t& state) {
    selected_.clear();
    given_this_message_.clear();
    given_alone_.clear();
    ++message_serial_;
    for (std::size_t i = 0; i < state.name.size(); ++i) {
      const std::string& name = state.name[i];
      const Entry entry = entryFor(i, name);
      if (entry.kind == EntryKind::kMimic) {
        give(entry.index, name, state.position[i]);
        continue;
      }
      if (entry.kind != EntryKind::kDriven) {
        skip(entry, name);
        continue;
      }
      const double position = state.position[i];
      if (firstFinite(driven_[entry.index].seen_in_message, name, position)) {
        selected_.push_back({entry.index, position});
      }
    }
    for (const std::uint32_t given : given_this_message_) {
      const GivenMimic& mimic = given_mimics_[given];
      if (driven_[mimic.leader].seen_in_message != message_serial_) given_alone_.push_back(given);
    }
  }

  // As robot_state_publisher does, a mimic joint's position in the message wins over the one
  // its leader's would give.
  void give(std::uint32_t index, const std::string& name, double position) {
    GivenMimic& mimic = given_mimics_[index];
    if (!firstFinite(mimic.seen_in_message, name, position)) return;
    ++statistics.given_mimic_positions;
    mimic.position = position;
    given_this_message_.push_back(index);
  }

  // Whether this is the first finite position of a joint in the message; notes it seen then.
  bool firstFinite(std::uint64_t& seen_in_message, const std::string& name, double position) {
    if (seen_in_message == message_serial_) {
      ++statistics.duplicate_joints;
      reporter_.report("duplicate " + name,
                       "joint '" + name +
                           "' appears twice in one joint state; its first finite value is "
                           "used (reported once per joint)");
      return false;
    }
    if (!std::isfinite(position)) {
      reportNonFinite(name, position);
      return false;
    }
    seen_in_message = message_serial_;
    return true;
  }

  void skip(const Entry& entry, const std::string& name) {
    if (entry.kind == EntryKind::kUnknown) {
      ++statistics.unknown_joints;
      reporter_.report("unknown " + name, "ignored joint '" + name + "': robot '" + robot_name_ +
                                              "' has no such joint (reported once per name)");
      return;
    }
    ++statistics.ignored_joints;
    std::string why;
    if (entry.kind == EntryKind::kFixed) {
      why = "a fixed joint, published once as a static transform";
    } else {
      why = "a " + unsupported_types_[entry.index] +
            " joint, whose pose a joint state cannot give: publish its transform yourself";
    }
    reporter_.report("ignored " + name, "ignored the position of joint '" + name + "': it is " +
                                            why + " (reported once per name)");
  }

  void reportNonFinite(const std::string& name, double position) {
    ++statistics.non_finite_positions;
    reporter_.report("non-finite " + name,
                     "skipped joint '" + name + "' at position " + std::to_string(position) +
                         " (reported once per joint; later ones are only counted)");
  }

  // The rate cap is per joint: a joint published less than a period ago is left out.
  void keepOnlyDue(std::int64_t stamp) {
    selected_.erase(std::remove_if(selected_.begin(), selected_.end(),
                                   [&](const Selected& s) {
                                     return !driven_[s.driven].schedule.due(stamp, period_us_);
                                   }),
                    selected_.end());
    given_alone_.erase(std::remove_if(given_alone_.begin(), given_alone_.end(),
                                      [&](std::uint32_t given) {
                                        return !given_mimics_[given].schedule.due(stamp,
                                                                                  period_us_);
                                      }),
                       given_alone_.end());
  }

  // Writes the joint's transform as the batch's next one, unless a huge position (or a mimic's
  // multiplier) made it non-finite.
  bool append(std::size_t& k, const Output& output, double position, std::int64_t stamp) {
    const Transform parent_T_child = parentTChild(output.joint, position);
    if (!parent_T_child.translation.allFinite() || !parent_T_child.rotation.coeffs().allFinite()) {
      reportNonFinite(output.joint.name, position);
      return false;
    }
    set(batch_.transforms[k++], output, parent_T_child, stamp);
    return true;
  }

  // Fills the batch; false when no transform in it was finite.
  bool fill(std::int64_t stamp, TimePoint arrival) {
    std::size_t count = 0;
    for (const Selected& s : selected_) {
      Driven& driven = driven_[s.driven];
      driven.schedule.published(stamp, period_us_);
      count += 1 + driven.followers.size();
    }
    for (const std::uint32_t given : given_alone_) {
      given_mimics_[given].schedule.published(stamp, period_us_);
      ++count;
    }
    batch_.utime = toUtime(arrival);
    batch_.transforms.resize(count);
    std::size_t k = 0;
    for (const Selected& s : selected_) {
      const Driven& driven = driven_[s.driven];
      append(k, outputs_[driven.output], s.position, stamp);
      for (const Follower& follower : driven.followers) {
        const GivenMimic& given = given_mimics_[follower.given];
        const double position = given.seen_in_message == message_serial_
                                    ? given.position
                                    : mimicPosition(follower.relation, s.position);
        append(k, outputs_[follower.output], position, stamp);
      }
    }
    for (const std::uint32_t given : given_alone_) {
      append(k, outputs_[given_mimics_[given].output], given_mimics_[given].position, stamp);
    }
    batch_.transforms.resize(k);
    batch_.num_transforms = static_cast<std::int32_t>(k);
    return k > 0;
  }

  std::string robot_name_;
  std::int64_t period_us_ = 0;
  programs::OnceReporter reporter_;
  JointStateSenders senders_;
  std::vector<Output> outputs_;
  std::vector<Driven> driven_;
  std::vector<std::string> unsupported_types_;
  std::unordered_map<std::string, Entry> entries_;
  std::vector<std::string> cached_names_;
  std::vector<Entry> cached_entries_;
  std::vector<Selected> selected_;
  std::vector<GivenMimic> given_mimics_;
  std::vector<std::uint32_t> given_this_message_;
  std::vector<std::uint32_t> given_alone_;  // given without their leader
  std::uint64_t message_serial_ = 0;
  joint_state_t decoded_;
  tf_message_t batch_{};
};

JointStateProcessor::JointStateProcessor(const RobotModel& robot, JointStateOptions options)
    : impl_(std::make_unique<Impl>(robot, std::move(options))) {}

JointStateProcessor::~JointStateProcessor() = default;

tf_message_t* JointStateProcessor::process(const void* data, std::size_t size, TimePoint arrival) {
  return impl_->process(data, size, arrival);
}

tf_message_t* JointStateProcessor::process(const joint_state_t& state, TimePoint arrival) {
  return impl_->process(state, arrival);
}

void JointStateProcessor::setRobot(const RobotModel& robot) { impl_->setRobot(robot); }

const JointStateStatistics& JointStateProcessor::statistics() const { return impl_->statistics; }

const JointStateOptions& JointStateProcessor::options() const { return impl_->options; }

std::string describe(const JointStateStatistics& s) {
  std::string text = std::to_string(s.received) + " joint states, " + std::to_string(s.batches) +
                     " batches of " + std::to_string(s.transforms) + " transforms";
  const std::pair<std::uint64_t, const char*> counts[] = {
      {s.rate_limited, "skipped by the rate cap"},
      {s.malformed, "malformed"},
      {s.length_mismatches, "with names and positions differing in number"},
      {s.unstamped, "unstamped"},
      {s.non_finite_positions, "non-finite positions skipped"},
      {s.unknown_joints, "unknown joint names"},
      {s.ignored_joints, "positions of fixed, floating or planar joints ignored"},
      {s.duplicate_joints, "repeated joints"},
      {s.lost, "lost on the way (numbers skipped)"},
      {s.reordered, "came out of order"},
      {s.duplicated, "came twice"},
  };
  for (const auto& [count, what] : counts) {
    if (count != 0) text += "; " + std::to_string(count) + " " + what;
  }
  return text;
}

std::vector<TransformStamped> fixedJointTransforms(const RobotModel& robot,
                                                   const std::string& frame_prefix,
                                                   TimePoint stamp) {
  std::vector<TransformStamped> transforms;
  transforms.reserve(robot.fixed_joints.size());
  for (const FixedJoint& joint : robot.fixed_joints) {
    transforms.push_back({stamp, frame_prefix + joint.parent_link, frame_prefix + joint.child_link,
                          joint.parent_T_child});
  }
  return transforms;
}

}  // namespace lcmtf::urdf
