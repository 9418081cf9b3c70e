// Where a held object may sit in the receiver's hand
// (control/grasp/presentation_seats.hpp): a ball held from the side cannot sit
// on the palm at the declared seat (the gripper's body would), so its seats
// move it; a bottle held from the top keeps the declared seat and adds a
// lower one; every seat has the grip point at the object and the gripper
// clear of the hand.
#include <gtest/gtest.h>

#include <random>

#include "control/grasp/presentation_seats.hpp"
#include "panda_fixture.hpp"

namespace handover::control::grasp {
namespace {

using testing::panda;

SeatGeometry geometry(io::ObjectShape::Kind kind, const Vector3& size, const Isometry& tcp_in_object) {
  SeatGeometry g;
  g.object.kind = kind;
  g.object.size = size;
  g.object_in_hand.translation() = Vector3(0.0, 0.0, 0.05);
  g.tcp_in_object = tcp_in_object;
  g.gripper_in_tcp = gripperCapsulesIn(panda(), "tcp");
  g.hand_box_size = Vector3(0.09, 0.08, 0.03);
  return g;
}

/// The smallest gripper-capsule to hand-box clearance with the object at `seat`.
double gripperClearance(const SeatGeometry& g, const Isometry& seat) {
  double d = 1e9;
  const Isometry tcp = seat * g.tcp_in_object;
  for (const ObstacleCapsule& c : g.gripper_in_tcp) {
    d = std::min(d, segmentBoxDistance(tcp * c.a, tcp * c.b, g.hand_box_in_hand, g.hand_box_size) - c.radius);
  }
  return d;
}

void expectInHandAndClear(const SeatGeometry& g, const SeatOptions& o, const Isometry& seat) {
  EXPECT_LE(io::signedDistance(g.object, seat.inverse() * Vector3::Zero()), o.reach + 1e-12);
  EXPECT_GE(gripperClearance(g, seat), o.clearance - 1e-9);
  EXPECT_TRUE(seat.linear().isApprox(g.object_in_hand.linear(), 1e-12));
}

TEST(PresentationSeats, GripperCapsulesAreTheHandsInTheTcpFrame) {
  const std::vector<ObstacleCapsule> caps = gripperCapsulesIn(panda(), "tcp");
  ASSERT_EQ(caps.size(), 2u);  // hand_a (the body) and hand_b (around the fingers)
  // the fingers' capsule runs across the TCP, the body's behind it (facts: hand b at the TCP, hand a 6 cm back)
  double nearest = 1e9;
  for (const auto& c : caps) nearest = std::min(nearest, (0.5 * (c.a + c.b)).norm());
  EXPECT_LT(nearest, 0.01);
}

TEST(PresentationSeats, SegmentBoxDistanceMatchesSampling) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  Isometry box = Isometry::Identity();
  box.linear() = Eigen::AngleAxisd(0.4, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  box.translation() = Vector3(0.01, -0.02, 0.03);
  const Vector3 size(0.09, 0.08, 0.03);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    double sampled = 1e9;
    for (int i = 0; i <= 2000; ++i) {
      const Vector3 p = box.inverse() * (a + (b - a) * (i / 2000.0));
      sampled = std::min(sampled, (p.cwiseAbs() - 0.5 * size).cwiseMax(0.0).norm());
    }
    const double d = segmentBoxDistance(a, b, box, size);
    EXPECT_LE(d, sampled + 1e-9);
    EXPECT_NEAR(d, sampled, 1e-3);
  }
}

TEST(PresentationSeats, ABallHeldFromTheSideMovesOffThePalm) {
  Isometry side = Isometry::Identity();
  side.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  const SeatGeometry g = geometry(io::ObjectShape::Kind::kSphere, Vector3(0.03, 0, 0), side);
  const SeatOptions o;
  ASSERT_LT(gripperClearance(g, g.object_in_hand), o.clearance);  // the declared seat: the gripper on the palm
  const std::vector<Isometry> seats = presentationSeats(g, o);
  ASSERT_FALSE(seats.empty());
  for (const Isometry& s : seats) expectInHandAndClear(g, o, s);
}

TEST(PresentationSeats, ABottleHeldFromTheTopKeepsTheDeclaredSeatAlone) {
  Isometry top = Isometry::Identity();
  top.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  top.translation() = Vector3(0.0, 0.0, 0.08);
  const SeatGeometry g = geometry(io::ObjectShape::Kind::kCylinder, Vector3(0.03, 0.22, 0), top);
  const SeatOptions o;
  const std::vector<Isometry> seats = presentationSeats(g, o);
  ASSERT_EQ(seats.size(), 1u);
  EXPECT_TRUE(seats[0].isApprox(g.object_in_hand, 1e-9));
  expectInHandAndClear(g, o, seats[0]);
}

TEST(PresentationSeats, NoneWhenNothingFits) {
  Isometry side = Isometry::Identity();
  side.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  SeatGeometry g = geometry(io::ObjectShape::Kind::kSphere, Vector3(0.03, 0, 0), side);
  g.hand_box_size = Vector3(0.5, 0.5, 0.5);  // a hand larger than the grid: the gripper never clears it
  SeatOptions o;
  o.range = 0.1;
  EXPECT_TRUE(presentationSeats(g, o).empty());
}

}  // namespace
}  // namespace handover::control::grasp

namespace handover::control::grasp {
namespace {
TEST(PresentationSeats, TheHandIsNeverAboveTheObjectsCentre) {
  Isometry top = Isometry::Identity();
  top.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  top.translation() = Vector3(0.0, 0.0, 0.035);
  const SeatGeometry g = geometry(io::ObjectShape::Kind::kBox, Vector3(0.07, 0.06, 0.15), top);
  for (const Isometry& s : presentationSeats(g, SeatOptions{})) EXPECT_GE(s.translation().z(), 0.0);
}
}  // namespace
}  // namespace handover::control::grasp
