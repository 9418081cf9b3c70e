// The collision queries' gripper and fingertip capsules are the robot
// description's (config/robot.yaml gripper), read from the capsules' roles:
// the same capsules whatever the links are called.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "control/collision/collision_config.hpp"
#include "control/collision/collision_data.hpp"
#include "control/collision/collision_model.hpp"
#include "control/model/robot_description.hpp"
#include "runtime/collision_queries.hpp"

namespace handover::runtime {
namespace {

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(CollisionQueries, GripperAndFingertipsAreTheDescriptions) {
  const control::RobotDescription d = control::defaultRobotDescription();
  const control::Model model = control::loadModel(d, 0.08);
  const control::CollisionModel cm =
      control::buildCollisionModel(model, control::loadCollisionConfig(control::defaultCollisionConfigPath()));
  int gripper = 0, fingertips = 0, robot = 0;
  for (const control::CollisionBody& b : cm.bodies) {
    if (!b.isRobot()) {
      EXPECT_FALSE(isGripperCapsule(b)) << b.name;
      EXPECT_FALSE(isFingertipCapsule(b)) << b.name;
      continue;
    }
    ++robot;
    EXPECT_EQ(isGripperCapsule(b), listed(d.gripper_links, b.link)) << b.link << "/" << b.name;
    EXPECT_EQ(isFingertipCapsule(b), listed(d.fingertip_capsules, b.name)) << b.link << "/" << b.name;
    gripper += isGripperCapsule(b);
    fingertips += isFingertipCapsule(b);
  }
  EXPECT_GT(robot, gripper);
  EXPECT_GT(gripper, fingertips);
  EXPECT_GT(fingertips, 0);
}

TEST(CollisionQueries, AnotherGripperIsADescriptionChange) {
  control::RobotDescription d = control::defaultRobotDescription();
  const control::Model shipped = control::loadModel(d, 0.08);
  // call the hand's other capsule the fingertip instead
  std::string other;
  for (const control::Capsule& c : shipped.capsules)
    if (c.role == control::CapsuleRole::kGripper) other = c.name;
  ASSERT_FALSE(other.empty());
  d.fingertip_capsules = {other};
  const control::Model model = control::loadModel(d, 0.08);
  const control::CollisionModel cm =
      control::buildCollisionModel(model, control::loadCollisionConfig(control::defaultCollisionConfigPath()));
  int fingertips = 0;
  for (const control::CollisionBody& b : cm.bodies) {
    if (!isFingertipCapsule(b)) continue;
    EXPECT_EQ(b.name, other);
    ++fingertips;
  }
  EXPECT_EQ(fingertips, 1);
}

// The "arm" distance (everything but the hand) leaves the gripper out against
// the person's forearm (the handover itself happens there) but not against
// the trunk: a gripper at the chest is no handover.
/// The shipped robot's collision model with only these pair rules (YAML list items).
control::CollisionModel modelWithPairs(const std::string& pairs) {
  const control::Model model = control::loadModel(control::defaultRobotDescription(), 0.08);
  return control::buildCollisionModel(model, control::parseCollisionConfig("pairs:\n" + pairs, "queries.yaml"));
}

/// Every pair active, at the distance `of(rule name, pair index)`.
template <class F>
void setDistances(const control::CollisionModel& cm, control::CollisionData& cd, F of) {
  for (int k = 0; k < cm.numPairs(); ++k) {
    cd.results[k].active = true;
    cd.results[k].distance = of(cm.rule_names[cm.pairs[k].rule], k);
  }
}

TEST(CollisionQueries, GripperCountsAgainstTheTrunkButNotTheForearm) {
  const control::CollisionModel cm = modelWithPairs(
      "  - {name: fore, robot: panda_hand, other: human_forearm, margin: 0.0}\n"
      "  - {name: trunk, robot: panda_hand, other: human_torso, margin: 0.0}\n");
  control::CollisionData cd(cm);
  setDistances(cm, cd, [](const std::string& rule, int k) { return rule == "fore" ? 0.01 : 0.05 + 0.001 * k; });
  double trunk = 1e9;
  for (int k = 0; k < cm.numPairs(); ++k)
    if (cm.rule_names[cm.pairs[k].rule] == "trunk") trunk = std::min(trunk, cd.results[k].distance);
  EXPECT_DOUBLE_EQ(personDistance(cm, cd, -1, false, PersonPart::kArm), trunk);
  EXPECT_DOUBLE_EQ(personDistance(cm, cd, -1, false, PersonPart::kAll), 0.01);
}

// The flange the gripper is mounted on is one rigid body with the hand: it
// stands 10-15 cm from the forearm of a hand that holds the object out, and
// counting it slowed every grasp's last centimetres to the overlay's speed.
// The links before it still count against the forearm.
TEST(CollisionQueries, TheFlangeThatCarriesTheGripperIsTheHandoverButTheElbowIsNot) {
  const control::CollisionModel cm = modelWithPairs(
      "  - {name: flange, robot: panda_link7*, other: human_forearm, margin: 0.0}\n"
      "  - {name: elbow, robot: panda_link4, other: human_forearm, margin: 0.0}\n");
  control::CollisionData cd(cm);
  int flange_pairs = 0;
  setDistances(cm, cd, [&](const std::string& rule, int) {
    flange_pairs += rule == "flange";
    return rule == "flange" ? 0.10 : 0.30;
  });
  ASSERT_GT(flange_pairs, 0);
  EXPECT_DOUBLE_EQ(personDistance(cm, cd, -1, false, PersonPart::kArm), 0.30);
  EXPECT_DOUBLE_EQ(personDistance(cm, cd, -1, false, PersonPart::kAll), 0.10);
  // the elbow near the forearm is an intruder like any other
  setDistances(cm, cd, [](const std::string& rule, int) { return rule == "elbow" ? 0.05 : 0.10; });
  EXPECT_DOUBLE_EQ(personDistance(cm, cd, -1, false, PersonPart::kArm), 0.05);
}

}  // namespace
}  // namespace handover::runtime
