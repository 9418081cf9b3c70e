// Where to put a held object upright: the stow pose after a take, or the
// presentation pose to a receiver, for an object grasped in any orientation.
//
// The object's up axis must point along world z; any turn about z is
// admissible. For each nominal position (the given one plus the configured
// offsets, in order) the turns about z are sampled every `yaw_step`; the
// object pose gives the TCP pose through the grasp (X_tcp = X_obj X_obj^tcp^-1),
// IK solves it from the current q then the fixed seeds, and the best-scoring
// solution (grasp_score.hpp: joint margin, manipulability, motion from q_now)
// at the first position with any solution wins. A solution whose object tilt
// exceeds `tilt_tolerance`, or whose arm dips into the table, is rejected.
//
// Frames: world; the grasp is the object's pose in the TCP frame. Units: m, rad.
// Real-time safe (no allocation) but not cheap: up to positions x turns x
// seeds IK solves (about 0.1-1 ms with the defaults): call it when a phase
// starts (Retract, Give) or at the sensor rate, not in every control step.
#pragma once

#include "control/grasp/grasp_selection_config.hpp"

namespace handover::control::grasp {

/// How the gripper holds the object.
struct HeldObject {
  Isometry object_in_tcp = Isometry::Identity();  ///< X_obj^tcp: object pose in the TCP frame
  Vector3 up_axis = Vector3::UnitZ();             ///< object frame, unit: the axis to keep vertical
};

struct UprightPlacement {
  bool found = false;
  Vector7 q = Vector7::Zero();                  ///< rad, IK configuration (posture reference)
  Isometry tcp = Isometry::Identity();          ///< world TCP pose to track
  Isometry object = Isometry::Identity();       ///< world object pose it puts the object in
  double yaw = 0.0;                             ///< rad, turn about world z of the chosen sample
  double tilt = 0.0;                            ///< rad, angle between the object's up axis and world z at q
  Vector3 offset = Vector3::Zero();             ///< m, position offset used (0 = the nominal position)
  ScoreTerms score;
  int ik_solves = 0;                            ///< cost of the search
};

/// Object pose with its up axis along world z, turned by `yaw` about z, at `position` (world).
Isometry uprightObjectPose(const Vector3& up_axis, double yaw, const Vector3& position);

/// Searches an upright placement of `held` near `position` (world, m) for the
/// arm at q_now (rad). `config` gives the frame, IK options and seeds, score
/// weights and the upright options; optional obstacle capsules (world, e.g.
/// the receiver's arm) enter the score's clearance term.
UprightPlacement findUprightPlacement(const Model& model, const HeldObject& held, const Vector3& position,
                                      const Vector7& q_now, const GraspSelectionConfig& config,
                                      const ObstacleCapsule* obstacles = nullptr, int num_obstacles = 0);

}  // namespace handover::control::grasp
