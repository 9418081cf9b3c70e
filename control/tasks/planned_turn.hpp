// The way a large turn of the TCP goes when the joints are headed for a
// planned configuration (the grasp planner's IK solution).
//
// Why a topological answer: the joint limits make the joint space a box, so
// every motion from q to q_plan inside them turns the TCP along rotations of
// one homotopy class; lifted to unit quaternions, all those turns end at the
// same one of +-Q(q_plan). The short and the long way round to a target lie in
// different classes, so only one of them lets the arm arrive at the plan: the
// other ends on another IK branch or against a joint limit. A linearised guess
// (J_w (q_plan - q)) misjudges the way once several joints move far.
//
// Quaternions are unit, world axes, the Eigen convention; angles in rad.
// Everything here is real-time safe (no allocation).
#pragma once

#include "control/model/model.hpp"
#include "control/types.hpp"

namespace handover::control {

/// The orientation of frame `frame_id` at `q_plan`, as the unit quaternion
/// reached continuously from `now` (the frame's orientation at `q`, either
/// sign) along the straight joint path from q to q_plan. Steps of at most a
/// quarter turn of summed joint motion (the frame turns no more than the sum
/// of |dq_i|), so each step's sign is unambiguous: at most 22 orientation-only
/// forward kinematics over the Panda's whole range, 1 to 4 in a handover.
Quaternion planOrientationAlongJointPath(const Model& model, int frame_id, const Vector7& q, const Quaternion& now,
                                         const Vector7& q_plan);

/// The orientation error the PD acts on (rotation vector of R_now R_target^T,
/// world axes; the PD turns by -e), its norm in [0, 2 pi): the short way, or
/// the long way round when the plan's orientation `plan` (lifted from `now`,
/// planOrientationAlongJointPath) lies on the long way's side of the target.
/// The plan decides only where it says something about the target: within a
/// quarter turn of it (a stale plan or the gripper's half-turn twin does
/// not), and not within kDefinedAxis of the target, where the long way's
/// axis is undefined. Elsewhere `long_way` (the last choice) holds.
Vector3 plannedTurnError(const Quaternion& now, const Quaternion& target, const Quaternion& plan, bool& long_way);

/// rad: below this short-way angle a turn keeps the short way (a full turn
/// round has no defined axis).
inline constexpr double kDefinedAxis = 0.1;

/// planOrientationAlongJointPath once per plan instead of every control step.
/// While the joints move continuously the lift's class cannot change (joint
/// space is contractible), so the plan's lifted quaternion stays valid
/// against the frame's orientation followed continuously step to step (one
/// sign test). The path is lifted again when the plan changes, or when q
/// moved more than the lift's own step bound since the last call (a reset).
/// Real-time safe.
class PlannedTurnLift {
 public:
  /// `now`: the frame's orientation at q (either sign); turned to the sign
  /// continuous with the last call's, which the returned plan is lifted against.
  Quaternion plan(const Model& model, int frame_id, const Vector7& q, Quaternion& now, const Vector7& q_plan);
  /// The next plan() lifts the path again (no plan in force).
  void reset() { valid_ = false; }

 private:
  bool valid_ = false;
  Vector7 q_plan_ = Vector7::Zero();  ///< rad, the plan lifted for
  Vector7 q_ = Vector7::Zero();       ///< rad, q at the last call
  Quaternion now_ = Quaternion::Identity();   ///< the frame's orientation at the last call, continuous
  Quaternion plan_ = Quaternion::Identity();  ///< the plan's orientation lifted against now_
};

}  // namespace handover::control
