#include "support/test_lcm.hpp"

#include <unistd.h>

#include <functional>

namespace lcmtf_test {

std::string privateUdpmUrl(const std::string& test_name) {
  // Below the kernel's ephemeral ports (from 32768), which any socket may hold without
  // SO_REUSEADDR: LCM's bind of such a port fails, and it cannot receive.
  constexpr std::size_t kFirstPort = 20000;
  constexpr std::size_t kPortCount = 12000;
  const std::size_t seed =
      std::hash<std::string>{}(test_name) ^ (static_cast<std::size_t>(getpid()) * 2654435761u);
  const std::size_t port = kFirstPort + seed % kPortCount;
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

}  // namespace lcmtf_test
