// Counting a description's nesting, elements and links before it is parsed, the markup that
// hides elements and the markup that does not, and the limits at their edges.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lcmtf_urdf/description_limits.hpp"
#include "lcmtf_urdf/robot_model.hpp"

namespace lcmtf::urdf {
namespace {

std::string repeated(const std::string& piece, std::size_t times) {
  std::string text;
  text.reserve(piece.size() * times);
  for (std::size_t i = 0; i < times; ++i) text += piece;
  return text;
}

std::string shapeOf(std::string_view text) {
  const DescriptionShape shape = measureDescription(text);
  return std::to_string(shape.deepest_nesting) + " deep, " + std::to_string(shape.elements) +
         " elements, " + std::to_string(shape.links) + " links";
}

std::string nestedLevels(std::size_t levels) {
  return repeated("<x>", levels) + repeated("</x>", levels);
}

std::string refusal(const std::string& text, const DescriptionLimits& limits = {}) {
  try {
    refuseOversizedDescription(text, "test.urdf", limits);
  } catch (const UrdfError& e) {
    return e.what();
  }
  return "";
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

TEST(DescriptionLimits, DeepestNestingIsTheLevelOfTheDeepestElement) {
  EXPECT_EQ(shapeOf("<r><a><b/></a><c></c></r>"), "3 deep, 4 elements, 0 links");
  EXPECT_EQ(shapeOf("<r/><r><a/></r>"), "2 deep, 3 elements, 0 links");
}

TEST(DescriptionLimits, ClosingTagsReturnToTheParentLevelAndNeverBelowTheDocument) {
  EXPECT_EQ(shapeOf("<r><a></a><a></a><a></a></r>"), "2 deep, 4 elements, 0 links");
  EXPECT_EQ(shapeOf("</x></x></x><r><a/></r>"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><a></a\n></r><q><w/></q>"), "2 deep, 4 elements, 0 links");
}

TEST(DescriptionLimits, LinksAreTheElementsNamedLinkExactly) {
  EXPECT_EQ(shapeOf("<robot name='r'><link name='a'/><link\tname='b'></link><links/><linkage/>"
                    "<xacro:link/><joint name='j'><parent link='a'/><child link='b'/></joint>"
                    "<Link/></robot>"),
            "3 deep, 10 elements, 2 links");
}

// TinyXML reading UTF-8 skips these between '<' and the name: each is a link to it.
TEST(DescriptionLimits, LinksNamedAfterByteOrderMarksAndWhitespaceAreLinks) {
  EXPECT_EQ(shapeOf("<?xml version='1.0'?><robot name='r'><\xEF\xBB\xBFlink name='a'/>"
                    "<\xEF\xBF\xBE link name='b'/><\xEF\xBF\xBF\xEF\xBB\xBF\tlink name='c'>"
                    "</link><\xEF\xBB\xBFlinks/><link\xEF\xBB\xBF/></robot>"),
            "2 deep, 6 elements, 3 links");
}

TEST(DescriptionLimits, LinksBehindByteOrderMarksCountTowardsTheLimit) {
  const DescriptionLimits limits;
  const std::string link = "<\xEF\xBB\xBFlink name='l'/>";
  EXPECT_EQ(
      refusal("<?xml version='1.0'?><robot>" + repeated(link, limits.max_links + 1) + "</robot>"),
      "test.urdf: 10001 links; the limit is 10000");
}

TEST(DescriptionLimits, CommentsHideTheirMarkupUpToTheFirstEndAfterTheStart) {
  EXPECT_EQ(shapeOf("<r><!-- <a><b><link/> --></r>"), "1 deep, 1 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><!--></a></r>--><a/></r>"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><!-- -- > --><a/></r>"), "2 deep, 2 elements, 0 links");
}

TEST(DescriptionLimits, CdataHidesItsMarkupButOnlyInCapitals) {
  EXPECT_EQ(shapeOf("<r><![CDATA[ <a><b></r> ]]><c/></r>"), "2 deep, 2 elements, 0 links");
  // TinyXML reads a lowercase one as unknown markup that ends at the first '>'.
  EXPECT_EQ(shapeOf("<r><![cdata[ x> <a><b/></a> ]]></r>"), "3 deep, 3 elements, 0 links");
}

TEST(DescriptionLimits, InstructionsAndDoctypesEndAtTheirFirstGreaterThanEvenInQuotes) {
  EXPECT_EQ(shapeOf("<r><?pi a>b <x/> ?></r>"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><?pi a='>'<x/>'?></r>"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<!DOCTYPE r [ <!ENTITY e 'v'> ]><r><a/></r>"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<!DOCTYPE a=\"> <!--\" ><r><a/></r>-->"), "0 deep, 0 elements, 0 links");
}

TEST(DescriptionLimits, XmlDeclarationsEndAtTheirFirstGreaterThan) {
  const std::string text =
      "<?xml version=\"1.0\" encoding='UTF-8' standalone=\"yes\"?>\n<r><?XML version='1'><a/></r>";
  EXPECT_EQ(shapeOf(text), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(measureDescription(text).unreadable, "");
}

TEST(DescriptionLimits, XmlDeclarationsWithWhitespaceOrGreaterThanInQuotesAreUnreadable) {
  for (const char* text : {"<?xml version='1>'?><r/>", "<r><?xml version=\"a b\"?><q/></r>",
                           "<r><?xml foo=\" version='x\" ?><q/>'<w/></r>",
                           "<?xmlversion=\"><!--\"><p", "<?xml version='1.0?><r/>"}) {
    EXPECT_EQ(measureDescription(text).unreadable,
              "an XML declaration with whitespace or '>' inside quotes")
        << text;
  }
  EXPECT_EQ(refusal("<?xml version='1 '?><r/>"),
            "test.urdf: an XML declaration with whitespace or '>' inside quotes, which the size "
            "check cannot read");
}

TEST(DescriptionLimits, Utf8CharactersCutShortByAsciiAreUnreadable) {
  // TinyXML reading UTF-8 would take the '<' after \xC3 as part of a character.
  for (const char* text :
       {"\xEF\xBB\xBF<s>\xC3<<k", "<r>\xE2\x82<a/></r>", "<r>\xF0\x9F\x98</r>", "<r/>\xC3"}) {
    EXPECT_EQ(measureDescription(text).unreadable,
              "bytes that are not UTF-8 (a character cut short)")
        << text;
  }
  EXPECT_EQ(measureDescription("<r name='caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80'/>").unreadable,
            "");
  EXPECT_EQ(refusal("<r>\xC3</r>"),
            "test.urdf: bytes that are not UTF-8 (a character cut short), which the size check "
            "cannot read");
}

TEST(DescriptionLimits, QuotedAttributeValuesMayHoldGreaterThanSlashAndMarkup) {
  EXPECT_EQ(shapeOf("<r a='>' b=\"/>\"><x c=\"</r><y>\" d='\"'/><z e=\"'\"></z></r>"),
            "2 deep, 3 elements, 0 links");
}

TEST(DescriptionLimits, SelfClosingTagsDoNotNestWhateverTheirAttributes) {
  EXPECT_EQ(shapeOf("<r><a/><a /><a b='1'/><a\nb=\"2\"\n/><a b=c/><link/></r>"),
            "2 deep, 7 elements, 1 links");
}

TEST(DescriptionLimits, LessThanWithoutANameIsNoElement) {
  EXPECT_EQ(shapeOf("<r><1a><-b><:c>< d></r>"), "1 deep, 1 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><_a><\xC3\xA9/></_a></r>"), "3 deep, 3 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><\x7f/></r>"),
            "2 deep, 2 elements, 0 links");  // DEL is a letter to TinyXML
}

TEST(DescriptionLimits, UnfinishedMarkupRunsToTheEndOfTheText) {
  EXPECT_EQ(shapeOf("<r><!-- <a><b>"), "1 deep, 1 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><![CDATA[ <a><b>"), "1 deep, 1 elements, 0 links");
  EXPECT_EQ(shapeOf("<r a='<b><c>"), "1 deep, 1 elements, 0 links");
  EXPECT_EQ(shapeOf("<r><a"), "2 deep, 2 elements, 0 links");
  EXPECT_EQ(shapeOf("<"), "0 deep, 0 elements, 0 links");
  EXPECT_EQ(shapeOf(""), "0 deep, 0 elements, 0 links");
}

TEST(DescriptionLimits, AMillionLevelsAreMeasuredWithoutRecursion) {
  EXPECT_EQ(measureDescription(repeated("<x>", 1'000'000)).deepest_nesting, 1'000'000u);
}

TEST(DescriptionLimits, NestingAtTheLimitIsAcceptedAndOneDeeperRefused) {
  const DescriptionLimits limits;
  EXPECT_EQ(refusal(nestedLevels(limits.max_nesting)), "");
  EXPECT_EQ(refusal(nestedLevels(limits.max_nesting + 1)),
            "test.urdf: elements nested 257 deep; the limit is 256");
  EXPECT_EQ(refusal("<robot name='d'>" + repeated("<x>", 40'000)),
            "test.urdf: elements nested 40001 deep; the limit is 256");
}

TEST(DescriptionLimits, LinksAtTheLimitAreAcceptedAndOneMoreRefused) {
  const DescriptionLimits limits;
  const std::string link = "<link name='l'/>";
  EXPECT_EQ(refusal("<robot>" + repeated(link, limits.max_links) + "</robot>"), "");
  EXPECT_EQ(refusal("<robot>" + repeated(link, limits.max_links + 1) + "</robot>"),
            "test.urdf: 10001 links; the limit is 10000");
}

TEST(DescriptionLimits, ElementsAtTheLimitAreAcceptedAndOneMoreRefused) {
  const DescriptionLimits limits;
  EXPECT_EQ(refusal("<robot>" + repeated("<a/>", limits.max_elements - 1) + "</robot>"), "");
  EXPECT_EQ(refusal("<robot>" + repeated("<a/>", limits.max_elements) + "</robot>"),
            "test.urdf: 200001 XML elements; the limit is 200000");
}

TEST(DescriptionLimits, NestingIsNamedFirstThenLinksWhenSeveralLimitsAreExceeded) {
  DescriptionLimits tight;
  tight.max_nesting = 2;
  tight.max_links = 1;
  tight.max_elements = 1;
  const std::string text = "<robot><link><x/></link><link/></robot>";
  EXPECT_EQ(refusal(text, tight), "test.urdf: elements nested 3 deep; the limit is 2");
  tight.max_nesting = 3;
  EXPECT_EQ(refusal(text, tight), "test.urdf: 2 links; the limit is 1");
  tight.max_links = 2;
  EXPECT_EQ(refusal(text, tight), "test.urdf: 4 XML elements; the limit is 1");
}

TEST(DescriptionLimits, RealRobotsAreFarWithinTheLimits) {
  std::vector<std::filesystem::path> robots{EXAMPLE_URDF};
  for (const auto& entry : std::filesystem::directory_iterator(LCMTF_SHARED_URDF_DIR)) {
    if (entry.path().extension() == ".urdf") robots.push_back(entry.path());
  }
  ASSERT_GE(robots.size(), 5u);
  const DescriptionLimits limits;
  for (const std::filesystem::path& robot : robots) {
    const DescriptionShape shape = measureDescription(readFile(robot));
    EXPECT_GE(shape.links, 10u) << robot;
    EXPECT_LE(shape.deepest_nesting * 16, limits.max_nesting) << robot;
    EXPECT_LE(shape.links * 100, limits.max_links) << robot;
    EXPECT_LE(shape.elements * 100, limits.max_elements) << robot;
  }
}

TEST(DescriptionLimits, ParsingRefusesOversizedTextBeforeTheXmlParserSeesIt) {
  try {
    parseRobotModel("<robot name='d'>" + repeated("<x>", 100'000), "deep.urdf");
    FAIL() << "a description 100001 levels deep was parsed";
  } catch (const UrdfError& e) {
    EXPECT_STREQ(e.what(), "deep.urdf: elements nested 100001 deep; the limit is 256");
  }
}

}  // namespace
}  // namespace lcmtf::urdf
