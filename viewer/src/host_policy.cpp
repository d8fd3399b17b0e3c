#include "lcmtf_viewer/host_policy.hpp"

#include <algorithm>
#include <boost/asio/ip/address.hpp>

#include "ascii_lowercase.hpp"
#include "lcmtf/printable.hpp"
#include "machine_name.hpp"

namespace lcmtf::viewer {

namespace {

// The name in host[:port] or [v6-address][:port]; nothing when the text is not one.
std::optional<std::string> nameOf(std::string_view authority) {
  if (!authority.empty() && authority.front() == '[') {
    const std::size_t close = authority.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    const std::string_view rest = authority.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return std::nullopt;
    return std::string(authority.substr(0, close + 1));
  }
  const std::size_t colon = authority.find(':');
  if (colon != std::string_view::npos && authority.find(':', colon + 1) != std::string_view::npos) {
    return std::nullopt;
  }
  std::string name(authority.substr(0, colon));
  if (!name.empty() && name.back() == '.') name.pop_back();
  if (name.empty()) return std::nullopt;
  return name;
}

bool isAddress(const std::string& name) {
  boost::system::error_code error;
  if (name.front() == '[' && name.back() == ']') {
    boost::asio::ip::make_address_v6(name.substr(1, name.size() - 2), error);
  } else {
    boost::asio::ip::make_address_v4(name, error);
  }
  return !error;
}

bool endsWith(const std::string& text, std::string_view end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// scheme://authority with the scheme's own port left out, so http://a and a:80 compare equal.
std::string withoutDefaultPort(const std::string& scheme, std::string authority) {
  const std::string_view port = scheme == "https" ? ":443" : ":80";
  if (endsWith(authority, port)) authority.resize(authority.size() - port.size());
  return authority;
}

}  // namespace

HostPolicy::HostPolicy(std::vector<std::string> allowed_hosts,
                       std::vector<std::string> allowed_origins)
    : machine_name_(asciiLowercase(machineName())) {
  for (const std::string& host : allowed_hosts) allowed_hosts_.push_back(asciiLowercase(host));
  for (std::string origin : allowed_origins) {
    while (!origin.empty() && origin.back() == '/') origin.pop_back();
    allowed_origins_.push_back(asciiLowercase(origin));
  }
}

bool HostPolicy::isOwnName(const std::string& name) const {
  if (name == "localhost" || endsWith(name, ".localhost") || isAddress(name)) return true;
  if (!machine_name_.empty() && (name == machine_name_ || name == machine_name_ + ".local")) {
    return true;
  }
  return std::any_of(allowed_hosts_.begin(), allowed_hosts_.end(),
                     [&](const std::string& allowed) { return allowed == "*" || allowed == name; });
}

std::optional<std::string> HostPolicy::refuseHost(std::string_view host) const {
  const std::optional<std::string> name = nameOf(asciiLowercase(host));
  if (!name) return "the Host header '" + printable(host) + "' is not a host name";
  if (isOwnName(*name)) return std::nullopt;
  return "'" + printable(*name) +
         "' is not a name of this viewer (an address, localhost or this machine's name are); "
         "start it with --allow-host " +
         printable(*name) + " to answer to it";
}

std::optional<std::string> HostPolicy::refuseOrigin(std::string_view origin,
                                                    std::string_view host) const {
  if (origin.empty()) return std::nullopt;
  std::string page = asciiLowercase(origin);
  while (!page.empty() && page.back() == '/') page.pop_back();
  if (std::any_of(allowed_origins_.begin(), allowed_origins_.end(),
                  [&](const std::string& allowed) { return allowed == "*" || allowed == page; })) {
    return std::nullopt;
  }
  const std::size_t separator = page.find("://");
  if (separator != std::string::npos) {
    const std::string scheme = page.substr(0, separator);
    if ((scheme == "http" || scheme == "https") &&
        withoutDefaultPort(scheme, page.substr(separator + 3)) ==
            withoutDefaultPort(scheme, asciiLowercase(host))) {
      return std::nullopt;
    }
  }
  return "a page from '" + printable(origin) +
         "' may not open this viewer's WebSocket, only its own pages may; start it with "
         "--allow-origin " +
         printable(origin) + " to let it";
}

}  // namespace lcmtf::viewer
