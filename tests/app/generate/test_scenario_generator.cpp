// `handover generate`: reproducible, valid, and covering the space the
// benchmark promises (docs/benchmark.md).
#include "app/generate/scenario_generator.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "scenes/scenario/scenario_category.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {
namespace {

namespace fs = std::filesystem;
using scenario::Scenario;

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("handover_generate_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

TEST(Generate, SameSeedSameFilesAndIndependentOfCount) {
  for (int i : {0, 7, 31}) {
    const GeneratedScenario a = generateScenario(5, i, GenerateMode::Both);
    const GeneratedScenario b = generateScenario(5, i, GenerateMode::Both);
    EXPECT_EQ(a.yaml, b.yaml);
    EXPECT_EQ(a.name, b.name);
  }
  EXPECT_NE(generateScenario(5, 3, GenerateMode::Both).yaml, generateScenario(6, 3, GenerateMode::Both).yaml);
  const fs::path d1 = tempDir("few"), d2 = tempDir("more");
  const auto few = generateScenarios({3, 11, d1.string(), GenerateMode::Both});
  const auto more = generateScenarios({6, 11, d2.string(), GenerateMode::Both});
  ASSERT_EQ(few.size(), 3u);
  ASSERT_EQ(more.size(), 6u);
  for (std::size_t i = 0; i < few.size(); ++i) {
    EXPECT_EQ(fs::path(few[i]).filename(), fs::path(more[i]).filename());
    EXPECT_EQ(fs::file_size(few[i]), fs::file_size(more[i]));
  }
  fs::remove_all(d1);
  fs::remove_all(d2);
}

TEST(Generate, ModeTakeAndGive) {
  for (int i = 0; i < 20; ++i) {
    const Scenario t = scenario::parseScenarioString(generateScenario(2, i, GenerateMode::Take).yaml, "t.yaml");
    EXPECT_EQ(t.mode, scenario::Mode::HumanToRobot);
    EXPECT_TRUE(t.human.holds_object.has_value());
    const Scenario g = scenario::parseScenarioString(generateScenario(2, i, GenerateMode::Give).yaml, "g.yaml");
    EXPECT_EQ(g.mode, scenario::Mode::RobotToHuman);
    EXPECT_TRUE(g.robot.holds_object);
  }
}

// every file written parses with the checks of `handover check`, keeps the
// promised ranges, and together they cover every factor's values
TEST(Generate, FilesAreValidInRangeAndCoverTheSpace) {
  const fs::path dir = tempDir("cover");
  const auto paths = generateScenarios({400, 1, dir.string(), GenerateMode::Both});
  ASSERT_EQ(paths.size(), 400u);
  std::map<std::string, std::set<std::string>> seen;
  std::set<std::string> names;
  for (const auto& p : paths) {
    const Scenario s = scenario::parseScenario(p);  // throws on an invalid file
    names.insert(s.name);
    const scenario::Category c = scenario::categoryOf(s);
    seen["direction"].insert(c.direction);
    seen["grasp"].insert(c.grasp);
    seen["shape"].insert(c.shape);
    seen["behaviour"].insert(c.behaviour);
    seen["placement"].insert(c.placement);
    seen["hand"].insert(c.hand);
    seen["height"].insert(c.height);
    // the name states the category, and it is the one the geometry implies
    EXPECT_NE(s.name.find("_" + c.direction + "_" + c.grasp + "_" + c.shape + "_" + c.behaviour), std::string::npos)
        << s.name << " classified as " << scenario::categoryLabel(c);
    EXPECT_GE(s.object.mass, 0.1);
    EXPECT_LE(s.object.mass, 1.0);
    EXPECT_GE(s.human.height, 1.5);
    EXPECT_LE(s.human.height, 2.0);
    // what the fingers close across fits the open gripper (8 cm)
    const double across = s.object.shape == scenario::Shape::Box ? s.object.size[1] : 2.0 * s.object.size[0];
    EXPECT_LE(across, 0.08) << s.name;
    EXPECT_GE(s.sensor.rate_hz, 30.0);
    EXPECT_LE(s.sensor.rate_hz, 120.0);
    EXPECT_LE(s.sensor.latency, 0.1);
    ASSERT_TRUE(s.expect.outcome.has_value());
    EXPECT_EQ(*s.expect.outcome, c.behaviour == "abort" ? "aborted" : "success");
  }
  EXPECT_EQ(names.size(), paths.size()) << "names must be unique";
  const std::map<std::string, std::set<std::string>> want = {
      {"direction", {"take", "give"}},
      {"grasp", {"top", "side", "angled", "around_axis"}},
      {"shape", {"cylinder", "box", "sphere"}},
      {"behaviour", {"plain", "moving", "retry", "abort", "late_release", "late_pull", "sensing"}},
      {"placement", {"front", "offset", "side"}},
      {"hand", {"right", "left"}},
      {"height", {"low", "mid", "high"}},
  };
  for (const auto& [factor, values] : want) {
    for (const auto& v : values) EXPECT_TRUE(seen[factor].count(v)) << factor << " never " << v;
  }
  fs::remove_all(dir);
}

// lowest point of the object at `pose` above the table top (z = 0), m
double lowestPoint(const Scenario& s, const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d up = pose.linear().transpose() * Eigen::Vector3d::UnitZ();  // world z in the object
  const auto& d = s.object.size;
  double extent = 0.0;
  if (s.object.shape == scenario::Shape::Sphere) extent = d[0];
  else if (s.object.shape == scenario::Shape::Box)
    extent = 0.5 * (std::abs(up.x()) * d[0] + std::abs(up.y()) * d[1] + std::abs(up.z()) * d[2]);
  else extent = 0.5 * d[1] * std::abs(up.z()) + d[0] * std::hypot(up.x(), up.y());
  return pose.translation().z() - extent;
}

// The object in a resting giver's hand stays clear of the table's height: the
// straight reach from a low rest swept it through the table's edge, and the
// run was judged a drop before the robot had moved (g1_00498).
TEST(Generate, TheObjectInTheRestingHandClearsTheTable) {
  int takes = 0;
  for (int i = 0; i < 300; ++i) {
    const Scenario t = scenario::parseScenarioString(generateScenario(1, i, GenerateMode::Take).yaml, "t.yaml");
    ASSERT_TRUE(t.human.holds_object.has_value());
    EXPECT_GE(lowestPoint(t, t.human.start * *t.human.holds_object), 0.03 - 1e-4) << t.name;
    ++takes;
  }
  EXPECT_EQ(takes, 300);
}

TEST(Generate, BadModeWord) { EXPECT_THROW(parseGenerateMode("sideways"), std::invalid_argument); }

}  // namespace
}  // namespace handover::app
