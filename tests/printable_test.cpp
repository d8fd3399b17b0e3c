// Names from the network printed safely.
#include <gtest/gtest.h>

#include <string>

#include "lcmtf/printable.hpp"

namespace lcmtf {
namespace {

TEST(Printable, OrdinaryFrameNamesAreUnchanged) {
  EXPECT_EQ(printable("base_link"), "base_link");
  EXPECT_EQ(printable("robot1/camera optical-frame.2"), "robot1/camera optical-frame.2");
  EXPECT_EQ(printable(""), "");
}

TEST(Printable, ControlAndNonAsciiBytesBecomeHexEscapes) {
  EXPECT_EQ(printable("a\x1b[2Jb"), "a\\x1b[2Jb");
  EXPECT_EQ(printable("tab\there\nnew"), "tab\\x09here\\x0anew");
  EXPECT_EQ(printable(std::string("nul\0end", 7)), "nul\\x00end");
  EXPECT_EQ(printable("caf\xc3\xa9\x7f"), "caf\\xc3\\xa9\\x7f");
}

TEST(Printable, BackslashIsDoubledSoEscapesCannotBeForged) {
  EXPECT_EQ(printable("a\\x1b"), "a\\\\x1b");
}

TEST(Printable, ReportsKeepTheirLinesButNotOtherControlBytes) {
  EXPECT_EQ(printableLines("frames:\n  a\x1b[31m\n\n"), "frames:\n  a\\x1b[31m\n\n");
  EXPECT_EQ(printableLines("no newline\r"), "no newline\\x0d");
  EXPECT_EQ(printableLines(""), "");
}

TEST(TerminalSafe, ControlCharactersAndMalformedUtf8BecomeHexEscapes) {
  EXPECT_EQ(terminalSafe("robot 'a\x1b[2Jb'\n  root \x07\t\r"),
            "robot 'a\\x1b[2Jb'\n  root \\x07\\x09\\x0d");
  EXPECT_EQ(terminalSafe(std::string("nul\0\x7f", 5)), "nul\\x00\\x7f");
  EXPECT_EQ(terminalSafe("c1 \xc2\x9b"
                         "31m \xc2\x80"),
            "c1 \\xc2\\x9b31m \\xc2\\x80");
  EXPECT_EQ(terminalSafe("cut \xe2\x82 lone \xff \xc0\xaf"),
            "cut \\xe2\\x82 lone \\xff \\xc0\\xaf");
}

TEST(TerminalSafe, TextAlreadySafeIsUnchanged) {
  const std::string safe = "caf\xc3\xa9 \xc2\xa0\xe2\x82\xac \xf0\x9f\xa4\x96 C:\\path\n";
  EXPECT_EQ(terminalSafe(safe), safe);
  const std::string escaped = printable("a\x1b\\b\xc3\xa9");
  EXPECT_EQ(terminalSafe(escaped), escaped);
  EXPECT_EQ(terminalSafe(""), "");
}

TEST(DotQuoted, NamesFromTheNetworkAreQuotedSoTheyCannotBreakAGraph) {
  EXPECT_EQ(dotQuoted("plain"), "\"plain\"");
  EXPECT_EQ(dotQuoted("a\"b"), "\"a\\\"b\"");
  EXPECT_EQ(dotQuoted("back\\slash"), "\"back\\\\slash\"");
  EXPECT_EQ(dotQuoted("line\nbreak"), "\"line\\nbreak\"");
  EXPECT_EQ(dotQuoted(std::string("bell\x07tab\t")), "\"bell?tab?\"");
  EXPECT_EQ(dotQuoted("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\xa4\x96"),
            "\"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\xa4\x96\"");
  EXPECT_EQ(dotQuoted("\xff\xfe\xc3"), "\"???\"");
  EXPECT_EQ(dotQuoted("\xe2\x82x \xc0\xaf \xed\xa0\x80"), "\"??x ?? ???\"");
}

TEST(YamlQuoted, NamesYamlCanShowAreSingleQuoted) {
  EXPECT_EQ(yamlQuoted("base_link"), "'base_link'");
  EXPECT_EQ(yamlQuoted("it's \"here\" \\"), "'it''s \"here\" \\'");
  EXPECT_EQ(yamlQuoted("caf\xc3\xa9 \xf0\x9f\xa4\x96"), "'caf\xc3\xa9 \xf0\x9f\xa4\x96'");
  EXPECT_EQ(yamlQuoted(""), "''");
}

TEST(YamlQuoted, LineBreaksAndControlCharactersAreEscapedInDoubleQuotes) {
  EXPECT_EQ(yamlQuoted("a\nb\tc"), "\"a\\nb\\tc\"");
  EXPECT_EQ(yamlQuoted("it's \"x\" \\\x1b"), "\"it's \\\"x\\\" \\\\\\x1B\"");
  EXPECT_EQ(yamlQuoted(std::string("nul\0", 4)), "\"nul\\x00\"");
  EXPECT_EQ(yamlQuoted("nel\xc2\x85 ls\xe2\x80\xa8"), "\"nel\\x85 ls\\u2028\"");
  EXPECT_EQ(yamlQuoted("bad\xff caf\xc3\xa9"), "\"bad\\xFF caf\xc3\xa9\"");
}

}  // namespace
}  // namespace lcmtf
