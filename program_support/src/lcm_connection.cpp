#include "lcmtf/programs/lcm_connection.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <ostream>

#include "lcmtf/programs/command_line.hpp"
#include "lcmtf/subscription_budget.hpp"

namespace lcmtf::programs {

const char* lcmBuiltInDefaultUrl() { return "udpm://239.255.76.67:7667?ttl=0"; }

namespace {

// $LCM_DEFAULT_URL, or null where it is unset or empty.
const char* urlFromEnvironment() {
  const char* from_environment = std::getenv("LCM_DEFAULT_URL");
  return from_environment && *from_environment ? from_environment : nullptr;
}

// What the URL a failure names came from.
std::string urlSource(const std::string& lcm_url) {
  if (!lcm_url.empty()) return "--lcm-url";
  return urlFromEnvironment() ? "$LCM_DEFAULT_URL" : "LCM's default URL";
}

void ignoreMessage(const lcm::ReceiveBuffer*, const std::string&, void*) {}

}  // namespace

std::string describeLcmUrl(const std::string& lcm_url) {
  if (!lcm_url.empty()) return lcm_url;
  if (const char* from_environment = urlFromEnvironment()) return from_environment;
  return lcmBuiltInDefaultUrl();
}

std::unique_ptr<lcm::LCM> openLcm(const std::string& lcm_url) {
  auto lcm = std::make_unique<lcm::LCM>(lcm_url);
  const std::string url = describeLcmUrl(lcm_url);
  if (!lcm->good()) {
    throw CommandLineError(urlSource(lcm_url) + ": cannot open LCM at '" + url + "'");
  }
  // Every program subscribes (a publisher to requests to resend): find out now, once.
  lcm::Subscription* probe =
      lcm->subscribeFunction<void*>("LCMTF_RECEIVE_CHECK", &ignoreMessage, nullptr);
  const bool receives = subscriptionMade(probe);
  lcm->unsubscribe(probe);
  if (!receives) {
    throw CommandLineError(urlSource(lcm_url) + ": LCM at '" + url + "' cannot receive (" +
                           kCannotReceiveWhy + ")");
  }
  return lcm;
}

std::unique_ptr<lcm::LCM> openLcmOrReport(const std::string& lcm_url, const std::string& program,
                                          std::ostream& err) {
  try {
    return openLcm(lcm_url);
  } catch (const CommandLineError& e) {
    err << program << ": " << e.what() << std::endl;
    return nullptr;
  }
}

bool handleLcmFor(lcm::LCM& lcm, std::chrono::milliseconds timeout, bool* handled) {
  const int milliseconds = static_cast<int>(std::clamp<std::int64_t>(timeout.count(), 0, 1000));
  errno = 0;
  const int result = lcm.handleTimeout(milliseconds);
  if (handled) *handled = result > 0;
  return result >= 0 || errno == EINTR;
}

}  // namespace lcmtf::programs
