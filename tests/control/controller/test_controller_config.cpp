// controller.yaml: the shipped file loads; bad files are InputErrors that
// name the file, the dotted key and the line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "control/controller_config.hpp"
#include "tests/support/temp_path.hpp"

using namespace handover;
using namespace handover::control;

namespace {

// Expects loading `text` to fail with a message naming file, key and line.
void expectError(const std::string& text, const std::string& key, int line) {
  const std::string path = handover::test::writeTempFile("ctl_bad.yaml", text);
  try {
    loadControllerConfig(path);
    FAIL() << "no error for:\n" << text;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(key), std::string::npos) << msg;
    EXPECT_NE(msg.find(":" + std::to_string(line) + ":"), std::string::npos) << msg;
  }
}

}  // namespace

TEST(ControllerConfig, ShippedFileLoadsWithPaperDefaults) {
  const ControllerConfig c = loadControllerConfig(defaultControllerConfigPath());
  EXPECT_DOUBLE_EQ(c.observation.gains.stiffness, 1500.0);
  EXPECT_NEAR(c.observation.gains.damping, 2.0 * std::sqrt(1500.0), 1e-12);
  EXPECT_DOUBLE_EQ(c.tracking.translation.gains.stiffness, 1.0);
  EXPECT_NEAR(c.tracking.translation.gains.damping, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.tracking.orientation.gains.stiffness, 2.0);
  EXPECT_NEAR(c.tracking.orientation.gains.damping, 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(c.posture.gains.stiffness, 10.0);
  // posture only resolves redundancy: far below the tracking task's weight
  EXPECT_LT(c.posture.weight, 1e-4 * c.tracking.weight);
  EXPECT_DOUBLE_EQ(c.limits.velocity_scale, 0.8);
  EXPECT_DOUBLE_EQ(c.limits.position.interaction, 0.10);
  EXPECT_DOUBLE_EQ(c.limits.position.safety, 0.01);
}

TEST(ControllerConfig, ValuesAndExplicitDampingAreRead) {
  const std::string path = handover::test::writeTempFile("ctl_ok.yaml",
                                     "tracking:\n"
                                     "  weight: 50\n"
                                     "  orientation:\n"
                                     "    stiffness: 9.0\n"
                                     "    damping: 1.5\n"
                                     "    weights: [1, 2, 0]\n"
                                     "  translation: {stiffness: 4.0}\n");
  const ControllerConfig c = loadControllerConfig(path);
  EXPECT_DOUBLE_EQ(c.tracking.weight, 50.0);
  EXPECT_DOUBLE_EQ(c.tracking.orientation.gains.damping, 1.5);
  EXPECT_EQ(c.tracking.orientation.weights, Vector3(1, 2, 0));
  EXPECT_NEAR(c.tracking.translation.gains.damping, 4.0, 1e-12);  // auto: 2 sqrt(4)
}

TEST(ControllerConfig, UnknownKeyNamesFileKeyAndLine) {
  expectError("observation:\n  stiffness: 1500\ntracking:\n  translation:\n    stifness: 2\n",
              "tracking.translation.stifness", 5);
}

TEST(ControllerConfig, OutOfRangeValueNamesFileKeyAndLine) {
  expectError("limits:\n  velocity:\n    scale: 3.0\n", "limits.velocity.scale", 3);
}

TEST(ControllerConfig, WrongTypeNamesFileKeyAndLine) {
  expectError("qp:\n  regularisation: lots\n", "qp.regularisation", 2);
}

TEST(ControllerConfig, WrongVectorLengthNamesFileKeyAndLine) {
  expectError("posture:\n  weight: 5\n  target: [0, 1, 2]\n", "posture.target", 3);
}

TEST(ControllerConfig, InconsistentMarginsAreRejected) {
  expectError("limits:\n  position:\n    interaction: 0.05\n    safety: 0.2\n", "limits.position", 3);
}

TEST(ControllerConfig, MissingFileIsAnInputError) {
  EXPECT_THROW(loadControllerConfig("/nonexistent/controller.yaml"), InputError);
}

TEST(ControllerConfig, DisturbanceSectionIsReadAndChecked) {
  const ControllerConfig c = loadControllerConfig(handover::test::writeTempFile(
      "ctl_dist.yaml", "disturbance:\n  compensation: off\n  filter_tau: 0.05\n  max_torque_fraction: 0.2\n"));
  EXPECT_EQ(c.disturbance.compensation, DisturbanceSettings::Compensation::kOff);
  EXPECT_DOUBLE_EQ(c.disturbance.filter_tau, 0.05);
  EXPECT_DOUBLE_EQ(c.disturbance.max_torque_fraction, 0.2);
  expectError("disturbance:\n  compensation: always\n", "disturbance.compensation", 2);
  expectError("disturbance:\n  max_torque_fraction: 2\n", "disturbance.max_torque_fraction", 2);
}

// tasks: / constraints: lists, read strictly; what a missing list means
TEST(ControllerConfig, TaskAndConstraintEntries) {
  const ControllerConfig shipped = loadControllerConfig(defaultControllerConfigPath());
  const ControllerConfig none = loadControllerConfig(handover::test::writeTempFile("ctl_empty.yaml", "period: 0.001\n"));
  ASSERT_EQ(shipped.tasks.size(), none.tasks.size());
  for (std::size_t i = 0; i < shipped.tasks.size(); ++i) {
    EXPECT_EQ(shipped.tasks[i].name, none.tasks[i].name);
    EXPECT_EQ(shipped.tasks[i].type, none.tasks[i].type);
    EXPECT_EQ(shipped.tasks[i].enabled, none.tasks[i].enabled);
  }
  ASSERT_EQ(shipped.constraints.size(), none.constraints.size());
  for (std::size_t i = 0; i < shipped.constraints.size(); ++i)
    EXPECT_EQ(shipped.constraints[i].type, none.constraints[i].type);
  expectError("tasks:\n  - {name: a, type: posture}\n  - {name: a, type: pose}\n", "name", 3);
  expectError("tasks:\n  - {name: a}\n", "type", 2);
  expectError("constraints: joint_position\n", "constraints", 1);
}

// a config holds its entries by pointer: assigning one config over another
// leaves the first one's document as it was (yaml-cpp's Node assignment
// would rebind the node it referred to)
TEST(ControllerConfig, AssignmentLeavesTheOtherDocumentAlone) {
  const YamlReader a = YamlReader::loadString("tasks:\n  - {name: observation, type: observation}\n"
                                              "  - {name: tracking, type: trajectory_tracking}\n", "a.yaml");
  const YamlReader b = YamlReader::loadString("tasks:\n  - {name: obs2, type: observation}\n"
                                              "  - {name: track2, type: trajectory_tracking}\n", "b.yaml");
  ControllerConfig ca = parseControllerConfig(a);
  const ControllerConfig cb = parseControllerConfig(b);
  ca = cb;
  EXPECT_EQ(ca.tasks[0].name, "obs2");
  const ControllerConfig again = parseControllerConfig(YamlReader(a.node(), "a.yaml", ""));
  EXPECT_EQ(again.tasks[0].name, "observation");
  EXPECT_EQ(again.tasks[1].name, "tracking");
}
