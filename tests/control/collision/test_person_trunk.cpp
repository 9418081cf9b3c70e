// The person's trunk (torso, legs, head) as collision bodies, and the sensing
// budget in the margins of the pairs with the person.
#include <gtest/gtest.h>

#include <cmath>

#include "collision_test_util.hpp"
#include "config/input_error.hpp"
#include "control/collision/collision_data.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"
#include "control/model/algorithms.hpp"

using namespace handover;
using namespace handover::control;
using namespace handover::control::testing;

namespace {

const char* kTrunkRules =
    "pairs:\n"
    "  - {name: trunk, robot: panda_hand, other: [human_torso, human_legs, human_head], margin: 0.0}\n";

Vector7 ready() {
  Vector7 q;
  q << 0, -0.785, 0, -2.356, 0, 1.571, 0.785;
  return q;
}

// the smallest distance of the trunk pairs of `cm`, infinity when none is active
double trunkDistance(const CollisionModel& cm, const CollisionData& cd) {
  double d = INFINITY;
  for (int k = 0; k < cm.numPairs(); ++k)
    if (cd.results[k].active && cm.bodies[cm.pairs[k].other_body].kind == CollisionBodyKind::kHumanTrunk)
      d = std::min(d, cd.results[k].distance);
  return d;
}

}  // namespace

// The torso box's front face 5 cm from the hand capsules' nearest point: the
// trunk pairs measure it; with the trunk unknown they give no rows.
TEST(PersonTrunk, TorsoInFrontOfTheHandIsMeasuredAndSwitchedByValidity) {
  const Model& m = pandaModel();
  Data data(m);
  computeAll(m, data, ready(), Vector7::Zero());
  CollisionConfig cfg = parseCollisionConfig(kTrunkRules, "trunk.yaml");
  const CollisionModel cm = buildCollisionModel(m, cfg);
  CollisionData cd(cm);
  ASSERT_GE(cm.human_torso, 0);
  ASSERT_GE(cm.human_head, 0);
  ASSERT_GE(cm.human_legs, 0);

  // the hand capsules' farthest reach along +x, from a far-away torso's measurement
  CollisionEnvironment env;
  env.person_valid = env.trunk_valid = true;
  env.torso = Isometry::Identity();
  env.torso.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix();
  const Vector3 tcp = data.oMb[7].translation();
  // torso centre at the hand's height: the box's front face (depth 0.22) x0 - 0.11
  const PersonTrunk& t = cfg.person.trunk;
  env.torso.translation() = Vector3(tcp.x() + 0.30, tcp.y(), tcp.z() - t.torso_centre);
  updateCollisions(cm, cd, m, data, env);
  const double d1 = trunkDistance(cm, cd);
  ASSERT_TRUE(std::isfinite(d1));
  env.torso.translation().x() -= 0.02;  // 2 cm closer: 2 cm less, the face is flat
  updateCollisions(cm, cd, m, data, env);
  EXPECT_NEAR(trunkDistance(cm, cd), d1 - 0.02, 1e-6);

  env.trunk_valid = false;
  updateCollisions(cm, cd, m, data, env);
  EXPECT_FALSE(std::isfinite(trunkDistance(cm, cd)));
  env.trunk_valid = true;
  env.person_valid = false;  // no person, no trunk either
  updateCollisions(cm, cd, m, data, env);
  EXPECT_FALSE(std::isfinite(trunkDistance(cm, cd)));
}

TEST(PersonTrunk, HeadIsASphereOfItsRadius) {
  const Model& m = pandaModel();
  Data data(m);
  computeAll(m, data, ready(), Vector7::Zero());
  const CollisionConfig cfg = parseCollisionConfig(
      "pairs:\n  - {name: head, robot: panda_link0, other: human_head, margin: 0.0, iDist: 0.5}\n", "head.yaml");
  const CollisionModel cm = buildCollisionModel(m, cfg);
  CollisionData cd(cm);
  ASSERT_EQ(cm.numPairs(), 1);
  const CollisionBody& link0 = cm.bodies[cm.pairs[0].robot_body];
  // the head centre straight above link 0's capsule core end, 0.3 m up
  CollisionEnvironment env;
  env.person_valid = env.trunk_valid = true;
  const Vector3 top = link0.local * Vector3(0, 0, 0.5 * link0.shape.length);
  const double r = cfg.person.trunk.head_radius;
  env.torso.translation() = top + Vector3(0, 0, 0.3) - Vector3(0, 0, cfg.person.trunk.head_centre);
  updateCollisions(cm, cd, m, data, env);
  ASSERT_TRUE(cd.results[0].active);
  EXPECT_NEAR(cd.results[0].distance, 0.3 - r - link0.radius, 1e-6);
}

// The other arm (untracked, hanging beside the torso) is a capsule of the
// trunk: its fingertip end straight above link 0's capsule end measures the
// gap less both radii, and it follows the torso frame.
TEST(PersonTrunk, FreeArmIsACapsuleHangingInTheTorsoFrame) {
  const Model& m = pandaModel();
  Data data(m);
  computeAll(m, data, ready(), Vector7::Zero());
  const CollisionConfig cfg = parseCollisionConfig(
      "person: {free_arm_radius: 0.05}\n"
      "pairs:\n  - {name: free_arm, robot: panda_link0, other: human_free_arm, margin: 0.0, iDist: 0.5}\n",
      "free_arm.yaml");
  const CollisionModel cm = buildCollisionModel(m, cfg);
  CollisionData cd(cm);
  ASSERT_EQ(cm.numPairs(), 1);
  const CollisionBody& arm = cm.bodies[cm.pairs[0].other_body];
  EXPECT_EQ(arm.name, "human_free_arm");
  EXPECT_EQ(arm.kind, CollisionBodyKind::kHumanTrunk);
  EXPECT_TRUE(arm.isPerson());
  EXPECT_DOUBLE_EQ(arm.radius, 0.05);
  const PersonTrunk& t = cfg.person.trunk;
  // default: a right hand hands, the left (+y in the torso frame) hangs beside the torso box
  EXPECT_GT(t.free_arm_top.y(), 0.5 * t.torso_size.y());
  EXPECT_GT(t.free_arm_top.z(), t.free_arm_bottom.z());

  const CollisionBody& link0 = cm.bodies[cm.pairs[0].robot_body];
  const Vector3 top = link0.local * Vector3(0, 0, 0.5 * link0.shape.length);
  CollisionEnvironment env;
  env.person_valid = env.trunk_valid = true;
  env.torso.translation() = top + Vector3(0, 0, 0.3) - t.free_arm_bottom;
  updateCollisions(cm, cd, m, data, env);
  ASSERT_TRUE(cd.results[0].active);
  EXPECT_NEAR(cd.results[0].distance, 0.3 - 0.05 - link0.radius, 1e-6);
  // turned half a turn about the fingertip's vertical: the same gap
  env.torso.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix();
  env.torso.translation() = top + Vector3(0, 0, 0.3) - env.torso.linear() * t.free_arm_bottom;
  updateCollisions(cm, cd, m, data, env);
  EXPECT_NEAR(cd.results[0].distance, 0.3 - 0.05 - link0.radius, 1e-6);
  env.trunk_valid = false;  // known only with the trunk
  updateCollisions(cm, cd, m, data, env);
  EXPECT_FALSE(cd.results[0].active);
}

// The shipped rules keep every arm link and the gripper off the free arm with
// the person margin and the sensing budget.
TEST(PersonTrunk, ShippedRulesPairTheFreeArmWithTheWholeArm) {
  const CollisionConfig cfg = loadCollisionConfig(defaultCollisionConfigPath());
  const CollisionModel cm = buildCollisionModel(pandaModel(), cfg);
  int pairs = 0;
  bool hand = false;
  for (const CollisionPair& p : cm.pairs) {
    if (cm.bodies[p.other_body].name != "human_free_arm") continue;
    ++pairs;
    hand = hand || cm.bodies[p.robot_body].link == "panda_hand";
    EXPECT_NEAR(p.margin, cfg.person.margin + cfg.sensing_error.budget(), 1e-12) << cm.pairLabel(static_cast<int>(&p - cm.pairs.data()));
  }
  EXPECT_GE(pairs, 7);
  EXPECT_TRUE(hand);
}

TEST(PersonTrunk, FreeArmRadiusIsValidated) {
  const std::string pairs = "pairs: [{name: a, robot: panda_hand, other: human_free_arm}]\n";
  try {
    parseCollisionConfig("person: {free_arm_radius: 0}\n" + pairs, "bad.yaml");
    FAIL() << "a zero radius was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("person.free_arm_radius"), std::string::npos) << e.what();
  }
}

// Every pair with the person carries the declared sensing budget on top of
// its rule's margin, except `sharing` rules; pairs with the table do not.
TEST(SensingBudget, EntersThePersonPairsMargins) {
  const std::string rules =
      "person: {margin: 0.01}\n"
      "sensing_error: {calibration: 0.004, noise: 0.002, noise_sigmas: 2, latency: 0.1, person_speed: 0.2}\n"
      "pairs:\n"
      "  - {name: hand, robot: panda_hand, other: human_hand, margin: 0.0}\n"
      "  - {name: arm, robot: panda_link4, other: human_forearm}\n"
      "  - {name: shared, robot: panda_link3, other: human_upper_arm, margin: 0.0, when: sharing}\n"
      "  - {name: table, robot: panda_hand, other: table}\n";
  const CollisionConfig cfg = parseCollisionConfig(rules, "budget.yaml");
  EXPECT_NEAR(cfg.sensing_error.budget(), 0.004 + 2 * 0.002 + 0.1 * 0.2, 1e-12);
  const CollisionModel cm = buildCollisionModel(pandaModel(), cfg);
  for (const CollisionPair& p : cm.pairs) {
    const std::string& rule = cm.rule_names[p.rule];
    if (rule == "hand") {
      EXPECT_NEAR(p.margin, 0.028, 1e-12);
    }
    if (rule == "arm") {
      EXPECT_NEAR(p.margin, 0.038, 1e-12);
    }
    if (rule == "shared") {
      EXPECT_NEAR(p.margin, 0.0, 1e-12);
    }
    if (rule == "table") {
      EXPECT_NEAR(p.margin, 0.0, 1e-12);
    }
  }
}

TEST(SensingBudget, BadValuesNameTheKey) {
  auto errorOf = [](const std::string& text) {
    try {
      parseCollisionConfig(text, "bad.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string pairs = "pairs: [{name: a, robot: panda_hand, other: table}]\n";
  std::string e = errorOf("sensing_error: {calibration: -0.01}\n" + pairs);
  EXPECT_NE(e.find("sensing_error.calibration"), std::string::npos) << e;
  e = errorOf("sensing_error: {latnecy: 0.1}\n" + pairs);
  EXPECT_NE(e.find("latnecy"), std::string::npos) << e;
  e = errorOf("sensing_error: {latency: 1.0, person_speed: 0.5}\n" + pairs);
  EXPECT_NE(e.find("exceeds"), std::string::npos) << e;
}
