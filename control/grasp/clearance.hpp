// Clearance between the arm's collision capsules and obstacle capsules given
// by the caller (e.g. the person's forearm and hand from perception), and
// from the table top, for scoring and filtering configurations. Analytic segment-segment distance
// (and segment-box, for a box obstacle); no FCL here (this runs over every candidate, and no witness
// points are needed).
// Frames: world. Units: m. Real-time safe.
#pragma once

#include "control/grasp/chain_kinematics.hpp"

namespace handover::control::grasp {

/// A capsule in the world: the segment [a, b] swept by a sphere of `radius`.
struct ObstacleCapsule {
  Vector3 a = Vector3::Zero();  ///< m, world
  Vector3 b = Vector3::Zero();  ///< m, world
  double radius = 0.0;          ///< m
  /// Half edges (m) of a box centred at `a` with axes `box_axes` (world),
  /// swept by `radius`, instead of the segment (`b` unused); zero: a capsule.
  /// The person's hand as the collision constraints see it is a box.
  Vector3 box_half_extents = Vector3::Zero();
  Matrix3 box_axes = Matrix3::Identity();
  /// The fingers work here (the person's hand that holds the object): the
  /// fingertip capsules (CapsuleRole::kFingertip), which close around the
  /// object in it, are not measured against it; the palm and the arm are.
  /// Counted against the fingers too, it was the nearest obstacle of every
  /// grasp in the hand and hid how close each put the palm to the hand.
  bool gripper_works_here = false;
  /// m: how far the collision constraints keep the arm's capsules (keep_arm)
  /// and the gripper's, palm and fingers (keep_gripper), from this obstacle
  /// (their pair's margin, sensing budget and sDist): a configuration nearer
  /// than that is one the arm cannot reach (personBodyClearance).
  double keep_arm = 0.0;
  double keep_gripper = 0.0;
  /// m: the same while the fingers share the object with the person's hand
  /// (the take's grasp itself: Grasp's rules, no sensing budget between the
  /// gripper and the arm whose hand holds the object); personBodyClearance
  /// with `sharing`. Negative: as keep_arm / keep_gripper.
  double keep_arm_sharing = -1.0;
  double keep_gripper_sharing = -1.0;
  /// Only its keeps count (keepShortfall, as for every obstacle the fingers
  /// do not work in): it adds no clearance penalty and no rejection. A give's
  /// receiving hand (the object goes onto it: the gripper may come as near as
  /// its constraints let it) and the receiver's trunk.
  bool keep_only = false;
  /// The object the person holds out, that the fingers will close on: none
  /// of the above counts it (at the grasp the palm's fit to it decides,
  /// palm_fit.hpp); heldObjectClearance does, where the arm lines up before
  /// the fingers go around it. A pre-grasp inside the object itself (a 60 cm
  /// tube, the grasp below its upper end) held the gripper against the
  /// object for 10 s until the approach gave up.
  bool held_object = false;
};

/// Smallest distance between the segments [p0, p1] and [q0, q1] (m).
double segmentDistance(const Vector3& p0, const Vector3& p1, const Vector3& q0, const Vector3& q1);

/// Smallest distance between the segment [p0, p1] and the box centred at
/// `centre` with axes `axes` (world) and half edges `half` (m; 0 inside).
double segmentBoxDistance(const Vector3& p0, const Vector3& p1, const Vector3& centre, const Matrix3& axes,
                          const Vector3& half);

/// How far the collision constraints hold the configuration short of itself:
/// the largest amount (m) by which any capsule, the fingertips included,
/// comes nearer an obstacle than its keep (keep_arm, keep_gripper); 0 when
/// all keep clear. Obstacles where the gripper works are left out (their
/// fingers close in them: workZoneClearance).
double keepShortfall(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                     int num_obstacles);

/// Smallest surface distance between any of the model's capsules posed by
/// `poses` and any obstacle (m, negative when they overlap), the fingertip
/// capsules left out against an obstacle where the fingers work; +infinity
/// without obstacles.
double armClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles, int num_obstacles);

/// Smallest surface distance between the capsules that do not close on the
/// object (the arm and the palm: every role but CapsuleRole::kFingertip) and
/// the obstacles where the fingers work (ObstacleCapsule::gripper_works_here),
/// m; +infinity without such obstacles. Negative: the palm or the arm would
/// sit in the person's hand at that grasp.
double workZoneClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                         int num_obstacles);

/// Smallest surface distance between any of the model's capsules, the
/// fingertips included, and the held objects (ObstacleCapsule::held_object),
/// beyond what the collision constraints keep from them (keep_arm,
/// keep_gripper), m; +infinity without such obstacles. For a pre-grasp: the
/// whole gripper is still in front of the object there.
double heldObjectClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                           int num_obstacles);

/// Smallest surface distance between any of the model's capsules, the
/// fingertips included, and the person's body (the forearm, upper arm and
/// trunk; the hand where the fingers work only for the arm's capsules),
/// beyond what the collision constraints keep from each
/// (ObstacleCapsule::keep_arm, keep_gripper; with `sharing`, the keeps while
/// the fingers share the object with the person's hand), m; negative: the arm
/// would have to come nearer than its constraints let it; +infinity without
/// obstacles.
double personBodyClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                          int num_obstacles, bool sharing = false);

/// Lowest point (world z, m) of the capsules of bodies `first_body`.. (the
/// base and link 1 stand on the table and are left out with first_body = 2).
double lowestArmPoint(const Model& model, const ChainPoses& poses, int first_body = 2);

}  // namespace handover::control::grasp
