// How good a joint configuration is for reaching a grasp: each term is
// normalised to about [0, 1] by a reference value, then weighted.
//
//   total = w_margin * margin - w_motion * motion + w_manip * manipulability
//           - w_clearance * clearance_penalty - w_shortfall * shortfall
//   margin            = min_i min(1, d_i / margin_ref), d_i = distance of joint i to its nearest limit (rad)
//   manipulability    = min(1, sqrt(det(J J')) / manipulability_ref), J = 6x7 TCP Jacobian [m; rad]
//   motion            = |q - q_now| / motion_ref (2-norm, rad)
//   clearance_penalty = max(0, 1 - clearance / clearance_ref), clearance (m) to the given obstacles
//   shortfall         = min(1, (keepShortfall / shortfall_ref)^2): how far (m) the collision constraints hold
//                       the arm short of q (the keeps of the obstacles the fingers do not work in)
//   exit (give only, GraspSelector::setPullDirection) = exitBlock: how much of the receiver's pull the
//                       open gripper blocks; subtracted with weight w_exit outside totalScore
//
// Saturating the margin says "0.5 rad from every limit is enough": beyond it,
// motion and manipulability decide. Real-time safe.
#pragma once

#include "control/grasp/clearance.hpp"

namespace handover::control::grasp {

struct ScoreWeights {
  double joint_margin = 2.0;
  double margin_ref = 0.5;           ///< rad, joint distance to a limit that counts as fully safe
  double manipulability = 0.5;
  double manipulability_ref = 0.08;  ///< sqrt(det(J J')) that counts as well-conditioned
  double motion = 0.5;
  double motion_ref = 2.0;           ///< rad, joint-space distance that costs one unit
  double clearance = 1.0;
  double clearance_ref = 0.15;       ///< m, obstacle distance below which the penalty starts
  double shortfall = 2.0;
  double shortfall_ref = 0.02;       ///< m held short that costs the whole weight
  double exit = 1.0;                 ///< weight of the blocked pull (give presentations)
};

struct ScoreTerms {
  double joint_margin = 0.0;     ///< [0, 1]
  double manipulability = 0.0;   ///< [0, 1]
  double motion = 0.0;           ///< >= 0
  double clearance = 0.0;        ///< penalty in [0, 1] (1 = touching or overlapping)
  double shortfall = 0.0;        ///< penalty in [0, 1] (1 = held shortfall_ref or more short)
  double preference = 0.0;       ///< the candidate's spec's preference (GraspSpec), in the total
  double exit = 0.0;             ///< penalty in [0, 1] (1 = the pull drives the object into a finger or the palm)
  double total = 0.0;
};

/// Smallest distance of any joint to its nearest limit (rad; negative outside the limits).
double smallestLimitDistance(const Model& model, const Vector7& q);

/// sqrt(det(J J')) of a 6x7 Jacobian (0 at a singularity).
double manipulability(const Matrix6x7& J);

/// Terms of one configuration q (rad): margin and manipulability at q, motion
/// from q_now, clearance to the obstacles and the shortfall their keeps cause. `poses` must be chainPoses at q.
ScoreTerms scoreConfiguration(const Model& model, int frame_id, const ChainPoses& poses, const Vector7& q,
                              const Vector7& q_now, const ObstacleCapsule* obstacles, int num_obstacles,
                              const ScoreWeights& w);

/// [0, 1]: how much of a pull along `pull` (world, unit) the open gripper at
/// `grasp` (world; y = the fingers' closing axis, z = the approach axis)
/// blocks. An object between open fingers leaves freely across their faces
/// (grasp x) and out past the fingertips (+z); a pull along the closing axis
/// drives it into a finger pad, one along -z into the palm, and the person,
/// who does not yield, drags the arm with it. The larger of |y . pull| and
/// min(1, 2 max(0, -z . pull)): the palm counts in full from 30 degrees on
/// (sin 30 = 1/2), since a gripper whose palm faces the receiver also stands
/// between the object and their hand. 0 for a zero `pull`.
double exitBlock(const Isometry& grasp, const Vector3& pull);

/// Weighted sum of the terms (the formula above).
double totalScore(const ScoreTerms& t, const ScoreWeights& w);

}  // namespace handover::control::grasp
