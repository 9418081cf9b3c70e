// Loading: the default scene has the contract names and a 1 ms step; missing
// or broken MJCF files are InputErrors that name the file.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "config/input_error.hpp"
#include "control/model/robot_description.hpp"
#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"
#include "tests/support/temp_path.hpp"

namespace handover::sim {
namespace {

std::string loadError(const std::string& path) {
  SimOptions o;
  o.scene_path = path;
  Simulation sim;
  try {
    sim.load(o);
  } catch (const InputError& e) {
    EXPECT_FALSE(sim.loaded());
    return e.what();
  }
  return "";
}

// A folder of this test's own for scene copies, with panda.xml beside them
// (the scene includes it by a relative path); ends with '/'.
std::string sceneCopyFolder() {
  const std::string folder = handover::test::uniqueTempPath("scene/");
  std::filesystem::create_directories(folder);
  const std::string dir = defaultScenePath().substr(0, defaultScenePath().rfind('/'));
  std::ifstream p(dir + "/panda.xml");
  std::ofstream out(folder + "panda.xml");
  out << p.rdbuf();
  return folder;
}

TEST(SimulationLoad, DefaultSceneHasContractNamesAndOneMillisecondStep) {
  Simulation sim;
  sim.load();
  ASSERT_TRUE(sim.loaded());
  EXPECT_DOUBLE_EQ(sim.timestep(), 0.001);
  const mjModel* m = sim.mujocoModel();
  const control::RobotDescription robot = control::defaultRobotDescription();
  for (const std::string& body : {robot.base_link, robot.hand_link, robot.finger_links[0], robot.finger_links[1],
                                  std::string("human_hand"), std::string("human_forearm"),
                                  std::string("human_upper_arm"), std::string("human_torso"), std::string("object")}) {
    EXPECT_GE(mj_name2id(m, mjOBJ_BODY, body.c_str()), 0) << body;
  }
  EXPECT_GE(mj_name2id(m, mjOBJ_CAMERA, "overview"), 0);
  EXPECT_GE(mj_name2id(m, mjOBJ_EQUALITY, "object_weld"), 0);
  EXPECT_FALSE(sim.objectWelded());
  // load() leaves the arm in the ready posture at rest
  const ArmState s = sim.armState();
  EXPECT_LT((s.q - test::readyPosture()).norm(), 1e-12);
  EXPECT_NEAR(s.finger_width, 0.08, 1e-12);
  EXPECT_EQ(sim.time(), 0.0);
}

TEST(SimulationLoad, MissingFileIsAnInputErrorNamingIt) {
  const std::string msg = loadError("/nonexistent/dir/scene.xml");
  EXPECT_NE(msg.find("/nonexistent/dir/scene.xml"), std::string::npos) << msg;
}

TEST(SimulationLoad, BrokenFileIsAnInputErrorNamingItWithMujocosText) {
  const std::string path = sceneCopyFolder() + "handover_broken_scene.xml";
  {
    std::ofstream out(path);
    out << "<mujoco><worldbody><body name=\"object\"><geom name=\"object_geom\" size=\"0.1\"/>\n<oops</worldbody>";
  }
  std::string msg = loadError(path);
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("XML"), std::string::npos) << "MuJoCo's own error text: " << msg;

  // the real scene with one bad attribute value: every named element is there
  std::ifstream in(defaultScenePath());
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string good = "timestep=\"0.001\"";
  ASSERT_NE(xml.find(good), std::string::npos);
  xml.replace(xml.find(good), good.size(), "timestep=\"fast\"");
  {
    std::ofstream out(path);
    out << xml;
  }
  msg = loadError(path);
  std::remove(path.c_str());
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("MuJoCo"), std::string::npos) << msg;
  EXPECT_NE(msg.find("XML"), std::string::npos) << "MuJoCo's own error text: " << msg;
}

TEST(SimulationLoad, ValidXmlWithoutTheContractNamesIsAnInputError) {
  // a copy of the real scene whose weld grips with the torso instead of the hand
  std::ifstream in(defaultScenePath());
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string weld = "body1=\"human_hand\"";
  xml.replace(xml.find(weld), weld.size(), "body1=\"human_torso\"");
  // the copy lives in a temp folder, with a copy of panda.xml beside it
  const std::string inc = "<include file=\"panda.xml\"/>";
  const std::string path = sceneCopyFolder() + "handover_scene_without_grip.xml";
  {
    std::ofstream out(path);
    out << xml;
  }
  ASSERT_NE(xml.find(inc), std::string::npos);
  const std::string msg = loadError(path);
  std::remove(path.c_str());
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("object_weld"), std::string::npos) << msg;
}

TEST(SimulationLoad, ResetRejectsNonFiniteInput) {
  Simulation sim;
  sim.load();
  test::Vector7 q = test::readyPosture();
  q[2] = std::nan("");
  EXPECT_THROW(sim.reset(q, 0.08), InputError);
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Another 7-DoF arm is a description change: the Panda's URDF, scene and
// robot description with every name changed load and run the same; the
// simulator names no robot joint or link itself (tests/docs/test_module_boundaries).
TEST(SimulationLoad, AnotherArmsNamesAreADescriptionChange) {
  const std::string folder = handover::test::uniqueTempPath("arm7/");
  std::filesystem::create_directories(folder);
  const control::RobotDescription panda = control::defaultRobotDescription();
  const std::string scenes = defaultScenePath().substr(0, defaultScenePath().rfind('/') + 1);
  writeText(folder + "arm7.urdf", replaceAll(readText(panda.urdf), "panda_", "arm7_"));
  writeText(folder + "panda.xml", replaceAll(readText(scenes + "panda.xml"), "panda_", "arm7_"));
  writeText(folder + "handover_scene.xml", readText(defaultScenePath()));
  std::string yaml = replaceAll(readText(panda.file), "panda_", "arm7_");
  yaml = replaceAll(yaml, "urdf: ../scenes/panda.urdf", "urdf: arm7.urdf");
  writeText(folder + "robot.yaml", yaml);
  ASSERT_NE(yaml.find("urdf: arm7.urdf"), std::string::npos);

  SimOptions renamed;
  renamed.scene_path = folder + "handover_scene.xml";
  renamed.robot_description = folder + "robot.yaml";
  Simulation arm7, reference;
  arm7.load(renamed);
  reference.load();
  EXPECT_GE(mj_name2id(arm7.mujocoModel(), mjOBJ_JOINT, "arm7_joint4"), 0);
  EXPECT_LT(mj_name2id(arm7.mujocoModel(), mjOBJ_JOINT, "panda_joint4"), 0);
  // the same world: the same steps under the same commands, the same hand mass
  EXPECT_EQ(arm7.handMass(), reference.handMass());
  for (int k = 0; k < 200; ++k) {
    test::holdStep(arm7, test::readyPosture(), 0.02);
    test::holdStep(reference, test::readyPosture(), 0.02);
  }
  EXPECT_EQ(arm7.armState().q, reference.armState().q);
  EXPECT_EQ(arm7.armState().finger_width, reference.armState().finger_width);
  EXPECT_TRUE(arm7.tcpPose().isApprox(reference.tcpPose(), 1e-12));

  // the Panda's description does not fit the renamed scene: the message names the joint and the description
  SimOptions mismatched;
  mismatched.scene_path = renamed.scene_path;
  Simulation sim;
  try {
    sim.load(mismatched);
    FAIL() << "the Panda's names loaded a scene without them";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("panda_joint1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("robot.yaml"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace handover::sim
