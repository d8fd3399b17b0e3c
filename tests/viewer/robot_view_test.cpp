// makeRobotView: what the page draws of a robot, on the shared real robots and the example.
#include "lcmtf_viewer/robot_view.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <set>

namespace lcmtf::viewer {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

const fs::path kShared = LCMTF_SHARED_URDF_DIR;

RobotView viewOf(const fs::path& urdf, std::vector<fs::path> package_paths = {}) {
  MeshSearch search;
  search.package_paths = std::move(package_paths);
  search.description_folder = urdf.parent_path();
  return makeRobotView(urdf::loadRobotModel(urdf.string()), search);
}

const json* findLink(const RobotView& view, const std::string& name) {
  for (const json& link : view.robot.at("links")) {
    if (link.at("name") == name) return &link;
  }
  return nullptr;
}

const json* findJoint(const RobotView& view, const std::string& name) {
  for (const json& joint : view.robot.at("joints")) {
    if (joint.at("name") == name) return &joint;
  }
  return nullptr;
}

class SharedRobots : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kShared / "panda.urdf")) GTEST_SKIP() << "no shared robots beside the project";
  }
};

TEST_F(SharedRobots, PandaMeshesAreFoundOnceEachAndServedUnderNumberedUrls) {
  const RobotView view = viewOf(kShared / "panda.urdf", {kShared / "packages"});
  EXPECT_TRUE(view.warnings.empty()) << view.robot.at("warnings").dump();
  EXPECT_EQ(view.robot.at("name"), "panda");
  EXPECT_EQ(view.robot.at("root_link"), "panda_link0");
  EXPECT_EQ(view.robot.at("links").size(), 13u);
  EXPECT_EQ(view.meshes.size(), 10u);  // the finger's visual is used twice
  std::set<std::string> urls;
  for (const json& link : view.robot.at("links")) {
    for (const json& visual : link.at("visuals")) {
      const json& geometry = visual.at("geometry");
      ASSERT_EQ(geometry.at("kind"), "mesh");
      EXPECT_EQ(geometry.at("format"), "dae");
      urls.insert(geometry.at("url").get<std::string>());
      EXPECT_EQ(visual.at("origin").size(), 7u);
    }
  }
  EXPECT_EQ(urls.size(), 10u);
  EXPECT_EQ(findLink(view, "panda_link0")->at("visuals")[0].at("geometry").at("url"),
            meshUrlPath(0, "link0.dae"));
  EXPECT_TRUE(urls.count("/mesh/0/link0.dae"));
}

TEST_F(SharedRobots, PandaFingerMimicHasNoSliderAndItsLeaderHasOneWithinLimits) {
  const RobotView view = viewOf(kShared / "panda.urdf", {kShared / "packages"});
  const json* leader = findJoint(view, "panda_finger_joint1");
  const json* follower = findJoint(view, "panda_finger_joint2");
  ASSERT_TRUE(leader && follower);
  EXPECT_TRUE(leader->at("slider").get<bool>());
  EXPECT_DOUBLE_EQ(leader->at("lower").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(leader->at("upper").get<double>(), 0.04);
  EXPECT_FALSE(follower->at("slider").get<bool>());
  EXPECT_EQ(follower->at("mimic").at("leader"), "panda_finger_joint1");
}

TEST_F(SharedRobots, G1MeshesMissingAreWarningsAndEveryLinkIsStillListed) {
  const RobotView view = viewOf(kShared / "unitree_g1_29dof.urdf");
  EXPECT_EQ(view.robot.at("links").size(), 39u);
  EXPECT_TRUE(view.meshes.empty());
  ASSERT_FALSE(view.warnings.empty());
  EXPECT_THAT(view.warnings.front(), HasSubstr("': mesh '"));
  EXPECT_EQ(view.robot.at("warnings").size(), view.warnings.size());
  std::size_t sliders = 0;
  for (const json& joint : view.robot.at("joints")) sliders += joint.at("slider").get<bool>();
  EXPECT_EQ(sliders, 29u);
}

TEST_F(SharedRobots, R2d2ShapesAndColoursAreGivenAsTheUrdfSays) {
  const RobotView view = viewOf(kShared / "r2d2_flexible.urdf");
  const json& base = findLink(view, "base_link")->at("visuals")[0];
  EXPECT_EQ(base.at("geometry"), json({{"kind", "cylinder"}, {"radius", 0.2}, {"length", 0.6}}));
  EXPECT_EQ(base.at("color"), json({0.0, 0.0, 0.8, 1.0}));  // "blue", defined once at the top
  const json& head = findLink(view, "head")->at("visuals")[0];
  EXPECT_EQ(head.at("geometry"), json({{"kind", "sphere"}, {"radius", 0.2}}));
  EXPECT_EQ(head.at("color"), json({1.0, 1.0, 1.0, 1.0}));
  const json& box = findLink(view, "box")->at("visuals")[0];
  EXPECT_EQ(box.at("geometry"), json({{"kind", "box"}, {"size", {0.08, 0.08, 0.08}}}));
  // The gripper's meshes are in a package that is not here.
  EXPECT_TRUE(findLink(view, "left_gripper")->at("visuals").empty());
  EXPECT_THAT(view.robot.at("warnings").dump(),
              HasSubstr("package://urdf_tutorial/meshes/l_finger.dae"));
}

TEST_F(SharedRobots, ContinuousJointsSlideOverAWholeTurn) {
  const RobotView view = viewOf(kShared / "r2d2_flexible.urdf");
  const json* wheel = findJoint(view, "left_front_wheel_joint");
  ASSERT_NE(wheel, nullptr);
  EXPECT_EQ(wheel->at("type"), "continuous");
  EXPECT_DOUBLE_EQ(wheel->at("lower").get<double>(), -M_PI);
  EXPECT_DOUBLE_EQ(wheel->at("upper").get<double>(), M_PI);
}

TEST(RobotView, ExampleRobotHasFixedJointsWithoutSliders) {
  const RobotView view = viewOf(EXAMPLE_URDF);
  EXPECT_EQ(view.robot.at("name"), "mobile_manipulator");
  bool saw_fixed = false;
  for (const json& joint : view.robot.at("joints")) {
    if (joint.at("type") == "fixed") {
      saw_fixed = true;
      EXPECT_FALSE(joint.at("slider").get<bool>());
    }
  }
  EXPECT_TRUE(saw_fixed);
}

TEST(RobotView, MeshesOfOtherFormatsAreNotServed) {
  const fs::path folder =
      fs::temp_directory_path() / ("lcmtf_robot_view_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "part.obj") << "v 0 0 0\n";
  const std::string urdf = R"(<robot name="r"><link name="base"><visual><geometry>
      <mesh filename="part.obj"/></geometry></visual></link></robot>)";
  MeshSearch search;
  search.description_folder = folder;
  const RobotView view = makeRobotView(urdf::parseRobotModel(urdf, "test"), search);
  fs::remove_all(folder);
  EXPECT_TRUE(view.meshes.empty());
  ASSERT_EQ(view.warnings.size(), 1u);
  EXPECT_EQ(view.warnings[0],
            "link 'base': mesh 'part.obj' is neither STL nor COLLADA, which are what is drawn");
}

TEST(MeshUrlPath, KeepsOnlyPlainCharactersOfTheFileName) {
  EXPECT_EQ(meshUrlPath(3, "/x/y/Link 1 (copy).STL"), "/mesh/3/Link_1__copy_.STL");
  EXPECT_EQ(meshUrlPath(0, "/x/..stl"), "/mesh/0/_.stl");
}

}  // namespace
}  // namespace lcmtf::viewer
