// A lossy link for LCM's multicast traffic, run in a network namespace between two others:
// each datagram to GROUP:PORT that arrives on one of the two interfaces leaves on the other,
// except that a fifth of them are dropped and a tenth are held back, to be sent after the next
// one (or 50 ms later). Each direction draws from its own generator seeded from SEED. REPORT
// (relay_report.hpp) appears once the relay listens and is rewritten every 50 ms or so while the
// counts change, each time whole, through a draft beside it. It ends after LIFETIME_MS, so that a
// killed test leaves nothing running.
//   lossy_relay GROUP PORT INTERFACE INTERFACE SEED REPORT LIFETIME_MS
#include <arpa/inet.h>
#include <net/if.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include "network/relay_report.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr double kDropShare = 0.2;
constexpr double kHoldShare = 0.1;
constexpr auto kLongestHold = 50ms;
constexpr auto kReportPeriod = 50ms;

[[noreturn]] void fail(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), what);
}

void setOption(int socket, int level, int name, const void* value, socklen_t size,
               const char* what) {
  if (setsockopt(socket, level, name, value, size) != 0) fail(what);
}

unsigned interfaceIndex(const std::string& interface) {
  const unsigned index = if_nametoindex(interface.c_str());
  if (index == 0) fail("no interface " + interface);
  return index;
}

// Hears GROUP:PORT on `interface` only.
int openReceiver(in_addr group, std::uint16_t port, const std::string& interface) {
  const int receiver = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (receiver < 0) fail("socket");
  const int yes = 1;
  setOption(receiver, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes, "SO_REUSEADDR");
  setOption(receiver, SOL_SOCKET, SO_BINDTODEVICE, interface.c_str(),
            static_cast<socklen_t>(interface.size()), "SO_BINDTODEVICE");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr = group;
  if (bind(receiver, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    fail("bind");
  }
  ip_mreqn membership{};
  membership.imr_multiaddr = group;
  membership.imr_ifindex = static_cast<int>(interfaceIndex(interface));
  setOption(receiver, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership,
            "IP_ADD_MEMBERSHIP");
  return receiver;
}

// Sends out of `interface` to the next hop only, and never to the relay itself.
int openSender(const std::string& interface) {
  const int sender = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (sender < 0) fail("socket");
  ip_mreqn outgoing{};
  outgoing.imr_ifindex = static_cast<int>(interfaceIndex(interface));
  setOption(sender, IPPROTO_IP, IP_MULTICAST_IF, &outgoing, sizeof outgoing, "IP_MULTICAST_IF");
  const int ttl = 1;
  setOption(sender, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl, "IP_MULTICAST_TTL");
  const int loop = 0;
  setOption(sender, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop, "IP_MULTICAST_LOOP");
  return sender;
}

// What arrives on one interface, on its way out of the other.
class Direction {
 public:
  Direction(const std::string& from, const std::string& to, sockaddr_in destination, unsigned seed)
      : sender_(openSender(to)), destination_(destination), random_(seed) {
    counts_.arrived_on = from;
  }

  void onDatagram(std::vector<char> datagram, Clock::time_point now) {
    ++counts_.received;
    const double draw = std::uniform_real_distribution<double>(0.0, 1.0)(random_);
    if (draw < kDropShare) {
      ++counts_.dropped;
      return;
    }
    if (draw < kDropShare + kHoldShare && !held_) {
      held_ = std::move(datagram);
      held_since_ = now;
      return;
    }
    send(datagram);
    if (held_) {
      send(*held_);
      ++counts_.reordered;
      held_.reset();
    }
  }

  // Sends what has waited too long for a later datagram to overtake it.
  bool releaseHeldBefore(Clock::time_point deadline) {
    if (!held_ || held_since_ > deadline) return false;
    send(*held_);
    held_.reset();
    return true;
  }

  const lcmtf_test::RelayCounts& counts() const { return counts_; }

 private:
  void send(const std::vector<char>& datagram) {
    const ssize_t sent =
        sendto(sender_, datagram.data(), datagram.size(), 0,
               reinterpret_cast<const sockaddr*>(&destination_), sizeof destination_);
    if (sent < 0) fail("sendto");
    ++counts_.forwarded;
  }

  int sender_;
  sockaddr_in destination_;
  std::mt19937 random_;
  std::optional<std::vector<char>> held_;
  Clock::time_point held_since_;
  lcmtf_test::RelayCounts counts_;
};

void writeReport(const std::string& path, const std::vector<Direction>& directions) {
  std::vector<lcmtf_test::RelayCounts> report;
  for (const Direction& direction : directions) report.push_back(direction.counts());
  const std::string partial = path + ".partial";
  std::ofstream(partial) << lcmtf_test::formatRelayReport(report);
  if (std::rename(partial.c_str(), path.c_str()) != 0) fail("cannot write " + path);
}

int relay(const std::string& group_text, std::uint16_t port, const std::string (&interfaces)[2],
          unsigned seed, const std::string& report_path, std::chrono::milliseconds lifetime) {
  in_addr group{};
  if (inet_pton(AF_INET, group_text.c_str(), &group) != 1) {
    std::fprintf(stderr, "lossy_relay: not an IPv4 group: %s\n", group_text.c_str());
    return 2;
  }
  sockaddr_in destination{};
  destination.sin_family = AF_INET;
  destination.sin_port = htons(port);
  destination.sin_addr = group;

  std::vector<Direction> directions;
  directions.reserve(2);
  std::vector<pollfd> receivers;
  for (int i = 0; i < 2; ++i) {
    directions.emplace_back(interfaces[i], interfaces[1 - i], destination,
                            seed + static_cast<unsigned>(i));
    receivers.push_back(pollfd{openReceiver(group, port, interfaces[i]), POLLIN, 0});
  }
  writeReport(report_path, directions);

  const Clock::time_point end = Clock::now() + lifetime;
  Clock::time_point next_report = Clock::now();
  bool changed = false;
  std::vector<char> buffer(65536);
  while (Clock::now() < end) {
    if (poll(receivers.data(), receivers.size(), 10) < 0 && errno != EINTR) fail("poll");
    const Clock::time_point now = Clock::now();
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      if ((receivers[i].revents & POLLIN) == 0) continue;
      const ssize_t size = recv(receivers[i].fd, buffer.data(), buffer.size(), 0);
      if (size < 0) fail("recv");
      directions[i].onDatagram(std::vector<char>(buffer.begin(), buffer.begin() + size), now);
      changed = true;
    }
    for (Direction& direction : directions) {
      changed = direction.releaseHeldBefore(now - kLongestHold) || changed;
    }
    if (changed && now >= next_report) {
      writeReport(report_path, directions);
      changed = false;
      next_report = now + kReportPeriod;
    }
  }
  writeReport(report_path, directions);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: %s GROUP PORT INTERFACE INTERFACE SEED REPORT LIFETIME_MS\n",
                 argv[0]);
    return 2;
  }
  try {
    const std::string interfaces[2] = {argv[3], argv[4]};
    return relay(argv[1], static_cast<std::uint16_t>(std::atoi(argv[2])), interfaces,
                 static_cast<unsigned>(std::atoll(argv[5])), argv[6],
                 std::chrono::milliseconds(std::atoll(argv[7])));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lossy_relay: %s\n", e.what());
    return 3;
  }
}
