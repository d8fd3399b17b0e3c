// ServedFiles: only listed paths are found; hostile request targets are refused before lookup.
#include "lcmtf_viewer/served_files.hpp"

#include <gtest/gtest.h>

namespace lcmtf::viewer {
namespace {

TEST(ServedFiles, FindsOnlyTheExactPathsListed) {
  ServedFiles files;
  files.add("/", "/srv/page/index.html");
  files.add("/js/main.js", "/srv/page/js/main.js");
  ASSERT_NE(files.find("/"), nullptr);
  EXPECT_EQ(files.find("/")->path, "/srv/page/index.html");
  EXPECT_EQ(files.find("/js/main.js")->content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(files.find("/js/main.js?v=2")->path, "/srv/page/js/main.js");
  EXPECT_EQ(files.find("/js/"), nullptr);
  EXPECT_EQ(files.find("/js/main.js/"), nullptr);
  EXPECT_EQ(files.find("/JS/main.js"), nullptr);
  EXPECT_EQ(files.find("/index.html"), nullptr);
  EXPECT_EQ(files.size(), 2u);
}

TEST(RefuseRequestTarget, AcceptsPlainPaths) {
  EXPECT_FALSE(refuseRequestTarget("/"));
  EXPECT_FALSE(refuseRequestTarget("/three/build/three.module.js"));
  EXPECT_FALSE(refuseRequestTarget("/mesh/3/link_0.dae?x=1"));
}

TEST(RefuseRequestTarget, RefusesTraversalEncodedOrNot) {
  for (const char* target :
       {"/../etc/passwd", "/three/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd",
        "/mesh/0/..%2f..%2fetc%2fpasswd", "/mesh/0/%2E%2E/x", "/a/..", "/..", "/web\\..\\x",
        "/index.html%00", "//etc/passwd", "etc/passwd", "", "/a b", "/caf\xc3\xa9"}) {
    EXPECT_TRUE(refuseRequestTarget(target).has_value()) << target;
  }
  EXPECT_EQ(*refuseRequestTarget("/../x"), "the path has '..'");
  EXPECT_EQ(*refuseRequestTarget("/%2e%2e/x"),
            "the path is percent-encoded; no file served needs that");
  EXPECT_EQ(*refuseRequestTarget(std::string_view("/a\0b", 4)), "the path has a NUL character");
  EXPECT_EQ(*refuseRequestTarget("/a\\b"), "the path has a backslash");
  EXPECT_EQ(*refuseRequestTarget(std::string(2000, 'a').insert(0, "/")),
            "the path is longer than 1024 characters");
}

TEST(ContentTypeFor, NamesWhatBrowsersAndLoadersNeed) {
  EXPECT_EQ(contentTypeFor("index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(contentTypeFor("a.CSS"), "text/css; charset=utf-8");
  EXPECT_EQ(contentTypeFor("link.STL"), "model/stl");
  EXPECT_EQ(contentTypeFor("hand.dae"), "model/vnd.collada+xml");
  EXPECT_EQ(contentTypeFor("data.bin"), "application/octet-stream");
  EXPECT_EQ(contentTypeFor("noextension"), "application/octet-stream");
}

}  // namespace
}  // namespace lcmtf::viewer
