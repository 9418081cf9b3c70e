// What the grasp planner tells the state machine (runtime/grasp_planning
// implements it with inverse kinematics on the robot's own model): which of
// the grasps an object admits the arm reaches best, and where to put a held
// object upright. The states decide when to follow a plan and when to hold
// on to the one they committed to (the grasp being closed, the object held).
//
// Frames: world (z up, base at the origin); offsets in the observed frame
// (object or hand). Units: m, rad.
#pragma once

#include "fsm/handover/controller_interface.hpp"

namespace handover::fsm {

/// The planner's latest choice of tracking target, updated at the sensor
/// rate. For the take: the grasp frame in the object frame; for the give:
/// the TCP in the receiver's hand frame.
struct TrackingPlan {
  bool valid = false;   ///< false: no candidate is reachable (or no planner)
  int index = -1;       ///< the candidate's identity; a new index = the choice switched
  Isometry target_in_observed = Isometry::Identity();
  Vector7 q_target = Vector7::Zero();  ///< rad, IK configuration at the target (posture reference)
  Vector7 q_pre = Vector7::Zero();     ///< rad, IK configuration at the pre-target (backed off along the approach axis)
};

/// An arm configuration that holds the object upright near a requested place.
struct ArmPlacement {
  bool found = false;
  Isometry tcp = Isometry::Identity();  ///< TCP pose to go to, world
  Vector7 q = Vector7::Zero();          ///< rad, its IK configuration (posture reference)
};

class PlannerInterface {
 public:
  virtual ~PlannerInterface() = default;
  /// Where to hold the object (its pose in the TCP frame `object_in_tcp`)
  /// with its axis `up_axis` (object frame, unit) along world z, near
  /// `object_position` (world, m), starting from q_now; with receiver_stop > 0
  /// (m, CarryRequest::receiver_stop) away from the path of the person who
  /// will reach for it there. Not
  /// cheap (about 1.5 ms: many IK solves): never inside the control step;
  /// HandoverFsm::plan calls it to answer a state's carry request
  /// (carry_request.hpp). No allocation.
  virtual ArmPlacement uprightPlacement(const Isometry& object_in_tcp, const Vector3& up_axis,
                                        const Vector3& object_position, const Vector7& q_now,
                                        double receiver_stop) = 0;
};

}  // namespace handover::fsm
