// The module boundaries docs/architecture.md claims, checked on the sources:
// control/, perception/ and fsm/ include nothing from scenes/, and no code
// outside the robot description (the URDF and config/robot.yaml; the MuJoCo
// scene XML is the simulator's own description) names a joint or link of the
// Panda ("panda_"), in code (scenes/ included) or in config/*.yaml.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace handover {
namespace {

namespace fs = std::filesystem;

// "file:line" of every line under `folder` (C++ sources and CMake files) that holds `needle`.
std::vector<std::string> linesWith(const std::string& folder, const std::string& needle) {
  std::vector<std::string> hits;
  const fs::path root = fs::path(HANDOVER_SOURCE_DIR) / folder;
  EXPECT_TRUE(fs::is_directory(root)) << root;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp" && ext != ".h" && entry.path().filename() != "CMakeLists.txt") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (line.find(needle) != std::string::npos) hits.push_back(entry.path().string() + ":" + std::to_string(n));
  }
  return hits;
}

std::string join(const std::vector<std::string>& v) {
  std::ostringstream out;
  for (const auto& s : v) out << "\n  " << s;
  return out.str();
}

TEST(ModuleBoundaries, ControlPerceptionAndFsmIncludeNothingFromScenes) {
  for (const char* folder : {"control", "perception", "fsm"}) {
    const auto hits = linesWith(folder, "scenes/");
    EXPECT_TRUE(hits.empty()) << folder << " names scenes/:" << join(hits);
  }
}

TEST(ModuleBoundaries, OnlyTheRobotDescriptionNamesPandaLinksAndJoints) {
  // scenes/ included: the simulator reads the arm's names from the robot
  // description (its MJCF files, the simulator's own description, are not code)
  for (const char* folder : {"control", "perception", "fsm", "runtime", "app", "interfaces", "scenes"}) {
    const auto hits = linesWith(folder, "panda_");
    EXPECT_TRUE(hits.empty()) << folder << " names the Panda's links or joints:" << join(hits);
  }
}

TEST(ModuleBoundaries, NoConfigFileButTheRobotDescriptionNamesPandaLinks) {
  const fs::path root = fs::path(HANDOVER_SOURCE_DIR) / "config";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.path().extension() != ".yaml" || entry.path().filename() == "robot.yaml") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      EXPECT_EQ(line.find("panda_"), std::string::npos) << entry.path().string() << ":" << n << ": " << line;
  }
  EXPECT_GE(files, 5);  // collision, controller, fsm, grasp_selection, perception
}

}  // namespace
}  // namespace handover
