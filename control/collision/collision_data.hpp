// Per-cycle collision results (Model/Data split: sized once from a
// CollisionModel; updateCollisions() then never allocates). One per thread.
#pragma once

#include <vector>

#include "control/collision/collision_model.hpp"
#include "control/collision/shape_distance.hpp"

namespace handover::control {

using RowVector7 = Eigen::Matrix<double, 1, 7>;

/// Distance of one pair at the current state. World frame, SI units.
/// The distance model: d = |c_robot - c_other| - r_robot - r_other - margin,
/// with c_* the closest points of the two cores (segment or box), treated as
/// fixed on their bodies for the derivatives.
struct PairResult {
  bool active = false;        ///< computed this cycle (enabled, person known, not culled)
  bool penetrating = false;   ///< cores touch: distance clamped, normal kept from before
  double distance = 0.0;      ///< d, m (negative once the surfaces overlap)
  double core_distance = 0.0; ///< |c_robot - c_other|, m
  Vector3 p_robot = Vector3::Zero();  ///< witness point on the robot capsule surface, m
  Vector3 p_other = Vector3::Zero();  ///< witness point on the other body's surface (without margin), m
  Vector3 c_robot = Vector3::Zero();  ///< closest point of the robot core, m
  Vector3 c_other = Vector3::Zero();  ///< closest point of the other core, m
  Vector3 normal = Vector3::UnitZ();  ///< unit, from the other body toward the robot body
  RowVector7 jacobian = RowVector7::Zero();  ///< dd/dq = n' (J_robot - J_other), 1/m... m/rad
  double d_dot = 0.0;   ///< m/s: jacobian * qdot minus the other body's own motion along n
  double drift = 0.0;   ///< m/s^2: d_ddot = jacobian * qddot + drift
};

struct CollisionData {
  explicit CollisionData(const CollisionModel& model);

  ShapeDistance shapes;               ///< FCL geometries (segment lengths follow the person)
  std::vector<Isometry> body_pose;    ///< world pose of each body's core canonical frame
  std::vector<Vector6> body_twist;    ///< [v of the canonical origin; omega], world (environment bodies)
  std::vector<bool> rule_enabled;     ///< run-time switch per pair rule
  std::vector<PairResult> results;    ///< one per CollisionModel::pairs entry
  std::vector<Vector3> last_normal;   ///< per pair: kept for penetrating cycles
  std::vector<bool> has_last_normal;
  int num_active = 0;                 ///< active pairs this cycle
  int num_narrow = 0;                 ///< pairs that reached the FCL narrow phase this cycle
};

}  // namespace handover::control
