// loadModel(): what it reads from scenes/panda.urdf and how it reports bad files.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>

#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "mujoco_oracle.hpp"
#include "tests/support/temp_path.hpp"

namespace handover::control {
namespace {

using test::sourcePath;

std::string readPanda() {
  std::ifstream in(sourcePath("scenes/panda.urdf"));
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Runs loadModel on `path`; expects InputError whose message holds the path and `detail`.
void expectInputError(const std::string& path, const std::string& detail) {
  try {
    loadModel(path);
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(detail), std::string::npos) << msg;
  }
}

// panda.urdf text with the element that starts at `start` (and ends at the next `end`) removed
std::string without(std::string text, const std::string& start, const std::string& end) {
  const std::size_t a = text.find(start);
  EXPECT_NE(a, std::string::npos) << start;
  const std::size_t b = text.find(end, a);
  return text.erase(a, b + end.size() - a);
}

TEST(ModelLoader, ReadsChainLimitsAndFrames) {
  const Model model = loadModel(sourcePath("scenes/panda.urdf"));
  for (int i = 0; i < kArmDofs; ++i) {
    EXPECT_EQ(model.joint_names[i], "panda_joint" + std::to_string(i + 1));
    EXPECT_EQ(model.body_names[i + 1], "panda_link" + std::to_string(i + 1));
    EXPECT_LT(model.q_min[i], model.q_max[i]);
  }
  EXPECT_EQ(model.body_names[0], "panda_link0");
  EXPECT_DOUBLE_EQ(model.q_min[3], -3.0718);
  EXPECT_DOUBLE_EQ(model.v_max[4], 2.61);
  EXPECT_DOUBLE_EQ(model.tau_max[0], 87.0);
  EXPECT_DOUBLE_EQ(model.a_max[1], 7.5);
  EXPECT_DOUBLE_EQ(model.finger_max_opening, 0.08);
  for (const char* f : {"hand", "tcp", "ft_sensor", "panda_hand", "panda_tcp", "panda_ft_sensor",
                        "panda_leftfinger", "panda_rightfinger", "panda_link0", "panda_link7"}) {
    EXPECT_TRUE(model.hasFrame(f)) << f;
  }
  EXPECT_FALSE(model.hasFrame("nonexistent"));
  EXPECT_THROW(model.frameId("nonexistent"), std::out_of_range);
  // aliases are the same frames as the links they name
  const Frame& tcp = model.frames[model.frameId("tcp")];
  const Frame& ptcp = model.frames[model.frameId("panda_tcp")];
  EXPECT_EQ(tcp.body, kArmDofs);
  EXPECT_TRUE(tcp.placement.isApprox(ptcp.placement));
  // the hand's mass and the fingers' are merged into body 7
  EXPECT_NEAR(model.inertias[kArmDofs].mass, 0.735522 + 0.73 + 2 * 0.015, 1e-12);
  // the published capsules, two of them for links 5, 7 and the hand
  EXPECT_EQ(model.capsules.size(), 12u);
}

TEST(ModelLoader, FingerOpeningMovesTheFingerFrames) {
  const Model open = loadModel(sourcePath("scenes/panda.urdf"), 0.08);
  const Model closed = loadModel(sourcePath("scenes/panda.urdf"), 0.0);
  const auto left = [](const Model& m) { return m.frames[m.frameId("panda_leftfinger")].placement.translation(); };
  const auto right = [](const Model& m) { return m.frames[m.frameId("panda_rightfinger")].placement.translation(); };
  EXPECT_NEAR((left(open) - right(open)).norm(), 0.08, 1e-12);
  EXPECT_NEAR((left(closed) - right(closed)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(open.inertias[kArmDofs].mass, closed.inertias[kArmDofs].mass, 1e-12);
  EXPECT_GT((open.inertias[kArmDofs].inertia_com - closed.inertias[kArmDofs].inertia_com).norm(), 1e-7);
}

TEST(ModelLoader, MissingFileNamesTheFile) {
  expectInputError(handover::test::uniqueTempPath("no_such_robot.urdf"), "cannot open");
}

TEST(ModelLoader, BrokenXmlNamesTheFileAndLine) {
  expectInputError(handover::test::writeTempFile("broken.urdf", "<robot name=\"x\">\n  <link name=\"a\">\n</robot>\n"), "XML error");
}

TEST(ModelLoader, JointWithoutLimitIsRejected) {
  std::string text = without(readPanda(), "<limit lower=\"-2.8973\" upper=\"2.8973\" velocity=\"2.1750\" effort=\"87\"/>", "/>");
  expectInputError(handover::test::writeTempFile("no_limit.urdf", text), "panda_joint1");
}

TEST(ModelLoader, LimitWithoutEffortIsRejected) {
  std::string text = readPanda();
  const std::size_t j = text.find("<joint name=\"panda_joint6\"");
  const std::size_t e = text.find("effort=\"12\"", j);
  text.erase(e, std::string("effort=\"12\"").size());
  expectInputError(handover::test::writeTempFile("no_effort.urdf", text), "effort");
}

TEST(ModelLoader, CutChainNamesWhereItIsCut) {
  std::string text = readPanda();
  const std::size_t j = text.find("<joint name=\"panda_joint4\" type=\"revolute\">");
  ASSERT_NE(j, std::string::npos);
  text.replace(j, std::string("<joint name=\"panda_joint4\" type=\"revolute\">").size(),
               "<joint name=\"panda_joint4\" type=\"fixed\">");
  expectInputError(handover::test::writeTempFile("cut_fixed.urdf", text), "panda_link3");
}

TEST(ModelLoader, RemovedJointIsReported) {
  // without joint 4 urdfdom sees two roots; the message still names the file
  const std::string text = without(readPanda(), "<joint name=\"panda_joint4\"", "</joint>");
  expectInputError(handover::test::writeTempFile("cut_removed.urdf", text), "urdf");
}

TEST(ModelLoader, NonCapsuleCollisionIsRejected) {
  std::string text = readPanda();
  const std::size_t c = text.find("<cylinder radius=\"0.06\" length=\"0.15\"/>");
  ASSERT_NE(c, std::string::npos);
  text.replace(c, std::string("<cylinder radius=\"0.06\" length=\"0.15\"/>").size(), "<box size=\"0.1 0.1 0.1\"/>");
  expectInputError(handover::test::writeTempFile("box_collision.urdf", text), "panda_link3");
}

TEST(ModelLoader, MissingTcpLinkIsRejected) {
  std::string text = without(readPanda(), "<joint name=\"panda_tcp_joint\"", "</joint>");
  text = without(text, "<link name=\"panda_tcp\"/>", "/>");
  expectInputError(handover::test::writeTempFile("no_tcp.urdf", text), "panda_tcp");
}

}  // namespace
}  // namespace handover::control
