// BufferCore::allFramesAsYaml read back by a YAML parser gives every frame name exactly, however
// hostile the names the network sent.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "lcmtf/buffer_core.hpp"

namespace lcmtf {
namespace {

TEST(FramesYaml, EveryNameReadsBackAsItWasSent) {
  const std::vector<std::string> names{"plain",
                                       "it's",
                                       "line\nbreak",
                                       "tab\there",
                                       "bell\x07",
                                       "cr\rlf",
                                       "quote\"back\\",
                                       "caf\xc3\xa9",
                                       "robot \xf0\x9f\xa4\x96",
                                       "nel\xc2\x85",
                                       "ls\xe2\x80\xa8",
                                       "bom\xef\xbb\xbf",
                                       "c1\xc2\x9b[2J",
                                       "a: b",
                                       "- dash",
                                       "#hash",
                                       "  spaces  ",
                                       "{flow}",
                                       "*alias",
                                       "~",
                                       "null",
                                       "\x7f"};
  BufferCore buffer;
  for (const std::string& name : names) {
    ASSERT_TRUE(buffer.setTransform({TimePoint{}, "root", name, Transform()}, "test", true))
        << name;
  }
  const YAML::Node yaml = YAML::Load(buffer.allFramesAsYaml());
  ASSERT_TRUE(yaml.IsMap());
  ASSERT_EQ(yaml.size(), names.size());
  for (const std::string& name : names) {
    ASSERT_TRUE(yaml[name]) << "missing: " << name;
    EXPECT_EQ(yaml[name]["parent"].as<std::string>(), "root") << name;
  }
}

TEST(FramesYaml, AMalformedUtf8ByteReadsBackAsTheCharacterOfItsValue) {
  BufferCore buffer;
  ASSERT_TRUE(buffer.setTransform({TimePoint{}, "root", "bad\xff", Transform()}, "test", true));
  const YAML::Node yaml = YAML::Load(buffer.allFramesAsYaml());
  EXPECT_TRUE(yaml["bad\xc3\xbf"]) << buffer.allFramesAsYaml();
}

}  // namespace
}  // namespace lcmtf
