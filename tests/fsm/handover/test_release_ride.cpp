// ReleaseRide (fsm/handover/release_ride.hpp): the opening fingers make way
// for the receiver's hand. A ball put on a palm from the side has one finger
// between the ball and the palm; a parallel gripper opens symmetrically, so
// without a shift that finger moves into the palm (g787_00457).
#include <gtest/gtest.h>

#include <cmath>

#include "fsm/handover/release_ride.hpp"

namespace handover::fsm {
namespace release_ride_test {

constexpr double kCycle = 0.001;  // s
constexpr double kOpeningRate = 0.1;  // m/s, total finger opening rate

struct Opening {
  HandoverParams params;
  HandoverContext ctx;
  ReleaseRide ride;

  /// TCP at the origin with the closing axis (y) along `closing`; the
  /// receiver's hand (grip point) at `hand`; fingers at `width`.
  Opening(const Vector3& closing, const Vector3& hand, double width) {
    params.release_ride = true;
    ctx.params = &params;
    ctx.object.shape.kind = io::ObjectShape::Kind::kSphere;
    ctx.object.shape.size = Vector3(0.026, 0.0, 0.0);
    Isometry tcp = Isometry::Identity();
    const Vector3 y = closing.normalized();
    const Vector3 z = y.unitOrthogonal();
    tcp.linear().col(0) = y.cross(z);
    tcp.linear().col(1) = y;
    tcp.linear().col(2) = z;
    ctx.in.tcp_pose = tcp;
    ctx.in.finger_width = width;
    ctx.in.hand.valid = true;
    ctx.in.hand.pose.translation() = hand;
    ctx.in.object.valid = false;  // the receiver's hand is the leaving body; it stays put here
    ride.start(ctx);
  }

  /// One cycle with the fingers opening at kOpeningRate; the set-point's offset
  /// and rate from the release.
  void step(Vector3& offset, Vector3& velocity) {
    ctx.in.time += kCycle;
    ctx.in.finger_width += kOpeningRate * kCycle;
    ride.measure(ctx.in);
    ride.follow(ctx.in, offset, velocity);
  }
};

TEST(ReleaseRide, TheFingerBetweenTheObjectAndThePalmHoldsItsPlaceAsTheGripperOpens) {
  // closing axis vertical, the palm 6.5 cm below the TCP: the lower finger
  // sits on the palm's side
  const Vector3 up = Vector3::UnitZ();
  Opening r(up, Vector3(0.0, 0.0, -0.065), 0.052);
  Vector3 offset, velocity;
  double width = 0.0;
  for (int k = 0; k < 200; ++k) {
    r.step(offset, velocity);
    width = r.ctx.in.finger_width;
    // the lower finger: the set-point's TCP minus half the opening along the axis
    const double lower_finger = offset.dot(up) - 0.5 * width;
    ASSERT_NEAR(lower_finger, -0.5 * 0.052, 1e-12) << k;
  }
  EXPECT_NEAR(offset.dot(up), 0.5 * (width - 0.052), 1e-12);
  EXPECT_NEAR(offset.head<2>().norm(), 0.0, 1e-12);
  // the opening's rate fed forward, half of it on the TCP
  EXPECT_NEAR(velocity.dot(up), 0.5 * kOpeningRate, 1e-6);
}

TEST(ReleaseRide, TheGripperOpensInPlaceWhenItsClosingAxisRunsAcrossTheLineToTheHand) {
  // a cylinder gripped from above, the hand beside it along the approach
  Opening r(Vector3::UnitY(), Vector3(0.0, 0.0, -0.065), 0.03);
  Vector3 offset, velocity;
  for (int k = 0; k < 100; ++k) r.step(offset, velocity);
  EXPECT_LT(offset.norm(), 1e-12);
  EXPECT_LT(velocity.norm(), 1e-12);
}

TEST(ReleaseRide, TheShiftScalesWithHowMuchTheClosingAxisPointsAtTheHand) {
  // the hand 60 degrees off the closing axis: the set-point moves cos(60) of
  // half the opening, along the axis, away from the hand
  const Vector3 axis = Vector3::UnitZ();
  const Vector3 hand = -0.07 * Vector3(std::sin(M_PI / 3.0), 0.0, std::cos(M_PI / 3.0));
  Opening r(axis, hand, 0.04);
  Vector3 offset, velocity;
  for (int k = 0; k < 100; ++k) r.step(offset, velocity);
  const double half_gained = 0.5 * (r.ctx.in.finger_width - 0.04);
  EXPECT_NEAR(offset.dot(axis), 0.5 * half_gained, 1e-12);
  EXPECT_NEAR((offset - offset.dot(axis) * axis).norm(), 0.0, 1e-12);
}

TEST(ReleaseRide, ClosingFingersAndAnUnseenHandMoveNothingAndTheRideCanBeSwitchedOff) {
  {
    Opening r(Vector3::UnitZ(), Vector3(0.0, 0.0, -0.065), 0.05);
    Vector3 offset, velocity;
    for (int k = 0; k < 50; ++k) {
      r.ctx.in.time += kCycle;
      r.ctx.in.finger_width -= kOpeningRate * kCycle;  // closing: not this state's
      r.ride.measure(r.ctx.in);
      r.ride.follow(r.ctx.in, offset, velocity);
    }
    EXPECT_LT(offset.norm(), 1e-12);
    EXPECT_LT(velocity.norm(), 1e-12);
  }
  for (const bool switched_off : {true, false}) {
    // the hand on the closing axis, but the ride switched off, or the hand unseen
    HandoverParams params;
    params.release_ride = !switched_off;
    HandoverContext ctx;
    ctx.params = &params;
    ctx.in.finger_width = 0.05;
    ctx.in.hand.pose.translation() = Vector3(0.0, -0.065, 0.0);
    ctx.in.hand.valid = switched_off;
    ReleaseRide ride;
    ride.start(ctx);
    Vector3 offset, velocity;
    for (int k = 0; k < 50; ++k) {
      ctx.in.time += kCycle;
      ctx.in.finger_width += kOpeningRate * kCycle;
      ride.measure(ctx.in);
      ride.follow(ctx.in, offset, velocity);
    }
    EXPECT_LT(offset.norm(), 1e-12) << switched_off;
    EXPECT_LT(velocity.norm(), 1e-12) << switched_off;
  }
}

/// A box of `size` held at `width`, the ride on and the receiver's hand seen
/// (the TCP at the origin unless the test turns it).
struct HeldBox {
  HandoverParams params;
  HandoverContext ctx;
  HeldBox(const Vector3& size, double width) {
    params.release_ride = true;
    ctx.params = &params;
    ctx.object.shape.kind = io::ObjectShape::Kind::kBox;
    ctx.object.shape.size = size;
    ctx.in.finger_width = width;
    ctx.in.hand.valid = true;
  }
  HeldBox(const HeldBox&) = delete;
  /// m: how far the object goes before it is clear of the pads
  double clear() const { return io::boundingRadius(ctx.object.shape) + params.finger_half_span; }
};

TEST(ReleaseRide, AnObjectPushedIntoTheGripperIsFollowedBackAndOneLeavingThroughTheFingertipsIsNot) {
  // approach axis z: the object leaves through the fingertips toward +z
  HeldBox box(Vector3(0.07, 0.03, 0.012), 0.03);
  HandoverContext& ctx = box.ctx;
  ctx.in.hand.pose.translation() = Vector3(0.0, 0.0, 0.05);  // along the approach: no opening shift
  ctx.in.object.valid = true;
  const Vector3 start(0.0, 0.0, 0.01);
  const double clear = box.clear();
  Vector3 offset, velocity;
  {
    // leaving through the fingertips: the gripper holds along the approach
    ctx.in.object.pose.translation() = start;
    ReleaseRide ride;
    ride.start(ctx);
    ctx.in.object.pose.translation() = start + Vector3(0.0, 0.0, 0.03);
    ctx.in.object.velocity.head<3>() = Vector3(0.0, 0.0, 0.3);
    ride.follow(ctx.in, offset, velocity);
    EXPECT_LT(offset.norm(), 1e-12);
    EXPECT_LT(velocity.norm(), 1e-12);
  }
  ctx.in.object.pose.translation() = start;
  ReleaseRide ride;
  ride.start(ctx);
  // pushed 3 cm up into the gripper while across by less than the pads' clearance
  ctx.in.object.pose.translation() = start + Vector3(0.5 * clear, 0.0, -0.03);
  ctx.in.object.velocity.head<3>() = Vector3(0.1, 0.0, -0.2);
  ride.follow(ctx.in, offset, velocity);
  EXPECT_NEAR(offset.z(), -0.03, 1e-12);  // followed back all the way
  EXPECT_NEAR(velocity.z(), -0.2, 1e-12);
  EXPECT_NEAR(offset.x(), 0.5 * clear, 1e-12);
  // out across, clear of the pads, and further in: nothing more to make way
  // for, and the set-point keeps the way it made (no step back toward it)
  ctx.in.object.pose.translation() = start + Vector3(2.0 * clear, 0.0, -0.06);
  ride.follow(ctx.in, offset, velocity);
  EXPECT_NEAR(offset.z(), -0.03, 1e-12);
  EXPECT_NEAR(offset.x(), clear, 1e-12);
  EXPECT_NEAR(velocity.z(), 0.0, 1e-12);
}

// The hand that takes the object (the leaving body while the robot still
// carries the payload): the gripper follows it along the closing axis (the
// object it holds would strike a pad) and along the fingers' faces only where
// it comes at them. A box held from the side (approach x, closing y, faces
// z), the receiver's hand 7 cm below the TCP: lifted, it is followed up (it
// rose into the fingers above it, outsider e_41); the same hand pulled along
// x, through the fingertips' way, or away along the faces is not chased (at
// 0.8 m/s the arm ran past its speed limits after it, outsider r_29).
TEST(ReleaseRide, TheHandThatTakesTheObjectIsFollowedOnlyWhereItComesAtTheGripper) {
  HeldBox box(Vector3(0.065, 0.04, 0.105), 0.04);
  HandoverContext& ctx = box.ctx;
  ctx.in.tcp_pose.linear().col(0) = Vector3(0.0, 0.0, 1.0);  // the faces' direction: up
  ctx.in.tcp_pose.linear().col(1) = Vector3(0.0, 1.0, 0.0);  // closing axis
  ctx.in.tcp_pose.linear().col(2) = ctx.in.tcp_pose.linear().col(0).cross(ctx.in.tcp_pose.linear().col(1));
  ctx.in.object.valid = false;  // the robot's own estimate while it carries it: not the leaving body
  const Vector3 hand0(0.0, 0.0, -0.07);
  const double clear = box.clear();
  auto followed = [&](const Vector3& moved, const Vector3& v, Vector3& velocity) {
    ctx.in.hand.pose.translation() = hand0;
    ReleaseRide ride;
    ride.start(ctx);
    ctx.in.hand.pose.translation() = hand0 + moved;
    ctx.in.hand.velocity.head<3>() = v;
    Vector3 offset;
    ride.follow(ctx.in, offset, velocity);
    return offset;
  };
  Vector3 velocity;
  // lifted 3 cm at 0.3 m/s: up toward the fingers, followed all the way, its rate fed forward
  Vector3 offset = followed(Vector3(0.0, 0.0, 0.03), Vector3(0.0, 0.0, 0.3), velocity);
  EXPECT_NEAR(offset.z(), 0.03, 1e-12);
  EXPECT_NEAR(velocity.z(), 0.3, 1e-12);
  // lowered (away from the fingers along their faces): not chased
  offset = followed(Vector3(0.0, 0.0, -0.03), Vector3(0.0, 0.0, -0.3), velocity);
  EXPECT_LT(offset.norm(), 1e-12);
  EXPECT_LT(velocity.norm(), 1e-12);
  // along the closing axis: followed (the object it holds would strike a pad), as far as clear
  offset = followed(Vector3(0.0, 0.02, 0.0), Vector3(0.0, 0.4, 0.0), velocity);
  EXPECT_NEAR(offset.y(), 0.02, 1e-12);
  EXPECT_NEAR(velocity.y(), 0.4, 1e-12);
  offset = followed(Vector3(0.0, 0.3, 0.0), Vector3(0.0, 0.4, 0.0), velocity);
  EXPECT_NEAR(offset.y(), clear, 1e-12);
  // the hand beside the gripper along the closing axis, moving along the faces: the faces
  // do not point at it (cosine 0), nothing is chased
  ctx.in.tcp_pose.translation() = Vector3(0.0, -0.07, -0.07);  // the hand 7 cm off along the closing axis
  offset = followed(Vector3(0.0, 0.0, 0.03), Vector3(0.0, 0.0, 0.3), velocity);
  EXPECT_LT(offset.norm(), 1e-12);
}

}  // namespace release_ride_test
}  // namespace handover::fsm
