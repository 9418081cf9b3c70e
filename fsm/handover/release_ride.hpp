// The open gripper rides along with the object a receiver takes out of it.
//
// From the release on, the receiver moves the object while it still lies
// between the fingers. A gripper that holds its place (or backs straight
// out) is struck by it wherever the pull has a component along the closing
// axis: at 0.4 m/s a finger pad 5 mm off the object is met within 15 ms, and
// the blow spins the wrist past its velocity limit before any force is felt
// to yield to. So the set-point moves with the object as it is seen leaving:
// its displacement since the release, across the approach axis (along it the
// object leaves through the fingertips, or the gripper backs away from it;
// pushed the other way, deeper into the gripper, it is followed back too),
// with its velocity fed forward so that the arm does not lag D v / K behind;
// and only as far as the object must go to be clear of the finger pads (its
// bounding radius plus a pad's half span): beyond that the gripper has
// nothing left to make way for. The object's estimate when it is seen and not the
// robot's own (a payload set), else the hand that holds it; of the hand's motion
// only what comes at the gripper (along the closing axis, and along the
// fingers' faces toward the TCP: atGripper).
//
// The opening itself makes way for the receiver's hand: a parallel gripper
// opens symmetrically about the TCP, so with the closing axis pointing at the
// hand (an object put on a palm from the side, one finger between the object
// and the palm) the near finger moves into the palm by half the width gained
// (g787_00457: the lower finger grazed the palm as it opened). The set-point
// moves along the closing axis by half the width gained since the release,
// away from the hand, scaled by how much the closing axis points at it
// (cos of the angle between the axis and the hand-to-TCP line): the near
// finger stays where it was, the far one takes the whole opening; with the
// closing axis across the line to the hand nothing moves. Real-time safe.
#pragma once

#include <algorithm>
#include <cmath>

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
    body_ = ctx.params->release_ride ? leaving(in, ctx.ledger != nullptr && ctx.ledger->payloadSet()) : Body::kNone;
    if (body_ != Body::kNone) origin_ = pose(in).translation();
    closing_ = in.tcp_pose.linear().col(1);
    faces_ = in.tcp_pose.linear().col(0);
    clear_ = io::boundingRadius(ctx.object.shape) + ctx.params->finger_half_span;
    into_ = 0.0;
    width_ = in.finger_width;
    last_width_ = in.finger_width;
    last_time_ = in.time;
    opening_rate_ = 0.0;
    // how much the closing axis and the fingers' faces point at the hand (cosines to the
    // hand-to-TCP line): the opening's shift, and what of the hand's motion comes at the gripper
    away_.setZero();
    faces_toward_ = 0.0;
    if (ctx.params->release_ride && in.hand.valid) {
      const Vector3 from_hand = in.tcp_pose.translation() - in.hand.pose.translation();
      const double n = from_hand.norm();
      if (n > 1e-9) {
        away_ = closing_ * (closing_.dot(from_hand) / n);
        if (body_ == Body::kHand) faces_toward_ = faces_.dot(from_hand) / n;
      }
    }
  }

  /// Offset (world, m) of the set-point from where the release left it, and
  /// its rate (m/s); zero when nothing is seen.
  /// Call once per cycle: it keeps how far the object has pushed in.
  void follow(const HandoverInput& in, Vector3& offset, Vector3& velocity) {
    offset.setZero();
    velocity.setZero();
    // the near finger holds its place as the fingers open (never back: a
    // closing gripper is not this state's), the opening's rate fed forward:
    // the pose task's soft spring alone lagged the half millimetre a finger
    // gains every 10 ms
    offset += away_ * (0.5 * std::max(0.0, in.finger_width - width_));
    velocity += away_ * (0.5 * opening_rate_);
    if (body_ == Body::kNone) return;
    const SensedBody& b = body_ == Body::kObject ? in.object : in.hand;
    if (!b.valid) return;
    const Vector3 moved = b.pose.translation() - origin_;
    const Vector3 across = atGripper(moved - moved.dot(axis_) * axis_);
    const double n = across.norm();
    offset += n > clear_ ? (clear_ / n) * across : across;
    const Vector3 v = b.velocity.head<3>();
    const bool between = n <= clear_;
    if (between) velocity += atGripper(v - v.dot(axis_) * axis_);
    // pushed into the gripper (against the approach axis) while it is still
    // between the fingers, it is followed back as far as it goes: the palm
    // has no clearance to let it by (a receiver lifting a key fob off the
    // fingers raised their palm into the fingertips of a gripper held
    // stiffly where it was, o_31); once clear of the pads it leaves no more
    // room to make, and the set-point keeps what it made
    const double along = moved.dot(axis_);
    if (between && along < into_) into_ = along;
    offset += into_ * axis_;
    if (between && along <= into_) velocity += std::min(0.0, v.dot(axis_)) * axis_;
  }

  /// Measures how fast the fingers open (call every cycle, before follow()).
  void measure(const HandoverInput& in) {
    const double dt = in.time - last_time_;
    if (dt <= 0.0) return;
    // the width's rate over this cycle, smoothed over kRateTime (a gripper
    // reports its width in steps, not at every control cycle)
    const double rate = std::max(0.0, in.finger_width - last_width_) / dt;
    opening_rate_ += (rate - opening_rate_) * std::min(1.0, dt / kRateTime);
    last_width_ = in.finger_width;
    last_time_ = in.time;
  }

  /// The pose task's set-point: `hold` (world) moved by follow(), its rate
  /// fed forward; measures the opening first.
  void hold(ControllerHandle& ctrl, const Isometry& hold, const HandoverInput& in) {
    measure(in);
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
  // While the robot carries the object's weight (a payload set: Release, ConfirmGone) its
  // estimate is where the gripper holds it, not where the receiver takes it: following that
  // followed the gripper itself, and a receiver lifting a box out of a side grip raised their
  // hand into fingers that never made way (outsider e_41). The hand that takes it then.
  static Body leaving(const HandoverInput& in, bool robot_carries) {
    if (in.object.valid && !robot_carries) return Body::kObject;
    if (in.hand.valid) return Body::kHand;
    return Body::kNone;
  }
  const Isometry& pose(const HandoverInput& in) const { return body_ == Body::kObject ? in.object.pose : in.hand.pose; }
  // What of a motion across the approach axis comes at the gripper. The object leaves between
  // the fingers in any direction. The hand that holds it strikes a pad along the closing axis,
  // and the fingers along their faces only where it comes at them: scaled by the cosine of the
  // faces' direction to the hand-to-TCP line, and only toward the TCP (a receiver lifting a box
  // held from the side raised their hand into the fingers above it, outsider e_41); a hand
  // pulled away along the faces is not chased (at 0.8 m/s the arm ran past its speed limits
  // after it, outsider r_29).
  Vector3 atGripper(const Vector3& across) const {
    if (body_ != Body::kHand) return across;
    const double along_faces = faces_.dot(across);
    const double toward = along_faces * faces_toward_ > 0.0 ? std::abs(faces_toward_) : 0.0;
    return closing_ * closing_.dot(across) + faces_ * (toward * along_faces);
  }

  Vector3 axis_ = Vector3::UnitZ();
  Vector3 closing_ = Vector3::UnitY();  ///< the TCP's closing axis (world) at the release
  Vector3 faces_ = Vector3::UnitX();    ///< the fingers' faces' direction across the approach (world)
  double faces_toward_ = 0.0;           ///< cosine of faces_ to the hand-to-TCP line (0: not the hand)
  Body body_ = Body::kNone;
  Vector3 origin_ = Vector3::Zero();
  double clear_ = 0.0;  ///< m, how far the object goes before it is clear of the fingers
  static constexpr double kRateTime = 0.01;  ///< s, smoothing of the opening rate
  double width_ = 0.0;  ///< m, the finger opening at the release
  double into_ = 0.0;   ///< m (<= 0), farthest the object went into the gripper while between the fingers
  double last_width_ = 0.0, last_time_ = 0.0;  ///< m, s: the previous cycle's
  double opening_rate_ = 0.0;                  ///< m/s, smoothed, >= 0
  /// unit closing axis (world) scaled by the cosine of its angle to the
  /// hand-to-TCP line: the set-point's way per metre of half-width gained
  Vector3 away_ = Vector3::Zero();
};

}  // namespace handover::fsm
