#include "lcmtf/programs/program_authority.hpp"

#include "lcmtf/channels.hpp"

namespace lcmtf::programs {

std::string programAuthority(const std::string& program) {
  const std::string authority = defaultAuthority();
  return program + authority.substr(authority.find('@'));
}

}  // namespace lcmtf::programs
