#pragma once

#include <string>

namespace lcmtf_test {

/// A udpm URL with ttl=0 (traffic stays on this machine) on a port of this test's own:
/// derived from `test_name` and the process id, so parallel tests and runs do not hear each other.
std::string privateUdpmUrl(const std::string& test_name);

}  // namespace lcmtf_test
