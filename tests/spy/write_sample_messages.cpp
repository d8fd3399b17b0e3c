// Writes one LCM-encoded message per lcmtf top-level type into a directory, as <type>.bin,
// with the field values SpyDecodesLcmtf.java expects.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "lcmtf/joint_state_t.hpp"
#include "lcmtf/resend_request_t.hpp"
#include "lcmtf/robot_description_t.hpp"
#include "lcmtf/tf_message_t.hpp"
#include "lcmtf/transform_t.hpp"

namespace {

lcmtf::transform_t makeTransform(std::int64_t utime, const std::string& parent,
                                 const std::string& child, double x) {
  lcmtf::transform_t t{};
  t.utime = utime;
  t.parent_frame = parent;
  t.child_frame = child;
  t.translation.x = x;
  t.translation.y = 2.5;
  t.translation.z = -3.25;
  t.rotation.x = 0.0;
  t.rotation.y = 0.0;
  t.rotation.z = 0.6;
  t.rotation.w = 0.8;
  return t;
}

template <class Message>
bool write(const std::string& dir, const std::string& type, const Message& msg) {
  std::vector<char> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  if (msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())) !=
      static_cast<int>(bytes.size())) {
    std::fprintf(stderr, "write_sample_messages: cannot encode %s\n", type.c_str());
    return false;
  }
  const std::string path = dir + "/" + type + ".bin";
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "write_sample_messages: cannot write %s\n", path.c_str());
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_sample_messages DIR\n");
    return 2;
  }
  const std::string dir = argv[1];

  lcmtf::tf_message_t tf{};
  tf.utime = 1700000000000001;
  tf.authority = "spy_sample@host:42";
  tf.sequence = 17;
  tf.transforms = {makeTransform(1700000000000002, "world", "base_link", 1.5),
                   makeTransform(1700000000000003, "base_link", "camera_optical", 0.125)};
  tf.num_transforms = static_cast<std::int32_t>(tf.transforms.size());

  const lcmtf::transform_t transform = makeTransform(1700000000000004, "map", "odom", -7.75);

  lcmtf::joint_state_t joints{};
  joints.utime = 1700000000000005;
  joints.authority = "spy_sample@host:44";
  joints.sequence = 18;
  joints.name = {"shoulder_pan", "elbow", "wrist_roll"};
  joints.position = {0.5, -1.25, 3.0};
  joints.velocity = {0.1, 0.2, -0.3};
  joints.num_joints = static_cast<std::int32_t>(joints.name.size());
  joints.num_positions = static_cast<std::int32_t>(joints.position.size());
  joints.num_velocities = static_cast<std::int32_t>(joints.velocity.size());
  joints.num_efforts = 0;

  lcmtf::resend_request_t resend{};
  resend.utime = 1700000000000006;
  resend.requester = "spy_sample_requester";

  lcmtf::robot_description_t robot{};
  robot.utime = 1700000000000007;
  robot.authority = "spy_sample@host:43";
  robot.robot_name = "spy_bot";
  robot.urdf = "<robot name=\"spy_bot\"><link name=\"base_link\"/></robot>";

  const bool ok = write(dir, "tf_message_t", tf) && write(dir, "transform_t", transform) &&
                  write(dir, "joint_state_t", joints) && write(dir, "resend_request_t", resend) &&
                  write(dir, "robot_description_t", robot);
  return ok ? 0 : 1;
}
