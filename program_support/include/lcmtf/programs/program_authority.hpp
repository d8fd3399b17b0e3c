#pragma once

#include <string>

namespace lcmtf::programs {

/// The name a program signs what it sends with: "program@host:pid", with the program's whole
/// name (the kernel's short name of a process may be cut).
std::string programAuthority(const std::string& program);

}  // namespace lcmtf::programs
