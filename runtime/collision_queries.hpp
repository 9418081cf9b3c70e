// Distances read from a collision model's results: robot to the person (all
// of it, the hand, the arm), robot to the table and robot to itself. Used
// for the state machine's inputs (from the controller's own collision
// constraint, perceived person) and by the judge (ground-truth person).
// Which robot capsules form the gripper comes from their role in the robot
// description (config/robot.yaml gripper; CollisionBody::role).
// m; real-time safe (reads only).
#pragma once

#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"

namespace handover::runtime {

/// Which of the person's bodies a distance covers.
enum class PersonPart { kAll, kHand, kArm };

/// The robot's gripper capsules (the description's gripper links), and among
/// them the fingertip capsules (gripper.fingertip_capsules: between the
/// fingers, where a held object sits).
bool isGripperCapsule(const control::CollisionBody& body);
bool isFingertipCapsule(const control::CollisionBody& body);

/// Smallest robot-person distance over the active pairs of `cd` (margins
/// added back: the true clearance), skipping pairs of rule `skip_rule` (-1:
/// none) and, when `skip_fingertips`, the fingertips (they hold the shared
/// object). The arm part (everything but the hand: forearm, upper arm and the
/// trunk) leaves out the gripper, and the robot body that carries it (the
/// wrist flange: one rigid body with the hand), against the forearm and upper
/// arm: near the person's wrist it is the handover itself (the flange stands
/// 10-15 cm from the forearm of a hand that holds the object out), and its
/// clearance is the collision constraint's job; against the trunk they count.
/// Infinity when no pair counts.
double personDistance(const control::CollisionModel& cm, const control::CollisionData& cd, int skip_rule,
                      bool skip_fingertips, PersonPart part = PersonPart::kAll);

/// A collision row with the person is engaged: an active pair with a person
/// body inside its interaction distance (distance beyond its margin < iDist),
/// so the velocity damper, not a task, decides how near the arm goes.
bool personConstraintEngaged(const control::CollisionModel& cm, const control::CollisionData& cd);

/// Smallest distance of the active pairs whose other body is the table
/// (`table`) or a robot body (`self`); infinity when none.
void tableAndSelfDistance(const control::CollisionModel& cm, const control::CollisionData& cd, double& table,
                          double& self);

}  // namespace handover::runtime
