// The robot description (config/robot.yaml): what it holds, that strict
// reading rejects bad files, and that another arm's names are a description
// change: the Panda URDF with every "panda_" renamed loads the same model
// once the description names the new links.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "config/input_error.hpp"
#include "control/model/model.hpp"
#include "control/model/robot_description.hpp"
#include "mujoco_oracle.hpp"
#include "tests/support/temp_path.hpp"

namespace handover::control {
namespace {

using test::sourcePath;

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The shipped description with `from` replaced by `to` (must occur).
std::string editedDescription(const std::string& from, const std::string& to) {
  const std::string text = readText(defaultRobotDescriptionPath());
  EXPECT_NE(text.find(from), std::string::npos) << from;
  return replaceAll(text, from, to);
}

void expectDescriptionError(const std::string& text, const std::string& detail) {
  const std::string path = handover::test::writeTempFile("bad_robot.yaml", text);
  try {
    loadRobotDescription(path);
    FAIL() << "no error for " << detail;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(detail), std::string::npos) << msg;
  }
}

TEST(RobotDescription, DefaultDescribesTheShippedUrdf) {
  const RobotDescription d = defaultRobotDescription();
  EXPECT_EQ(d.file, defaultRobotDescriptionPath());
  EXPECT_TRUE(std::ifstream(d.urdf).good()) << d.urdf;
  const Model model = loadModel(d, 0.08);
  EXPECT_EQ(model.body_names[0], d.base_link);
  EXPECT_EQ(model.frames[model.frameId("tcp")].placement.matrix(),
            model.frames[model.frameId(d.tcp_link)].placement.matrix());
  EXPECT_EQ(model.a_max, d.acceleration_limits);
}

TEST(RobotDescription, CapsuleRolesComeFromTheGripperSection) {
  const RobotDescription d = defaultRobotDescription();
  const Model model = loadModel(d, 0.08);
  int gripper = 0, fingertips = 0;
  for (const Capsule& c : model.capsules) {
    bool on_gripper_link = false;
    for (const std::string& l : d.gripper_links) on_gripper_link = on_gripper_link || c.link == l;
    bool fingertip = false;
    for (const std::string& n : d.fingertip_capsules) fingertip = fingertip || c.name == n;
    EXPECT_EQ(c.role != CapsuleRole::kArm, on_gripper_link) << c.name;
    EXPECT_EQ(c.role == CapsuleRole::kFingertip, fingertip) << c.name;
    gripper += c.role != CapsuleRole::kArm;
    fingertips += c.role == CapsuleRole::kFingertip;
  }
  EXPECT_GT(gripper, fingertips);
  EXPECT_GT(fingertips, 0);

  // no fingertip capsule named: the gripper keeps its capsules, none is a fingertip
  RobotDescription none = d;
  none.fingertip_capsules.clear();
  for (const Capsule& c : loadModel(none, 0.08).capsules) EXPECT_NE(c.role, CapsuleRole::kFingertip) << c.name;
}

TEST(RobotDescription, AnotherArmsNamesAreADescriptionChange) {
  const RobotDescription panda = defaultRobotDescription();
  const Model reference = loadModel(panda, 0.08);

  const std::string urdf = handover::test::writeTempFile("renamed_arm.urdf", replaceAll(readText(panda.urdf), "panda_", "arm7_"));
  RobotDescription other = panda;
  for (std::string* s : {&other.base_link, &other.hand_link, &other.tcp_link, &other.ft_sensor_link})
    *s = replaceAll(*s, "panda_", "arm7_");
  for (std::string& s : other.gripper_links) s = replaceAll(s, "panda_", "arm7_");
  for (std::string& s : other.finger_links) s = replaceAll(s, "panda_", "arm7_");
  for (LinkGroup& g : other.link_groups)
    for (std::string& p : g.patterns) p = replaceAll(p, "panda_", "arm7_");
  other.capsule_prefix = "arm7_";
  const Model model = loadModel(urdf, other, 0.08);

  EXPECT_EQ(model.body_names[0], "arm7_link0");
  ASSERT_EQ(model.capsules.size(), reference.capsules.size());
  for (std::size_t i = 0; i < model.capsules.size(); ++i) {
    EXPECT_EQ(model.capsules[i].name, reference.capsules[i].name);
    EXPECT_EQ(model.capsules[i].role, reference.capsules[i].role) << model.capsules[i].name;
  }
  for (const char* alias : {"hand", "tcp", "ft_sensor"}) {
    EXPECT_EQ(model.frames[model.frameId(alias)].placement.matrix(),
              reference.frames[reference.frameId(alias)].placement.matrix())
        << alias;
  }
  EXPECT_EQ(model.a_max, reference.a_max);
  EXPECT_EQ(model.q_max, reference.q_max);
  ASSERT_EQ(model.link_groups.size(), reference.link_groups.size());
  for (std::size_t i = 0; i < model.link_groups.size(); ++i) EXPECT_EQ(model.link_groups[i].name, reference.link_groups[i].name);
  EXPECT_EQ(model.inertias[kArmDofs].mass, reference.inertias[kArmDofs].mass);

  // the Panda's names do not fit the renamed URDF
  try {
    loadModel(urdf, panda, 0.08);
    FAIL() << "the Panda description loaded a URDF without its links";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("base_link"), std::string::npos) << e.what();
  }
}

TEST(RobotDescription, NamesThatAreNotInTheUrdfAreErrors) {
  RobotDescription d = defaultRobotDescription();
  d.tcp_link = "no_such_tcp";
  EXPECT_THROW(loadModel(d, 0.08), InputError);
  d = defaultRobotDescription();
  d.gripper_links.push_back("no_such_finger");
  EXPECT_THROW(loadModel(d, 0.08), InputError);
  d = defaultRobotDescription();
  d.fingertip_capsules = {"no_such_capsule"};
  EXPECT_THROW(loadModel(d, 0.08), InputError);
  d = defaultRobotDescription();
  d.link_groups.push_back(LinkGroup{"wrong", {"no_such_link"}});
  EXPECT_THROW(loadModel(d, 0.08), InputError);
}

TEST(RobotDescription, StrictReading) {
  expectDescriptionError(editedDescription("\ngripper:", "\nextra: 1\ngripper:"), "extra");
  expectDescriptionError(editedDescription("\ngripper:", "\ngrippers:"), "gripper");
  expectDescriptionError(editedDescription("\nlink_groups:", "\nlink_group:"), "link_group");
  expectDescriptionError(editedDescription("  elbow: [panda_link4]", "  elbow: []"), "elbow");
  expectDescriptionError(editedDescription("base_link:", "base:"), "base");
  expectDescriptionError(editedDescription("[15.0, 7.5,", "[15.0, -7.5,"), "acceleration_limits");
  expectDescriptionError(editedDescription("[15.0, 7.5,", "[7.5,"), "acceleration_limits");
  // the two fingers, left then right, each a gripper link
  expectDescriptionError(editedDescription("fingers: [panda_leftfinger, panda_rightfinger]", "fingers: [panda_leftfinger]"),
                         "fingers");
  expectDescriptionError(
      editedDescription("fingers: [panda_leftfinger, panda_rightfinger]", "fingers: [panda_leftfinger, panda_link7]"),
      "panda_link7");
  expectDescriptionError(editedDescription("  fingers: [panda_leftfinger, panda_rightfinger]", ""), "fingers");
}

TEST(RobotDescription, FingersAreLeftThenRight) {
  const RobotDescription d = defaultRobotDescription();
  EXPECT_EQ(d.finger_links[0], "panda_leftfinger");
  EXPECT_EQ(d.finger_links[1], "panda_rightfinger");
}

}  // namespace
}  // namespace handover::control
