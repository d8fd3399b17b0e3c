// Which Host and Origin headers the viewer answers.
#include "lcmtf_viewer/host_policy.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

namespace lcmtf::viewer {
namespace {

using testing::HasSubstr;

const HostPolicy kDefault({}, {});

TEST(HostPolicy, AddressesLocalhostAndThisMachinesNameAreAnswered) {
  for (const char* host : {"127.0.0.1", "127.0.0.1:8080", "10.1.2.3:9000", "[::1]:8080", "[::1]",
                           "localhost", "LOCALHOST:80", "localhost.:80", "viewer.localhost"}) {
    EXPECT_EQ(kDefault.refuseHost(host), std::nullopt) << host;
  }
  char name[256] = {};
  ASSERT_EQ(gethostname(name, sizeof name - 1), 0);
  EXPECT_EQ(kDefault.refuseHost(std::string(name) + ":8080"), std::nullopt);
  EXPECT_EQ(kDefault.refuseHost(std::string(name) + ".local"), std::nullopt);
}

TEST(HostPolicy, OtherNamesAreRefusedWithTheOptionThatAllowsThem) {
  EXPECT_THAT(kDefault.refuseHost("attacker.example:8080").value_or(""),
              HasSubstr("'attacker.example' is not a name of this viewer"));
  EXPECT_THAT(kDefault.refuseHost("attacker.example").value_or(""),
              HasSubstr("--allow-host attacker.example"));
  for (const char* host : {"127.0.0.1.attacker.example", "localhost.attacker.example", "127.1",
                           "0x7f000001", "[::1", "[::1]x", "a:1:2", ":8080", ""}) {
    EXPECT_NE(kDefault.refuseHost(host), std::nullopt) << host;
  }
  EXPECT_THAT(kDefault.refuseHost("evil\n.example").value_or(""), HasSubstr("evil\\x0a.example"));
}

TEST(HostPolicy, AllowedHostsAreAnsweredInAnyCase) {
  const HostPolicy policy({"Robot.Lab"}, {});
  EXPECT_EQ(policy.refuseHost("robot.lab:8080"), std::nullopt);
  EXPECT_NE(policy.refuseHost("other.lab"), std::nullopt);
  EXPECT_EQ(HostPolicy({"*"}, {}).refuseHost("anything.example"), std::nullopt);
}

TEST(HostPolicy, OnlyThePagesOwnOriginMayOpenTheWebSocket) {
  EXPECT_EQ(kDefault.refuseOrigin("http://127.0.0.1:8080", "127.0.0.1:8080"), std::nullopt);
  EXPECT_EQ(kDefault.refuseOrigin("HTTP://LocalHost:8080", "localhost:8080"), std::nullopt);
  EXPECT_EQ(kDefault.refuseOrigin("http://127.0.0.1", "127.0.0.1:80"), std::nullopt);
  EXPECT_EQ(kDefault.refuseOrigin("https://127.0.0.1", "127.0.0.1:443"), std::nullopt);
  EXPECT_EQ(kDefault.refuseOrigin("", "127.0.0.1:8080"), std::nullopt) << "not a browser";
  EXPECT_THAT(kDefault.refuseOrigin("http://attacker.example", "127.0.0.1:8080").value_or(""),
              HasSubstr("'http://attacker.example' may not open this viewer's WebSocket"));
  for (const char* origin : {"http://127.0.0.1:8081", "http://localhost:8080", "null", "file://",
                             "ws://127.0.0.1:8080", "127.0.0.1:8080"}) {
    EXPECT_NE(kDefault.refuseOrigin(origin, "127.0.0.1:8080"), std::nullopt) << origin;
  }
}

TEST(HostPolicy, AllowedOriginsMayOpenTheWebSocket) {
  const HostPolicy policy({}, {"http://Dashboard.lab:3000/"});
  EXPECT_EQ(policy.refuseOrigin("http://dashboard.lab:3000", "127.0.0.1:8080"), std::nullopt);
  EXPECT_NE(policy.refuseOrigin("http://dashboard.lab:3001", "127.0.0.1:8080"), std::nullopt);
  EXPECT_EQ(HostPolicy({}, {"*"}).refuseOrigin("null", "127.0.0.1:8080"), std::nullopt);
}

}  // namespace
}  // namespace lcmtf::viewer
