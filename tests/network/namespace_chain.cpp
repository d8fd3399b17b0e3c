#include "network/namespace_chain.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <optional>
#include <vector>

#include "network/in_namespace.hpp"

namespace lcmtf_test {

namespace {

constexpr const char* kPrefix = "lcmtf-";
constexpr const char* kNamespaceDirectory = "/var/run/netns";
constexpr const char* kToRelay = "to-relay";

std::string findIp() {
  for (const char* path : {"/usr/sbin/ip", "/sbin/ip", "/usr/bin/ip", "/bin/ip"}) {
    if (access(path, X_OK) == 0) return path;
  }
  return "";
}

std::optional<int> run(const std::string& program, const std::vector<std::string>& arguments) {
  ChildProcess process(program, arguments);
  return process.waitForExit(std::chrono::seconds(20));
}

bool processIsGone(const std::string& pid_text) {
  try {
    const long pid = std::stol(pid_text);
    return pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
  } catch (const std::exception&) {
    return false;
  }
}

// Namespaces named by a run of this code whose process has died (killed at a timeout, say).
void removeLeftovers(const std::string& ip) {
  std::vector<std::string> gone;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(kNamespaceDirectory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kPrefix, 0) != 0) continue;
    const std::size_t pid_start = std::string(kPrefix).size();
    const std::size_t pid_end = name.find('-', pid_start);
    if (pid_end != std::string::npos &&
        processIsGone(name.substr(pid_start, pid_end - pid_start))) {
      gone.push_back(name);
    }
  }
  for (const std::string& name : gone) run(ip, {"netns", "delete", name});
}

}  // namespace

NamespaceChain::OwnedNamespaces::~OwnedNamespaces() {
  for (const std::string& name : names) run(ip, {"netns", "delete", name});
}

NamespaceChain::NamespaceChain() {
  if (geteuid() != 0) throw NamespacesUnavailable("making network namespaces needs root");
  owned_.ip = findIp();
  if (owned_.ip.empty()) throw NamespacesUnavailable("no `ip` program (iproute2) was found");
  removeLeftovers(owned_.ip);

  const std::string prefix = kPrefix + std::to_string(getpid()) + "-";
  sender_ = prefix + "sender";
  relay_ = prefix + "relay";
  receiver_ = prefix + "receiver";
  for (const std::string* name : {&sender_, &relay_, &receiver_}) create(*name);

  ip({"-n", sender_, "link", "add", kToRelay, "type", "veth", "peer", "name", kRelayToSender,
      "netns", relay_});
  ip({"-n", receiver_, "link", "add", kToRelay, "type", "veth", "peer", "name", kRelayToReceiver,
      "netns", relay_});
  const struct {
    const std::string& name;
    const char* interface;
    const char* address;
  } ends[] = {{sender_, kToRelay, "10.231.1.1/24"},
              {relay_, kRelayToSender, "10.231.1.2/24"},
              {relay_, kRelayToReceiver, "10.231.2.1/24"},
              {receiver_, kToRelay, "10.231.2.2/24"}};
  for (const auto& end : ends) {
    ip({"-n", end.name, "address", "add", end.address, "dev", end.interface});
    ip({"-n", end.name, "link", "set", end.interface, "up"});
  }
  for (const std::string* name : {&sender_, &receiver_}) {
    ip({"-n", *name, "route", "add", "224.0.0.0/4", "dev", kToRelay});
  }
}

void NamespaceChain::create(const std::string& name) {
  ip({"netns", "add", name});
  owned_.names.push_back(name);
  ip({"-n", name, "link", "set", "lo", "up"});
}

void NamespaceChain::ip(const std::vector<std::string>& arguments) const {
  const std::optional<int> status = run(owned_.ip, arguments);
  if (status == 0) return;
  std::string command = "ip";
  for (const std::string& argument : arguments) command += " " + argument;
  throw NamespacesUnavailable(
      "`" + command + "` " +
      (status ? "failed with status " + std::to_string(*status) : std::string("did not finish")) +
      " (ip's message, if any, is above)");
}

std::unique_ptr<ChildProcess> NamespaceChain::start(
    const std::string& name, const std::string& program,
    const std::vector<std::string>& arguments) const {
  std::unique_ptr<ChildProcess> child;  // a process begins in the namespace of its parent thread
  runInNamespace(name, [&] { child = std::make_unique<ChildProcess>(program, arguments); });
  return child;
}

}  // namespace lcmtf_test
