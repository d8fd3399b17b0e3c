#pragma once

#include <chrono>
#include <iosfwd>
#include <memory>
#include <string>

#include <lcm/lcm-cpp.hpp>

namespace lcmtf::programs {

/// The URL an LCM opened on `lcm_url` uses, spelled out for messages ("" is
/// $LCM_DEFAULT_URL, else LCM's built-in default).
std::string describeLcmUrl(const std::string& lcm_url);

/// The URL LCM uses when none is given and $LCM_DEFAULT_URL is not set.
const char* lcmBuiltInDefaultUrl();

/// An LCM on `lcm_url`; CommandLineError "--lcm-url: cannot open LCM at 'URL'" when it cannot
/// be opened, or "... cannot receive" when it cannot subscribe (naming $LCM_DEFAULT_URL or
/// LCM's default URL instead of --lcm-url when `lcm_url` is empty).
std::unique_ptr<lcm::LCM> openLcm(const std::string& lcm_url);

/// openLcm, with a failure reported on `err` as "program: message"; null when it failed (the
/// program then exits with kExitBadArguments).
std::unique_ptr<lcm::LCM> openLcmOrReport(const std::string& lcm_url, const std::string& program,
                                          std::ostream& err);

/// lcm.handleTimeout that takes a wait cut short by a signal as nothing handled. Returns
/// false only when LCM itself fails; `handled` says whether a message was dispatched.
bool handleLcmFor(lcm::LCM& lcm, std::chrono::milliseconds timeout, bool* handled = nullptr);

}  // namespace lcmtf::programs
