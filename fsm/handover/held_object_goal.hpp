// Where to carry a held object: a named TCP pose (stow, safe, ready) assumes
// the gripper points down, which tilts or hangs an object grasped from the
// side and may be out of reach with it. With a planner, the goal becomes an
// upright placement of the object near where the named pose would put it,
// reached by a move in joint space to its IK configuration: the posture task
// alone (pose task off) drives every joint along the same critically damped
// profile, a straight line between two configurations within the limits,
// so it stays within them. A TCP pose task toward the same goal would follow
// the shortest turn of the gripper, which may run the wrist into its limit.
// RT safe apart from the planner's search (about 1 ms, once per phase start).
#pragma once

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Sends the controller toward the goal for carrying the held object to
/// `named` and returns the TCP pose it ends at: `named` through the pose
/// task when there is no planner, the gripper holds nothing, or no upright
/// placement was found; else the placement, in joint space.
/// The axis of the object's frame (+-x, +-y, +-z) nearest to world up for the
/// object at rotation R_obj: the way up it was handed over, squared to its own
/// axes (a bottle stays standing, a baton held lying stays lying).
inline Vector3 handedUpAxis(const Eigen::Matrix3d& R_obj) {
  const Vector3 up_in_object = R_obj.transpose() * Vector3::UnitZ();
  Eigen::Index k = 0;
  up_in_object.cwiseAbs().maxCoeff(&k);
  return Vector3::Unit(k) * (up_in_object[k] >= 0.0 ? 1.0 : -1.0);
}

/// The take: the way up the person handed the object over (its pose now).
inline Vector3 handedUpAxis(const HandoverContext& ctx) {
  return handedUpAxis(ctx.in.tcp_pose.linear() * ctx.objectInTcp().linear());
}
/// The give: the way up it will sit in the receiver's hand (params.object_in_hand).
inline Vector3 presentedUpAxis(const HandoverContext& ctx) {
  return handedUpAxis(ctx.params->object_in_hand.linear());
}

/// `up_axis`: the object-frame axis to keep vertical (handedUpAxis or presentedUpAxis).
inline Isometry carryHeldObject(HandoverContext& ctx, ControllerHandle& ctrl, const Isometry& named,
                                const Vector3& up_axis) {
  if (ctx.planner != nullptr && ctx.ledger->payloadSet()) {
    const Isometry object_in_tcp = ctx.objectInTcp();
    const Vector3 position = (named * object_in_tcp).translation();
    const ArmPlacement placement = ctx.planner->uprightPlacement(object_in_tcp, up_axis, position, ctx.in.q);
    if (placement.found) {
      ctrl.clearPoseTarget();
      ctrl.setPostureTarget(placement.q);
      return placement.tcp;
    }
  }
  ctrl.setPoseTarget(named);
  return named;
}

}  // namespace handover::fsm
