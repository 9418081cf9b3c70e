// The open gripper rides along with the object a receiver takes out of it.
//
// From the release on, the receiver moves the object while it still lies
// between the fingers. A gripper that holds its place (or backs straight
// out) is struck by it wherever the pull has a component along the closing
// axis: at 0.4 m/s a finger pad 5 mm off the object is met within 15 ms, and
// the blow spins the wrist past its velocity limit before any force is felt
// to yield to. So the set-point moves with the object as it is seen leaving:
// its displacement since the release, across the approach axis (along it the
// object leaves through the fingertips, or the gripper backs away from it),
// with its velocity fed forward so that the arm does not lag D v / K behind;
// and only as far as the object must go to be clear of the finger pads (its
// bounding radius plus a pad's half span): beyond that the gripper has
// nothing left to make way for. The object's estimate when it is seen, else
// the hand that holds it. Real-time safe.
#pragma once

#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

class ReleaseRide {
 public:
  /// At the release: the TCP's approach axis (world), where the leaving body
  /// is now, and how far it must go to clear the fingers. Off (params) or
  /// nothing seen: rides nowhere.
  void start(const HandoverContext& ctx) {
    const HandoverInput& in = ctx.in;
    axis_ = in.tcp_pose.linear().col(2);
    body_ = ctx.params->release_ride ? leaving(in) : Body::kNone;
    if (body_ != Body::kNone) origin_ = pose(in).translation();
    clear_ = io::boundingRadius(ctx.object.shape) + ctx.params->finger_half_span;
  }

  /// Offset (world, m) of the set-point from where the release left it, and
  /// its rate (m/s); zero when nothing is seen.
  void follow(const HandoverInput& in, Vector3& offset, Vector3& velocity) const {
    offset.setZero();
    velocity.setZero();
    if (body_ == Body::kNone) return;
    const SensedBody& b = body_ == Body::kObject ? in.object : in.hand;
    if (!b.valid) return;
    const Vector3 moved = b.pose.translation() - origin_;
    const Vector3 across = moved - moved.dot(axis_) * axis_;
    const double n = across.norm();
    offset = n > clear_ ? (clear_ / n) * across : across;
    if (n <= clear_) velocity = b.velocity.head<3>() - b.velocity.head<3>().dot(axis_) * axis_;
  }

  /// The pose task's set-point: `hold` (world) moved by follow(), its rate fed forward.
  void hold(ControllerHandle& ctrl, const Isometry& hold, const HandoverInput& in) const {
    Vector3 offset, velocity;
    follow(in, offset, velocity);
    Isometry goal = hold;
    goal.translation() += offset;
    Vector6 twist = Vector6::Zero();
    twist.head<3>() = velocity;
    ctrl.setPoseTarget(goal, twist);
  }

 private:
  enum class Body { kNone, kObject, kHand };
  static Body leaving(const HandoverInput& in) {
    if (in.object.valid) return Body::kObject;
    if (in.hand.valid) return Body::kHand;
    return Body::kNone;
  }
  const Isometry& pose(const HandoverInput& in) const { return body_ == Body::kObject ? in.object.pose : in.hand.pose; }

  Vector3 axis_ = Vector3::UnitZ();
  Body body_ = Body::kNone;
  Vector3 origin_ = Vector3::Zero();
  double clear_ = 0.0;  ///< m, how far the object goes before it is clear of the fingers
};

}  // namespace handover::fsm
