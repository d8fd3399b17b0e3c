#include "lcmtf/channels.hpp"

#include <unistd.h>

#include <array>
#include <fstream>

namespace lcmtf {

std::string defaultAuthority() {
  std::string program;
  std::ifstream comm("/proc/self/comm");
  std::getline(comm, program);
  if (program.empty()) program = "lcmtf";
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  return program + "@" + (host[0] ? std::string(host.data()) : std::string("localhost")) + ":" +
         std::to_string(getpid());
}

}  // namespace lcmtf
