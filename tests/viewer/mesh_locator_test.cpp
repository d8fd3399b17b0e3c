// locateMesh: package://, file:// and relative names, each confined to where it may look.
#include "lcmtf_viewer/mesh_locator.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace lcmtf::viewer {
namespace {

namespace fs = std::filesystem;

class MeshLocator : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("lcmtf_mesh_locator_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    write(root_ / "packages/arm/meshes/base.stl");
    write(root_ / "solo_pkg/meshes/tool.dae");
    write(root_ / "robot/parts/wheel.stl");
    write(root_ / "secret.txt");
    fs::create_symlink(root_ / "secret.txt", root_ / "packages/arm/meshes/leak.stl");
    search_.package_paths = {root_ / "packages", root_ / "solo_pkg"};
  }
  void TearDown() override { fs::remove_all(root_); }

  static void write(const fs::path& path) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "solid x\nendsolid x\n";
  }
  fs::path found(const std::string& name) const {
    const auto result = locateMesh(name, search_);
    if (const std::string* why = std::get_if<std::string>(&result)) {
      ADD_FAILURE() << name << ": " << *why;
      return {};
    }
    return std::get<fs::path>(result);
  }
  std::string refused(const std::string& name) const {
    const auto result = locateMesh(name, search_);
    if (std::holds_alternative<fs::path>(result)) {
      ADD_FAILURE() << name << " was found at " << std::get<fs::path>(result);
      return {};
    }
    return std::get<std::string>(result);
  }

  fs::path root_;
  MeshSearch search_;
};

TEST_F(MeshLocator, FindsPackageFilesUnderAFolderOfPackagesOrAFolderNamedAsThePackage) {
  EXPECT_EQ(found("package://arm/meshes/base.stl"),
            fs::canonical(root_ / "packages/arm/meshes/base.stl"));
  EXPECT_EQ(found("package://solo_pkg/meshes/tool.dae"),
            fs::canonical(root_ / "solo_pkg/meshes/tool.dae"));
}

TEST_F(MeshLocator, RefusesPackageNamesThatLeadOutOfThePackage) {
  EXPECT_NE(refused("package://arm/../../secret.txt").find("not found in the package paths"),
            std::string::npos);
  EXPECT_FALSE(refused("package://arm/meshes/leak.stl").empty());  // a link to outside
  EXPECT_FALSE(refused("package://arm/meshes/").empty());          // a folder
  EXPECT_EQ(refused("package://arm"), "'package://arm' names no file inside a package");
  EXPECT_FALSE(refused("package://nothing/base.stl").empty());
  EXPECT_EQ(refused("package://../secret.txt"),
            "'package://../secret.txt': '..' is not a package name");
  EXPECT_EQ(refused("package://./arm/meshes/base.stl"),
            "'package://./arm/meshes/base.stl': '.' is not a package name");
}

TEST_F(MeshLocator, ServesAbsoluteAndFileNamesOnlyInsideThePackagePaths) {
  const std::string inside = (root_ / "packages/arm/meshes/base.stl").string();
  EXPECT_EQ(found("file://" + inside), fs::canonical(inside));
  EXPECT_EQ(found(inside), fs::canonical(inside));
  EXPECT_EQ(refused("file:///etc/passwd"),
            "'file:///etc/passwd' is not a readable file inside the package paths");
  EXPECT_FALSE(refused("file://" + (root_ / "secret.txt").string()).empty());
  EXPECT_FALSE(refused("file://" + (root_ / "packages/../secret.txt").string()).empty());
  EXPECT_EQ(refused("file://relative/x.stl"),
            "'file://relative/x.stl' is not an absolute file:// path");
  EXPECT_EQ(refused("http://example.com/x.stl"),
            "'http://example.com/x.stl': only package:// and file:// are resolved");
}

TEST_F(MeshLocator, FindsRelativeNamesBesideTheDescriptionFileOnly) {
  EXPECT_EQ(refused("parts/wheel.stl"),
            "'parts/wheel.stl' is relative, and the description came with no folder");
  search_.description_folder = root_ / "robot";
  EXPECT_EQ(found("parts/wheel.stl"), fs::canonical(root_ / "robot/parts/wheel.stl"));
  EXPECT_EQ(found((root_ / "robot/parts/wheel.stl").string()),
            fs::canonical(root_ / "robot/parts/wheel.stl"));
  EXPECT_FALSE(refused("../secret.txt").empty());
}

TEST_F(MeshLocator, SaysWhereItLookedWhenAPackageFileIsMissing) {
  EXPECT_EQ(refused("package://arm/meshes/gone.stl"),
            "'package://arm/meshes/gone.stl' not found in the package paths (" +
                (root_ / "packages").string() + ", " + (root_ / "solo_pkg").string() + ")");
  search_.package_paths.clear();
  EXPECT_EQ(refused("package://arm/meshes/base.stl"),
            "'package://arm/meshes/base.stl': no package paths to look in (give --package-path)");
}

TEST(SplitPackagePath, SkipsEmptyEntries) {
  EXPECT_EQ(splitPackagePath("/a:/b::/c:"), (std::vector<fs::path>{"/a", "/b", "/c"}));
  EXPECT_TRUE(splitPackagePath("").empty());
}

TEST(MeshLocatorSharedRobots, FindsThePandasMeshesInTheSharedPackages) {
  const fs::path shared = LCMTF_SHARED_URDF_DIR;
  if (!fs::exists(shared / "packages")) GTEST_SKIP() << "no shared robots beside the project";
  MeshSearch search;
  search.package_paths = {shared / "packages"};
  const auto result = locateMesh(
      "package://example-robot-data/robots/panda_description/meshes/visual/link0.dae", search);
  ASSERT_TRUE(std::holds_alternative<fs::path>(result)) << std::get<std::string>(result);
}

}  // namespace
}  // namespace lcmtf::viewer
