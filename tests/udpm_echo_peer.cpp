// The other process of the udpm round-trip test: receives tf_message_t batches on a request
// channel and answers each with the inverse of every transform on a reply channel.
// usage: udpm_echo_peer URL REQUEST_CHANNEL REPLY_CHANNEL REPLIES TIMEOUT_MS
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "lcmtf/message_conversions.hpp"
#include "lcmtf/wire_decode.hpp"

namespace {

class Echo {
 public:
  Echo(lcm::LCM& lcm, std::string reply_channel)
      : lcm_(lcm), reply_channel_(std::move(reply_channel)) {}

  void onRequest(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    lcmtf::tf_message_t request;
    const lcmtf::DecodeResult result =
        lcmtf::decodeMessage(buffer->data, buffer->data_size, request);
    if (!result.ok) {
      std::fprintf(stderr, "udpm_echo_peer: ignored a bad message: %s\n", result.error.c_str());
      return;
    }
    lcmtf::tf_message_t reply = request;
    reply.authority = "udpm_echo_peer";
    for (lcmtf::transform_t& t : reply.transforms) {
      lcmtf::TransformStamped stamped = lcmtf::fromMessage(t);
      std::swap(stamped.parent_frame, stamped.child_frame);
      stamped.transform = stamped.transform.inverse();
      t = lcmtf::toMessage(stamped);
    }
    lcm_.publish(reply_channel_, &reply);
    ++replies_;
  }

  int replies() const { return replies_; }

 private:
  lcm::LCM& lcm_;
  std::string reply_channel_;
  int replies_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: %s URL REQUEST_CHANNEL REPLY_CHANNEL REPLIES TIMEOUT_MS\n",
                 argv[0]);
    return 2;
  }
  lcm::LCM lcm(argv[1]);
  if (!lcm.good()) {
    std::fprintf(stderr, "udpm_echo_peer: cannot open LCM at %s\n", argv[1]);
    return 2;
  }
  Echo echo(lcm, argv[3]);
  lcm.subscribe(argv[2], &Echo::onRequest, &echo);
  const int wanted = std::atoi(argv[4]);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(std::atoi(argv[5]));
  while (echo.replies() < wanted) {
    if (std::chrono::steady_clock::now() >= deadline) {
      std::fprintf(stderr, "udpm_echo_peer: timed out after %d of %d replies\n", echo.replies(),
                   wanted);
      return 3;
    }
    lcm.handleTimeout(50);
  }
  return 0;
}
