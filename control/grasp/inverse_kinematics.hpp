// Inverse kinematics of a full frame pose (position + orientation) on our own
// model: a Levenberg-Marquardt iteration with joint limits.
//
// Each iteration takes dq = (J' W J + lambda I)^-1 J' W e (computed in the
// equivalent 6x6 form J_w' (J_w J_w' + lambda I)^-1 e_w), with the error
// e = [p_target - p; log(R_target R')] in world axes, W weighting the rotation
// rows by `orientation_weight` (m/rad) so that both halves are comparable, and
// lambda = mu (E + damping) where E = e' W e / 2 (Sugihara's choice: large
// steps are damped far from the target, near-Gauss-Newton steps close to it).
// A step is kept only if it lowers E; a rejected one multiplies mu by 4 (an
// accepted one divides it by 3, down to 1), which keeps the iteration from
// oscillating near singular configurations. A secondary step, projected into
// the null space of J, pulls the joints toward the middle of their ranges
// (redundancy resolution away from the limits); the configuration is then
// clamped into the limits minus `limit_clearance`.
//
// Frames: the target is the world pose of model frame `frame_id` (e.g. "tcp").
// Units: m, rad. Real-time safe: fixed-size Eigen storage only, no heap
// allocation and no exceptions, so it may run inside a control or sensor
// cycle; the cost is bounded by max_iterations (about 1 us an iteration).
#pragma once

#include "control/model/model.hpp"

namespace handover::control::grasp {

struct IkOptions {
  int max_iterations = 80;               ///< linear solves, accepted or rejected
  double position_tolerance = 1e-4;      ///< m, converged when the position error is below
  double orientation_tolerance = 1e-3;   ///< rad, and the rotation error is below this
  double orientation_weight = 0.3;       ///< m/rad, weight of the rotation rows against the position rows
  double damping = 1e-5;                 ///< lambda's floor (m^2): regularises near singularities
  double max_step = 0.3;                 ///< rad, largest joint change in one iteration (inf-norm)
  double limit_clearance = 0.01;         ///< rad, kept from each joint limit by clamping
  double nullspace_gain = 0.1;           ///< fraction of the distance to mid-range moved per iteration (null space)
  double nullspace_max_step = 0.05;      ///< rad, largest null-space joint change in one iteration (inf-norm)
  /// Iterations stop early when the weighted error drops by less than this
  /// fraction over `stall_window` iterations (a local minimum, e.g. against a limit).
  double stall_ratio = 1e-3;
  int stall_window = 8;
};

struct IkResult {
  Vector7 q = Vector7::Zero();    ///< rad, within [q_min, q_max] (minus limit_clearance)
  bool converged = false;         ///< both errors below their tolerances
  int iterations = 0;
  double position_error = 0.0;    ///< m, |p_target - p(q)|
  double orientation_error = 0.0; ///< rad, angle of R_target R(q)'
};

/// Solves for q such that frame `frame_id` reaches `target` (world), starting
/// from `seed` (rad; clamped into the limits first). Returns the last iterate
/// with its residuals even when it did not converge (unreachable target, or a
/// local minimum against a joint limit: try another seed).
IkResult solveIk(const Model& model, int frame_id, const Isometry& target, const Vector7& seed,
                 const IkOptions& options);

/// solveIk from each of `seeds[0..num_seeds)` in turn, returning the first
/// converged result (seeds in order of preference, e.g. the current q first),
/// else the one with the smallest weighted residual. Real-time safe.
IkResult solveIkMultiStart(const Model& model, int frame_id, const Isometry& target, const Vector7* seeds,
                           int num_seeds, const IkOptions& options);

/// Position and rotation errors (m, rad) of frame `frame_id` at q against `target`.
void poseError(const Model& model, int frame_id, const Vector7& q, const Isometry& target, double& position_error,
               double& orientation_error);

}  // namespace handover::control::grasp
