// Where to carry a held object: a named TCP pose (stow, safe, ready) assumes
// the gripper points down, which tilts or hangs an object grasped from the
// side and may be out of reach with it. With a planner, the goal becomes an
// upright placement of the object near where the named pose would put it,
// reached by a move in joint space to its IK configuration: the posture task
// alone (pose task off) drives every joint along the same critically damped
// profile, a straight line between two configurations within the limits,
// so it stays within them. A TCP pose task toward the same goal would follow
// the shortest turn of the gripper, which may run the wrist into its limit.
//
// The placement search (about 1.5 ms) never runs in the control step: the
// carry posts a request (carry_request.hpp) and heads for the named pose at
// once; the planning stage answers before the next step, and the carry
// switches to the placement in that step (one cycle on the named pose).
// With params.carry.joint_speed > 0 the move in joint space is timed
// (timed_move.hpp): a cruise profile fed forward to the posture task
// (on as shipped: config/fsm.yaml carry).
// RT safe: no search, no allocation.
#pragma once

#include "fsm/handover/handover_context.hpp"
#include "fsm/handover/timed_move.hpp"

namespace handover::fsm {

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

/// Carries the held object toward a named pose: a member of each state that
/// carries one (Retract, HoldReady, Retreat), started in onStart, updated in
/// every onRun, stopped in onTeardown.
class HeldObjectCarry {
 public:
  /// Sends `named` through the pose task and, with a planner, posts the
  /// placement request: with the object in the gripper, an upright placement
  /// of it (`up_axis`: the object-frame axis to keep vertical, handedUpAxis
  /// or presentedUpAxis); with an empty gripper, the named pose itself with
  /// its turn about the vertical left free (the TCP axis that points up in
  /// `named` kept up). Either way the arm then moves in joint space to an IK
  /// configuration within its limits: a pose task from a far, turned wrist
  /// can stall against a joint limit on the way (an elbow at its limit after
  /// a give whose wrist had turned 160 degrees). receiver_stop (m, > 0): a
  /// person will reach for the object there (CarryRequest::receiver_stop).
  void start(HandoverContext& ctx, ControllerHandle& ctrl, const Isometry& named, const Vector3& up_axis,
             double receiver_stop = 0.0) {
    goal_ = named;
    request_ = 0;
    move_.stop();
    ctrl.setPoseTarget(named);
    if (ctx.planner == nullptr) return;
    if (!ctx.ledger->payloadSet()) {
      request_ = ctx.carry.post(Isometry::Identity(), handedUpAxis(named.linear()), named.translation(), ctx.in.q);
      return;
    }
    const Isometry object_in_tcp = ctx.objectInTcp();
    request_ = ctx.carry.post(object_in_tcp, up_axis, (named * object_in_tcp).translation(), ctx.in.q, receiver_stop);
  }

  /// Adopts the answer to this carry's request once it has come: a found
  /// placement replaces the named pose by the move in joint space (timed from
  /// where the arm is then with params.carry.joint_speed > 0, the posture
  /// reference then moved along that profile); none keeps the named pose.
  /// Call at the start of every onRun.
  void update(HandoverContext& ctx, ControllerHandle& ctrl) {
    if (move_.active()) {
      Vector7 q, qd, qdd;
      move_.sample(ctx.in.time, q, qd, qdd);
      ctrl.setPostureTarget(q, qd, qdd);
    }
    if (request_ == 0) return;
    const ArmPlacement* answer = ctx.carry.answerTo(request_);
    if (answer == nullptr) return;
    request_ = 0;
    if (!answer->found) return;
    ctrl.clearPoseTarget();
    goal_ = answer->tcp;
    const HandoverParams& p = *ctx.params;
    if (p.carry_joint_speed <= 0.0) {
      ctrl.setPostureTarget(answer->q);
      return;
    }
    move_.start(ctx.in.q, answer->q,
                cruiseFor((answer->q - ctx.in.q).cwiseAbs().maxCoeff(), p.carry_joint_speed,
                          p.carry_joint_acceleration, (answer->tcp.translation() - ctx.in.tcp_pose.translation()).norm(),
                          p.grip_acceleration, p.carry_min_duration),
                ctx.in.time);
    ctrl.setPostureTarget(ctx.in.q);  // the profile's start, at rest
  }

  /// Withdraws a request still waiting (the state ends first).
  void stop(HandoverContext& ctx) {
    ctx.carry.withdraw(request_);
    request_ = 0;
  }

  /// The request has no answer yet: the goal may still change (a state does
  /// not finish on the named pose while the placement may lie elsewhere).
  bool waiting() const { return request_ != 0; }
  /// The TCP pose the carry ends at: `named`, or the placement once adopted.
  const Isometry& goal() const { return goal_; }

 private:
  Isometry goal_ = Isometry::Identity();
  int request_ = 0;  ///< the request awaiting its answer (0: none)
  JointMove move_;   ///< the timed move to the placement's configuration
};

}  // namespace handover::fsm
