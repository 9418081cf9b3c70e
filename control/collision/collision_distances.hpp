// The per-cycle collision pipeline stage: body poses -> broad phase ->
// FCL narrow phase -> distance, normal, Jacobian row and drift per pair.
#pragma once

#include <string>

#include "control/collision/collision_data.hpp"
#include "control/collision/collision_environment.hpp"
#include "control/model/model.hpp"

namespace handover::control {

/// Updates every pair of `cdata` for the robot state in `data` (forwardKinematics
/// or computeAll already run; data.v is qdot) and the person in `env`.
/// Pairs of disabled rules, person pairs without a valid person, and pairs
/// whose bounding spheres are farther apart than iDist + broadphase_margin
/// come out inactive. For active pairs:
///   d_dot  = jacobian * qdot - n' v_other_env
///   d_ddot = jacobian * qddot + drift, exact for the point-to-point model
///            (ndot = (I - n n')(v1 - v2) / core_distance); when the other
///            core point lies on a box face, n turns with the box instead.
/// Real-time safe: no allocation, no exceptions.
void updateCollisions(const CollisionModel& cmodel, CollisionData& cdata, const Model& model, const Data& data,
                      const CollisionEnvironment& env);

/// Switches a pair rule on or off by name (the state machine relaxes e.g. the
/// hand-gripper pair while grasping). Throws InputError naming the rule and
/// listing the known ones when the name is unknown. Not real-time safe (string
/// search); use setRuleEnabled(index) in the loop.
void setRuleEnabled(const CollisionModel& cmodel, CollisionData& cdata, const std::string& rule, bool enabled);
/// Real-time safe variant by index (CollisionModel::ruleIndex).
void setRuleEnabled(CollisionData& cdata, int rule, bool enabled);

/// Smallest distance over active pairs whose other body is the person (or
/// +inf when none). Real-time safe.
double minPersonDistance(const CollisionModel& cmodel, const CollisionData& cdata);

/// The active pair nearest its safety distance: the one whose damper is
/// closest to stopping the robot (what holds the arm back when it stalls).
struct NearestPair {
  int pair = -1;       ///< index into CollisionModel::pairs, -1 when no pair is active
  double gap = 0.0;    ///< m, its distance (after margins) minus its sDist
};
/// Real-time safe.
NearestPair nearestToSafetyDistance(const CollisionModel& cmodel, const CollisionData& cdata);

}  // namespace handover::control
