// config/fsm.yaml loads; broken copies of it are rejected with file, key, line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

std::string shipped() {
  std::ifstream in(HandoverFsm::defaultConfigPath());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

int lineOf(const std::string& text, const std::string& what) {
  const auto pos = text.find(what);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

std::string loadError(const std::string& text) {
  RecordingController ctl;
  try {
    HandoverFsm fsm(YamlReader::loadString(text, "fsm.yaml"), ctl, ObjectInfo{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// The shipped file with `from` replaced by `to` is refused with a message naming `what`.
void expectRefused(const std::string& from, const std::string& to, const std::string& what) {
  const std::string msg = loadError(replaced(shipped(), from, to));
  EXPECT_NE(msg.find(what), std::string::npos) << from << " -> " << to << ": " << msg;
}

TEST(HandoverConfig, ShippedConfigLoads) {
  EXPECT_EQ(loadError(shipped()), "");
  RecordingController ctl;
  HandoverFsm fsm(YamlReader::loadFile(HandoverFsm::defaultConfigPath()), ctl, ObjectInfo{});
  EXPECT_EQ(fsm.machine().interruptCount(), 3);  // object_lost, slow_down, safety_stop
}

TEST(HandoverConfig, TypoInStateKey) {
  // a misspelt required key: reported as missing, at the state's line
  std::string bad = replaced(shipped(), "release_share: 0.9", "release_shrae: 0.9");
  std::string msg = loadError(bad);
  EXPECT_NE(msg.find("fsm.yaml:" + std::to_string(lineOf(bad, "release_shrae"))), std::string::npos) << msg;
  EXPECT_NE(msg.find("needs release_share"), std::string::npos) << msg;
  bad = replaced(shipped(), "release_wait: 3.5, hold_time: 0.05", "release_wait: 3.5, hold_tiem: 0.05");
  msg = loadError(bad);
  EXPECT_NE(msg.find("fsm.yaml:" + std::to_string(lineOf(bad, "hold_tiem"))), std::string::npos) << msg;
  EXPECT_NE(msg.find("WaitForRelease': missing required key 'hold_time'"), std::string::npos) << msg;
  // both rules at once: one of them is a mistake
  bad = replaced(shipped(), "release_share: 0.9", "release_share: 0.9, release_fraction: 0.7");
  msg = loadError(bad);
  EXPECT_NE(msg.find("not both"), std::string::npos) << msg;
  // an extra key: reported as unknown, at its own line
  bad = replaced(shipped(), "release_share: 0.9", "release_share: 0.9, relase_delay: 1");
  msg = loadError(bad);
  EXPECT_NE(msg.find("fsm.yaml:" + std::to_string(lineOf(bad, "relase_delay"))), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'relase_delay'"), std::string::npos) << msg;
}

TEST(HandoverConfig, UnknownTargetState) {
  const std::string bad = replaced(shipped(), "[Grasp, Grasped, WaitForRelease]", "[Grasp, Grasped, WaitForRelaese]");
  const std::string msg = loadError(bad);
  EXPECT_NE(msg.find("fsm.yaml:" + std::to_string(lineOf(bad, "WaitForRelaese"))), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown state 'WaitForRelaese'"), std::string::npos) << msg;
}

TEST(HandoverConfig, UnknownOutput) {
  const std::string msg = loadError(replaced(shipped(), "[Grasp, Missed, RetreatOpen]", "[Grasp, Dropped, RetreatOpen]"));
  EXPECT_NE(msg.find("state 'Grasp' has no output 'Dropped' (outputs: Grasped, Missed, Withdrawn, Timeout)"),
            std::string::npos)
      << msg;
}

TEST(HandoverConfig, BadParameterValues) {
  expectRefused("gravity_sign: -1", "gravity_sign: 2", "params.ft.gravity_sign");
  const std::string msg = loadError(replaced(shipped(), "pull_threshold: 3.0", "pull_threshold: -3.0"));
  EXPECT_NE(msg.find("pull_threshold"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be > 0"), std::string::npos) << msg;
  expectRefused("pose: stow", "pose: home", "'home' is not one of: stow | safe | ready");
  expectRefused("close_width: 0.0", "close_width: 0.09", "params.gripper.close_width");
  expectRefused("home_radius: 0.025", "home_radius: 0.9", "params.withdraw.home_radius");
  expectRefused("away_time_constant: 0.1", "away_time_constant: 5.0", "params.withdraw.away_time_constant");
  // a first wait's Withdrawn is the body back home: without home_radius there is no home to be back at,
  // and without the flag the state has no such output to map
  expectRefused("home_radius: 0.05, home_rest_time: 0.3, withdrawn_at_home: true", "withdrawn_at_home: true",
                "WaitForReceiver.withdrawn_at_home': a person back home needs home_radius");
  expectRefused("home_rest_time: 0.3, withdrawn_at_home: true", "home_rest_time: 0.3",
                "state 'WaitForReceiver' has no output 'Withdrawn'");
}

TEST(HandoverConfig, TakeGainsAndTheGraspFunnel) {
  RecordingController ctl;
  HandoverFsm fsm(YamlReader::loadFile(HandoverFsm::defaultConfigPath()), ctl, ObjectInfo{});
  // the fingers line up stiffer than the arm follows (both read from the shipped file)
  EXPECT_GT(fsm.params().align_tracking_translation_stiffness, fsm.params().tracking_translation_stiffness);
  EXPECT_GT(fsm.params().finger_half_span, 0.0);
  expectRefused("align:", "aling:", "unknown key 'aling'");
  expectRefused("funnel_margin: 0.25", "funnel_margin: 1.5", "funnel_margin");
  expectRefused("finger_half_span: 0.012", "finger_half_span: -0.01", "params.gripper.finger_half_span");
  EXPECT_GT(fsm.params().finger_pad_reach, 0.0);
  EXPECT_GT(fsm.params().grip_depth, 0.0);
  expectRefused("pad_reach: 0.0095", "pad_reach: 0.2", "params.gripper.pad_reach");
  expectRefused("grip_depth: 0.006", "grip_depth: -0.006", "params.gripper.grip_depth");
  expectRefused("touch_force: 5.0", "touch_force: -5.0", "touch_force");
  expectRefused("max_touches: 2", "max_touches: 20", "max_touches");
  expectRefused("yield_after: 1.0", "yield_after: -1.0", "yield_after");
  // the funnel's motion budget: a horizon past a second, a negative significance, one without the other
  expectRefused("motion_horizon: 0.1", "motion_horizon: 5.0", "motion_horizon");
  expectRefused("motion_significance: 2.0", "motion_significance: -1.0", "motion_significance");
  expectRefused("motion_significance: 2.0", "funnel_depth: 2.0", "motion_significance");
}

TEST(HandoverConfig, MissingThresholdIsAnError) {
  const std::string msg =
      loadError(replaced(shipped(), "ApproachHand, near_distance: 0.08, lift", "ApproachHand, lift"));
  EXPECT_NE(msg.find("missing required key 'near_distance'"), std::string::npos) << msg;
}

TEST(HandoverConfig, BadObjectMass) {
  RecordingController ctl;
  ObjectInfo obj;
  obj.mass = 0.0;
  EXPECT_THROW(HandoverFsm(YamlReader::loadString(shipped(), "fsm.yaml"), ctl, obj), InputError);
}

}  // namespace
}  // namespace handover::fsm::test

namespace handover::fsm::test {
namespace {

TEST(GripForce, BudgetsTheWeightAndItsMomentAboutTheClosingAxis) {
  HandoverParams p;
  p.gravity = 9.81;
  p.grip_friction = 0.5;
  p.grip_torsional_friction = 0.01;
  p.grip_margin = 2.0;
  p.grip_acceleration = 3.0;
  p.grip_min_force = 10.0;
  p.grip_max_force = 70.0;
  const double load = 2.0 * 0.8 * (9.81 + 3.0);
  // centred between the fingers: friction alone
  EXPECT_NEAR(p.gripForce(0.8, Vector3::Zero()), load / (2.0 * 0.5), 1e-9);
  // along the closing axis (y) the weight has no lever about it
  EXPECT_NEAR(p.gripForce(0.8, Vector3(0.0, 0.03, 0.0)), load / (2.0 * 0.5), 1e-9);
  // 3 cm off the axis: the moment decides
  EXPECT_NEAR(p.gripForce(0.8, Vector3(0.03, 0.0, 0.0)), load * 0.03 / (2.0 * 0.01), 1e-9);
  EXPECT_GT(p.gripForce(0.8, Vector3(0.0, 0.0, 0.03)), p.gripForce(0.8, Vector3::Zero()));
  // clipped to what the gripper can give, and never below the minimum
  EXPECT_DOUBLE_EQ(p.gripForce(0.8, Vector3(0.1, 0.0, 0.0)), 70.0);
  EXPECT_DOUBLE_EQ(p.gripForce(0.05, Vector3::Zero()), 10.0);
}

}  // namespace
}  // namespace handover::fsm::test
