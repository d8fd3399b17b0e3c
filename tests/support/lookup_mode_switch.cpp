// Linked into the lookup suites: with LCMTF_TEST_LOOKUPS=walk in the environment, every lookup
// in the program walks the tree edge by edge instead of taking the root paths.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "lookup_mode.hpp"

namespace {

class LookupModeSwitch : public ::testing::Environment {
 public:
  void SetUp() override {
    const char* mode = std::getenv("LCMTF_TEST_LOOKUPS");
    const bool walk_only = mode != nullptr && std::string(mode) == "walk";
    lcmtf::detail::setQuickLookupsEnabled(!walk_only);
    if (walk_only) std::printf("Lookups walk the tree edge by edge: quick lookups are off.\n");
  }
};

const ::testing::Environment* const kLookupModeSwitch =
    ::testing::AddGlobalTestEnvironment(new LookupModeSwitch);

}  // namespace
