#include "runtime/collision_queries.hpp"

#include <algorithm>
#include <cmath>

namespace handover::runtime {

// The roles come from the robot description (config/robot.yaml, gripper).
bool isGripperCapsule(const control::CollisionBody& b) {
  return b.isRobot() && (b.role == control::CapsuleRole::kGripper || b.role == control::CapsuleRole::kFingertip);
}
bool isFingertipCapsule(const control::CollisionBody& b) {
  return b.isRobot() && b.role == control::CapsuleRole::kFingertip;
}

double personDistance(const control::CollisionModel& cm, const control::CollisionData& cd, int skip_rule,
                      bool skip_fingertips, PersonPart part) {
  double d = INFINITY;
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& pair = cm.pairs[i];
    const auto& res = cd.results[i];
    if (!res.active || pair.rule == skip_rule) continue;
    const control::CollisionBody& other = cm.bodies[pair.other_body];
    if (!other.isPerson()) continue;
    const bool is_hand = other.kind == control::CollisionBodyKind::kHumanHand;
    if ((part == PersonPart::kHand && !is_hand) || (part == PersonPart::kArm && is_hand)) continue;
    const control::CollisionBody& robot = cm.bodies[pair.robot_body];
    if (skip_fingertips && isFingertipCapsule(robot)) continue;
    // the gripper (and the flange it is on) near the person's forearm is the handover itself;
    // near the trunk it is not
    if (part == PersonPart::kArm && robot.body == cm.gripper_body && other.kind != control::CollisionBodyKind::kHumanTrunk)
      continue;
    d = std::min(d, res.distance + pair.margin);
  }
  return d;
}

bool personConstraintEngaged(const control::CollisionModel& cm, const control::CollisionData& cd) {
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& pair = cm.pairs[i];
    const auto& res = cd.results[i];
    if (res.active && cm.bodies[pair.other_body].isPerson() && res.distance < pair.damper.i_dist) return true;
  }
  return false;
}

void tableAndSelfDistance(const control::CollisionModel& cm, const control::CollisionData& cd, double& table,
                          double& self) {
  table = self = INFINITY;
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& res = cd.results[i];
    if (!res.active) continue;
    const auto& other = cm.bodies[cm.pairs[i].other_body];
    if (other.kind == control::CollisionBodyKind::kTable) table = std::min(table, res.distance);
    if (other.isRobot()) self = std::min(self, res.distance);
  }
}

}  // namespace handover::runtime
