// The grasp funnel (fsm/handover/grasp_funnel.hpp): the fit of the object
// between the open fingers and the standoff it allows, on hand-computed
// geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "fsm/handover/grasp_funnel.hpp"

namespace handover::fsm {
namespace {

constexpr double kOpening = 0.08;
constexpr double kSpan = 0.012;

io::ObjectShape cylinder(double radius, double height) {
  io::ObjectShape s;
  s.kind = io::ObjectShape::Kind::kCylinder;
  s.size = Vector3(radius, height, 0.0);
  return s;
}

io::ObjectShape box(double x, double y, double z) {
  io::ObjectShape s;
  s.kind = io::ObjectShape::Kind::kBox;
  s.size = Vector3(x, y, z);
  return s;
}

/// A side grasp on an upright object at `object`: approach along world x,
/// fingers closing along world y.
Isometry sideGrasp(const Vector3& at) {
  Isometry g = Isometry::Identity();
  g.linear() << 0, 0, 1,  //
      0, 1, 0,            //
      -1, 0, 0;           // columns: x = -z_w, y = y_w, z = x_w
  g.translation() = at;
  return g;
}

Isometry at(const Vector3& p) { return Isometry(Eigen::Translation3d(p)); }

TEST(GraspFunnel, UnknownShapeSlidesStraightIn) {
  const Isometry grasp = sideGrasp(Vector3(0.5, 0.0, 0.3));
  const FingerFit f = fingerFit(grasp, at(grasp.translation()), grasp, io::ObjectShape{}, kOpening, kSpan);
  EXPECT_GT(f.fit, 1.0);
  EXPECT_EQ(funnelStandoff(f, 0.08, 0.5), 0.0);
}

TEST(GraspFunnel, AlignedObjectFitsWithItsWholeClearance) {
  const Vector3 p(0.5, 0.0, 0.3);
  const FingerFit f = fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_NEAR(f.clearance, 0.01, 1e-12);  // (0.08 - 0.06) / 2
  EXPECT_NEAR(f.fit, 0.01, 1e-12);
  EXPECT_EQ(funnelStandoff(f, 0.08, 0.5), 0.0);
}

TEST(GraspFunnel, LateralErrorBeyondTheClearanceHoldsTheGripperBack) {
  const Vector3 p(0.5, 0.0, 0.3);
  // the TCP 12 mm to the side along the closing axis: a finger lands on the object
  const Isometry tcp = sideGrasp(p + Vector3(0.0, 0.012, 0.0));
  const FingerFit f = fingerFit(tcp, at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_NEAR(f.fit, -0.002, 1e-12);
  EXPECT_EQ(funnelStandoff(f, 0.08, 0.5), 0.08);
}

TEST(GraspFunnel, StandoffShrinksLinearlyAsTheFitGrows) {
  const Vector3 p(0.5, 0.0, 0.3);
  // 7.5 mm to the side: fit 2.5 mm, half of the 5 mm margin (0.5 of 10 mm)
  const Isometry tcp = sideGrasp(p + Vector3(0.0, -0.0075, 0.0));
  const FingerFit f = fingerFit(tcp, at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_NEAR(f.fit, 0.0025, 1e-12);
  EXPECT_NEAR(funnelStandoff(f, 0.08, 0.5), 0.04, 1e-12);
  // an offset along the approach axis or across the fingers does not matter
  const Isometry tcp2 = sideGrasp(p + Vector3(-0.05, -0.0075, 0.004));
  EXPECT_NEAR(fingerFit(tcp2, at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan).fit, 0.0025, 1e-12);
  // margin 0: in as soon as it fits at all
  EXPECT_EQ(funnelStandoff(f, 0.08, 0.0), 0.0);
}

TEST(GraspFunnel, TurnAcrossTheClosingAxisWidensByTheFingerSpan) {
  const Vector3 p(0.5, 0.0, 0.3);
  const double turn = 0.1;  // rad
  for (const Vector3& axis : {Vector3(Vector3::UnitX()), Vector3(Vector3::UnitZ())}) {  // TCP frame: across and along the fingers
    Isometry tcp = sideGrasp(p);
    tcp.linear() = tcp.linear() * Eigen::AngleAxisd(turn, axis).toRotationMatrix();
    const FingerFit f = fingerFit(tcp, at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
    EXPECT_NEAR(f.fit, 0.01 - kSpan * turn, 1e-12) << axis.transpose();
  }
  // a turn about the closing axis keeps the object's slab where it was
  Isometry tcp = sideGrasp(p);
  tcp.linear() = tcp.linear() * Eigen::AngleAxisd(turn, Vector3::UnitY()).toRotationMatrix();
  EXPECT_NEAR(fingerFit(tcp, at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan).fit, 0.01, 1e-12);
}

TEST(GraspFunnel, ClearanceComesFromTheWidthAcrossTheGraspsFingers) {
  const Vector3 p(0.5, 0.0, 0.3);
  // a 9 x 6 cm box: fingers across its 6 cm side leave 1 cm, across the 9 cm side nothing fits
  Isometry obj = at(p);
  EXPECT_NEAR(fingerFit(sideGrasp(p), obj, sideGrasp(p), box(0.09, 0.06, 0.2), kOpening, kSpan).clearance, 0.01,
              1e-12);
  obj.linear() = Eigen::AngleAxisd(M_PI / 2.0, Vector3::UnitZ()).toRotationMatrix();
  const FingerFit f = fingerFit(sideGrasp(p), obj, sideGrasp(p), box(0.09, 0.06, 0.2), kOpening, kSpan);
  EXPECT_NEAR(f.clearance, 0.001, 1e-12);  // the floor: (0.08 - 0.09) / 2 < 0
  EXPECT_NEAR(f.fit, 0.001, 1e-12);
}

TEST(GraspFunnel, GraspOffTheMidPlaneCountsTheObjectsOwnOffset) {
  const Vector3 p(0.5, 0.0, 0.3);
  // the grasp 5 mm off the cylinder's axis along the closing direction: the
  // object sits 5 mm off the fingers' mid-plane with the TCP right on the grasp
  const Isometry grasp = sideGrasp(p + Vector3(0.0, 0.005, 0.0));
  const FingerFit f = fingerFit(grasp, at(p), grasp, cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_NEAR(f.fit, 0.005, 1e-12);
}

/// The shipped funnel's mouth and speed, fed forward; `acceleration` 0: first order.
GraspFunnel slideFunnel(double acceleration) {
  GraspFunnel f;
  f.max_standoff = 0.08;
  f.speed = 0.4;
  f.acceleration = acceleration;
  f.feed_forward = true;
  f.restart(0.0);
  return f;
}

// The funnel over time with an acceleration limit: a smooth slide within its
// speed and acceleration, braking in time, ending at the goal at rest; what it
// reports is what it does (the rate is the standoff's derivative).
TEST(GraspFunnelSlide, ReachesTheGoalWithinItsSpeedAndAccelerationAndStopsThere) {
  GraspFunnel f = slideFunnel(4.0);
  const double dt = 0.001;
  GraspFunnel::Slide s{0.08, 0.0, 0.0};
  double t = 0.0, fastest = 0.0, arrived = -1.0;
  for (int k = 1; k <= 1000; ++k) {
    t = k * dt;
    const GraspFunnel::Slide next = f.step(s.standoff, s.rate, 0.0, t);
    EXPECT_LE(std::abs(next.rate), f.speed + 1e-12);
    EXPECT_LE(std::abs(next.acceleration), f.acceleration + 1e-9);
    EXPECT_GE(next.standoff, 0.0);                    // never past the goal
    EXPECT_LE(next.standoff, s.standoff + 1e-15);     // only in
    EXPECT_NEAR(next.standoff - s.standoff, next.rate * dt, 1e-9);
    fastest = std::max(fastest, std::abs(next.rate));
    s = next;
    if (arrived < 0.0 && s.standoff == 0.0) arrived = t;
  }
  EXPECT_EQ(s.standoff, 0.0);
  EXPECT_EQ(s.rate, 0.0);
  EXPECT_EQ(s.acceleration, 0.0);  // at rest: nothing left to feed forward
  EXPECT_NEAR(fastest, f.speed, 1e-9);
  // the time-optimal profile: 0.1 s up to speed (2 cm), 4 cm at speed, 0.1 s down
  EXPECT_NEAR(arrived, 0.3, 0.01);
}

TEST(GraspFunnelSlide, BacksOffSmoothlyWhenTheGoalMovesOut) {
  GraspFunnel f = slideFunnel(4.0);
  // sliding in at full speed when the fit is lost: the rate turns around at the acceleration limit
  GraspFunnel::Slide s{0.04, -0.4, 0.0};
  double lowest = s.standoff;
  for (int k = 1; k <= 500; ++k) {
    const GraspFunnel::Slide next = f.step(s.standoff, s.rate, 0.08, k * 0.001);
    EXPECT_LE(std::abs(next.rate - s.rate), 4.0 * 0.001 + 1e-12);
    s = next;
    lowest = std::min(lowest, s.standoff);
  }
  EXPECT_NEAR(lowest, 0.04 - 0.4 * 0.4 / (2.0 * 4.0), 1e-3);  // its braking distance further in
  EXPECT_EQ(s.standoff, 0.08);
  EXPECT_EQ(s.rate, 0.0);
}

TEST(GraspFunnelSlide, WithoutAnAccelerationLimitMovesAtItsSpeed) {
  GraspFunnel f = slideFunnel(0.0);
  const GraspFunnel::Slide s = f.step(0.08, 0.0, 0.0, 0.01);
  EXPECT_NEAR(s.standoff, 0.076, 1e-12);
  EXPECT_NEAR(s.rate, -0.4, 1e-9);
  EXPECT_EQ(f.step(0.001, 0.0, 0.0, 0.02).standoff, 0.0);
  // not fed forward: the same standoff, no rate to feed
  f.feed_forward = false;
  f.restart(0.0);
  const GraspFunnel::Slide set_point = f.step(0.08, 0.0, 0.0, 0.01);
  EXPECT_EQ(set_point.standoff, s.standoff);
  EXPECT_EQ(set_point.rate, 0.0);
}


/// The fit of a 6 cm cylinder aligned at a side grasp at `p` (1 cm to spare each side), budgeted
/// for its `velocity` and the TCP's over `horizon` (s) with 2-sigma noise of `speed_std`.
FingerFit movingFit(const Vector3& velocity, const Vector3& tcp_velocity = Vector3::Zero(), double speed_std = 0.0,
                    double horizon = 0.1) {
  const Vector3 p(0.5, 0.0, 0.3);
  const Isometry grasp = sideGrasp(p);  // closing along world y, approach along world x
  FingerFit f = fingerFit(grasp, at(p), grasp, cylinder(0.03, 0.2), kOpening, kSpan);
  budgetMotion(f, grasp, velocity, tcp_velocity, speed_std, horizon, 2.0);
  return f;
}

// An object that moves is met `horizon` late: across the
// fingers its way costs the fit, toward the palm it is the lead the standoff
// keeps, and noise within the speed's significance counts as nothing.
TEST(GraspFunnel, AnObjectThatMovesAcrossTheFingersLosesTheFitItCoversWithinTheHorizon) {
  const Vector3 p(0.5, 0.0, 0.3);
  const Isometry grasp = sideGrasp(p);  // closing along world y, approach along world x
  FingerFit f = fingerFit(grasp, at(p), grasp, cylinder(0.03, 0.2), kOpening, kSpan);
  ASSERT_NEAR(f.fit, 0.01, 1e-12);
  budgetMotion(f, grasp, Vector3(0.0, 0.3, 0.0), Vector3::Zero(), 0.0, 0.1, 2.0);
  EXPECT_NEAR(f.fit, 0.01 - 0.03, 1e-12);  // 0.3 m/s x 0.1 s across: a finger would land on it
  EXPECT_EQ(f.lead, 0.0);
  EXPECT_EQ(f.closing_speed, 0.0);
  EXPECT_NEAR(funnelStandoff(f, 0.08, 0.5), 0.08, 1e-12);  // held back at the mouth
  // where it will be, not how fast: 5 mm toward +y and moving back toward the middle, it fits better
  const Isometry off = sideGrasp(p - Vector3(0.0, 0.005, 0.0));  // the TCP 5 mm toward -y
  FingerFit back = fingerFit(off, at(p), grasp, cylinder(0.03, 0.2), kOpening, kSpan);
  ASSERT_NEAR(back.fit, 0.005, 1e-12);
  budgetMotion(back, grasp, Vector3(0.0, -0.05, 0.0), Vector3::Zero(), 0.0, 0.1, 2.0);
  EXPECT_NEAR(back.fit, 0.01, 1e-12);
  EXPECT_NEAR(back.mid_plane, 0.0, 1e-12);
  // the TCP's own motion does not enter: it is where it is, the object is known late
  FingerFit same = movingFit(Vector3(0.0, 0.3, 0.0), Vector3(0.0, 0.3, 0.0));
  EXPECT_NEAR(same.fit, 0.01 - 0.03, 1e-12);
  // the same speed along the fingers' width (world z) does not cost the fit
  FingerFit g = movingFit(Vector3(0.0, 0.0, 0.3));
  EXPECT_NEAR(g.fit, 0.01, 1e-12);
}

TEST(GraspFunnel, AnObjectComingAtThePalmIsKeptInFrontByItsWayWithinTheHorizon) {
  // toward the palm is against the approach axis (world -x here) at 0.6 m/s
  FingerFit f = movingFit(Vector3(-0.6, 0.0, 0.0));
  EXPECT_NEAR(f.closing_speed, 0.6, 1e-12);
  EXPECT_NEAR(f.lead, 0.06, 1e-12);
  EXPECT_NEAR(f.fit, 0.01, 1e-12);                         // along the axis: the fit stays
  EXPECT_NEAR(funnelStandoff(f, 0.08, 0.5), 0.06, 1e-12);  // fits, yet not slid onto it
  // leaving (away from the palm): nothing to keep
  FingerFit g = movingFit(Vector3(0.6, 0.0, 0.0));
  EXPECT_EQ(g.lead, 0.0);
  EXPECT_EQ(g.closing_speed, 0.0);
}

TEST(GraspFunnel, TheArmsOwnWayInCountsOnlyWhileTheObjectComesAtThePalm) {
  // the TCP sliding in at 0.25 m/s onto an object at rest: its set slide, no lead
  FingerFit f = movingFit(Vector3::Zero(), Vector3(0.25, 0.0, 0.0));
  EXPECT_EQ(f.lead, 0.0);
  EXPECT_EQ(f.closing_speed, 0.0);
  // the object coming at 0.6 m/s while the arm is on its way in at 0.4: the gap closes at 1.0
  FingerFit g = movingFit(Vector3(-0.6, 0.0, 0.0), Vector3(0.4, 0.0, 0.0));
  EXPECT_NEAR(g.closing_speed, 1.0, 1e-12);
  EXPECT_NEAR(g.lead, 0.1, 1e-12);
  // an arm that already backs away with it takes its way off; faster than the object, nothing is left
  FingerFit h = movingFit(Vector3(-0.6, 0.0, 0.0), Vector3(-0.4, 0.0, 0.0));
  EXPECT_NEAR(h.closing_speed, 0.2, 1e-12);
  FingerFit k = movingFit(Vector3(-0.4, 0.0, 0.0), Vector3(-0.5, 0.0, 0.0));
  EXPECT_EQ(k.closing_speed, 0.0);
  EXPECT_EQ(k.lead, 0.0);
}

TEST(GraspFunnel, ASpeedWithinItsNoiseIsNoMotion) {
  const Vector3 p(0.5, 0.0, 0.3);
  const Isometry grasp = sideGrasp(p);
  // 0.15 m/s across and toward with a speed std of 0.1: within 2 sigma, nothing
  FingerFit f = movingFit(Vector3(-0.15, 0.15, 0.0), Vector3::Zero(), 0.1);
  EXPECT_NEAR(f.fit, 0.01, 1e-12);
  EXPECT_EQ(f.lead, 0.0);
  // beyond it, only what is beyond counts: (0.3 - 0.2) x 0.1 s
  budgetMotion(f, grasp, Vector3(-0.3, 0.3, 0.0), Vector3::Zero(), 0.1, 0.1, 2.0);
  EXPECT_NEAR(f.fit, 0.01 - 0.01, 1e-12);
  EXPECT_NEAR(f.lead, 0.01, 1e-12);
  // no horizon, or an object of unknown shape: untouched
  FingerFit g = movingFit(Vector3(-0.6, 0.6, 0.0), Vector3::Zero(), 0.0, 0.0);
  EXPECT_NEAR(g.fit, 0.01, 1e-12);
  EXPECT_EQ(g.lead, 0.0);
  FingerFit u = fingerFit(grasp, at(p), grasp, io::ObjectShape{}, kOpening, kSpan);
  budgetMotion(u, grasp, Vector3(-0.6, 0.6, 0.0), Vector3::Zero(), 0.0, 0.1, 2.0);
  EXPECT_GT(u.fit, 1.0);
  EXPECT_EQ(u.lead, 0.0);
}

// While the object is still brought in the funnel waits at its line-up: the
// whole standoff, farther only where an object coming at the palm needs the
// fingertips mouth_clearance plus its lead in front of the near face.
TEST(GraspFunnel, TheLineUpKeepsAnObjectComingAtThePalmItsLeadInFrontOfItsFace) {
  GraspFunnel g;
  g.max_standoff = 0.08;
  g.mouth_clearance = 0.02;
  FingerFit f;
  f.clearance = 0.01;
  f.near_face = 0.03;  // the fingertips (pad_reach 0.01) clear of the face from 0.03 + 0.01 + 0.02 = 0.06
  EXPECT_EQ(g.lineUp(f, 0.01), 0.08);  // at rest: the whole standoff
  f.lead = 0.01;
  EXPECT_EQ(g.lineUp(f, 0.01), 0.08);  // 0.07 needed: within the line-up's own room
  f.lead = 0.05;
  EXPECT_NEAR(g.lineUp(f, 0.01), 0.11, 1e-12);  // 0.06 + 0.05 farther than the line-up
  EXPECT_NEAR(g.mouth(f, 0.01), 0.06, 1e-12);  // the mouth is the object's, whatever the lead
  // an unknown shape: the whole standoff and the lead on top
  FingerFit unknown;
  unknown.lead = 0.05;
  EXPECT_NEAR(g.lineUp(unknown, 0.01), 0.13, 1e-12);
}

TEST(GraspFunnelSlide, BacksOutFasterByTheSpeedOfAnObjectComingAtThePalm) {
  GraspFunnel f = slideFunnel(0.0);  // 0.4 m/s
  const GraspFunnel::Slide out = f.step(0.02, 0.0, 0.08, 0.01, 0.6);
  EXPECT_NEAR(out.standoff, 0.03, 1e-12);  // (0.4 + 0.6) m/s for 10 ms
  // sliding in keeps its own speed whatever the object does
  f.restart(0.0);
  const GraspFunnel::Slide in = f.step(0.08, 0.0, 0.0, 0.01, 0.6);
  EXPECT_NEAR(in.standoff, 0.076, 1e-12);
  // and with an acceleration limit the cap is raised the same way
  GraspFunnel smooth = slideFunnel(100.0);
  GraspFunnel::Slide s{0.0, 0.0, 0.0};
  for (int k = 1; k <= 300; ++k) s = smooth.step(s.standoff, s.rate, 0.5, k * 0.001, 0.6);
  EXPECT_GT(s.rate, 0.4 + 0.5);
  EXPECT_LE(s.rate, 1.0 + 1e-9);
}

// How much of the object lies behind the grasp point toward the gripper, from
// the shape: the depth the pads can close on.
TEST(GraspFunnel, TheObjectBehindTheGraspPointIsMeasuredAlongTheApproachAxis) {
  const Vector3 p(0.5, 0.0, 0.3);
  // a side grasp through a bottle's axis: its radius lies toward the gripper
  EXPECT_NEAR(fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan).near_face, 0.03, 1e-9);
  // a phone lying flat taken from above across its width: half its 8 mm
  Isometry top = Isometry::Identity();
  top.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();  // approach down, z_w
  top.translation() = p;
  const io::ObjectShape phone = box(0.15, 0.072, 0.008);
  EXPECT_NEAR(fingerFit(top, at(p), top, phone, kOpening, kSpan).near_face, 0.004, 1e-9);
  // the same grasp 5 cm along the phone: still its half thickness
  top.translation() = p + Vector3(-0.05, 0, 0);
  EXPECT_NEAR(fingerFit(top, at(p), top, phone, kOpening, kSpan).near_face, 0.004, 1e-9);
  // a ball grasped from the side 1 cm off its centre across the fingers: the chord's half
  const io::ObjectShape ball{io::ObjectShape::Kind::kSphere, Vector3(0.03, 0, 0)};
  const Isometry off = sideGrasp(p + Vector3(0, 0.01, 0));
  EXPECT_NEAR(fingerFit(off, at(p), off, ball, kOpening, kSpan).near_face, std::sqrt(0.03 * 0.03 - 0.01 * 0.01), 1e-9);
}

TEST(GraspFunnel, ThePadsMustReachIntoAThinObjectBeforeTheFingersClose) {
  const Vector3 p(0.5, 0.0, 0.3);
  Isometry top = Isometry::Identity();
  top.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  top.translation() = p;
  const FingerFit phone = fingerFit(top, at(p), top, box(0.15, 0.072, 0.008), kOpening, kSpan);
  ASSERT_GT(phone.fit, 0.0);  // it fits across the fingers
  constexpr double kReach = 0.0095, kDepth = 0.006;
  // 1.4 cm short (the TCP above it): the pad tips end above its top (-0.5 mm into it)
  EXPECT_NEAR(padDepth(phone, -0.014, kReach), -0.0005, 1e-9);
  EXPECT_FALSE(deepEnough(phone, -0.014, kReach, kDepth));
  EXPECT_TRUE(deepEnough(phone, -0.007, kReach, kDepth));  // 6.5 mm into it
  EXPECT_TRUE(deepEnough(phone, 0.0, kReach, kDepth));
  // a bottle from the side: 2 cm short still closes on 3.95 cm of it
  const FingerFit bottle = fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_TRUE(deepEnough(bottle, -0.02, kReach, kDepth));
  // a grasp declared at the object's surface asks half of what it gives (4.75 mm)
  Isometry surface = top;
  surface.translation() = p + Vector3(0, 0, 0.004);
  const FingerFit flat = fingerFit(surface, at(p), surface, box(0.15, 0.072, 0.008), kOpening, kSpan);
  EXPECT_NEAR(flat.near_face, 0.0, 1e-9);
  EXPECT_TRUE(deepEnough(flat, -0.004, kReach, kDepth));
  EXPECT_FALSE(deepEnough(flat, -0.006, kReach, kDepth));
  // an unknown shape tells nothing: never held back
  EXPECT_TRUE(deepEnough(fingerFit(top, at(p), top, io::ObjectShape{}, kOpening, kSpan), -0.05, kReach, kDepth));
}

io::ObjectShape sphere(double radius) {
  io::ObjectShape s;
  s.kind = io::ObjectShape::Kind::kSphere;
  s.size = Vector3(radius, 0.0, 0.0);
  return s;
}

// Where the pads' squeeze holds: a flat face at once, a round section only
// from r (1 - mu / sqrt(1 + mu^2)) deep (the side's slope there is mu).
TEST(GraspFunnel, ARoundSideHoldsOnlyFromTheDepthWhereItsSlopeIsTheFriction) {
  constexpr double kStep = 5e-4;  // the scan's resolution
  for (double mu : {0.5, 1.0}) {
    const double round = 1.0 - mu / std::sqrt(1.0 + mu * mu);
    // a tube lying across the fingers (grasp on its axis, approach across it): the "around_axis" grasp
    Isometry across = Isometry::Identity();
    across.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
    EXPECT_NEAR(holdDepth(cylinder(0.023, 0.27), across, mu), 0.023 * round, 2 * kStep) << mu;
    EXPECT_NEAR(holdDepth(sphere(0.04), Isometry::Identity(), mu), 0.04 * round, 2 * kStep) << mu;
    // the same tube upright, from above (down its axis): the pads slide along its side
    Isometry top = Isometry::Identity();
    top.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
    EXPECT_LE(holdDepth(cylinder(0.023, 0.27), top, mu), 2 * kStep) << mu;
    // a box face on
    EXPECT_LE(holdDepth(box(0.06, 0.05, 0.2), Isometry::Identity(), mu), 2 * kStep) << mu;
  }
  // a box across its edge (turned 45 degrees about the approach axis' normal): its sides slope 1:1,
  // steeper than mu = 0.5 all the way: only its far half holds
  Isometry edge = Isometry::Identity();
  edge.linear() = Eigen::AngleAxisd(M_PI / 4, Vector3::UnitX()).toRotationMatrix();
  const double diagonal = 0.05 * std::sqrt(2.0);
  EXPECT_NEAR(holdDepth(box(0.2, 0.05, 0.05), edge, 0.5), 0.5 * diagonal, 2 * kStep);
  EXPECT_DOUBLE_EQ(holdDepth(io::ObjectShape{}, Isometry::Identity(), 0.5), 0.0);
  EXPECT_DOUBLE_EQ(holdDepth(sphere(0.04), Isometry::Identity(), 0.0), 0.0);
}

// The width the fingers closed to locates them on the object's section: a bottle of radius
// 33 mm lying across them, pinched 5.0 cm wide (s_21: 3 cm short of its axis), is held 1.15 cm
// into it, short of its hold depth; closed to its diameter they hold it at its axis.
TEST(GraspFunnel, TheWidthTheFingersClosedToTellsHowDeepTheyHoldARoundSide) {
  constexpr double kStep = 5e-4, r = 0.033;
  Isometry across = Isometry::Identity();
  across.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  const io::ObjectShape bottle = cylinder(r, 0.22);
  for (double w : {0.01, 0.03, 0.05, 0.06}) {
    const double expected = r - std::sqrt(r * r - 0.25 * w * w);
    EXPECT_NEAR(depthOfWidth(bottle, across, w), expected, 2 * kStep) << w;
  }
  EXPECT_LT(depthOfWidth(bottle, across, 0.050), holdDepth(bottle, across, 0.5));
  EXPECT_GT(depthOfWidth(bottle, across, 0.065), holdDepth(bottle, across, 0.5));
  EXPECT_NEAR(depthOfWidth(bottle, across, 2 * r - 1e-6), r, 2 * kStep);
  // wider than it is anywhere up to the grasp point (fingers on something else): unknown
  EXPECT_LT(depthOfWidth(bottle, across, 2 * r + 0.002), 0.0);
  // a box face on is as wide as it is from its face on
  EXPECT_LE(depthOfWidth(box(0.06, 0.05, 0.2), Isometry::Identity(), 0.05), 2 * kStep);
  EXPECT_LT(depthOfWidth(io::ObjectShape{}, across, 0.05), 0.0);
}

// The 1 ms step scans once per grasp: a grasp that stays (within noise) reads the last scan,
// one that moves (a new choice, a touch's correction) or another shape is scanned again.
TEST(GraspFunnel, TheHoldDepthIsScannedAgainOnlyForAnotherGrasp) {
  HoldDepthCache cache;
  Isometry across = Isometry::Identity();
  across.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  const io::ObjectShape tube = cylinder(0.023, 0.27);
  const double d = cache.get(tube, across, 0.5);
  EXPECT_DOUBLE_EQ(d, holdDepth(tube, across, 0.5));
  Isometry jitter = across;
  jitter.translation() += Vector3(0.0, 0.0, 0.0005);  // noise: the last scan stands
  EXPECT_DOUBLE_EQ(cache.get(tube, jitter, 0.5), d);
  Isometry turned = across;
  turned.rotate(Eigen::AngleAxisd(M_PI / 2, Vector3::UnitZ()));  // fingers across its length now: flat
  EXPECT_DOUBLE_EQ(cache.get(tube, turned, 0.5), holdDepth(tube, turned, 0.5));
  EXPECT_LT(cache.get(tube, turned, 0.5), 0.5 * d);
  EXPECT_DOUBLE_EQ(cache.get(box(0.05, 0.05, 0.2), across, 0.5), holdDepth(box(0.05, 0.05, 0.2), across, 0.5));
  EXPECT_DOUBLE_EQ(cache.get(tube, across, 1.0), holdDepth(tube, across, 1.0));
}

// The close waits until the pads reach that depth now: the tube of radius 23 mm, the fingers
// met 12 mm short of its axis (a 39 mm chord) and it squeezed out in the retract (g547_00075).
TEST(GraspFunnel, TheFingersCloseOnARoundObjectOnlyWhereTheyHoldIt) {
  const Vector3 p(0.5, 0.0, 0.3);
  constexpr double kReach = 0.0095, kMu = 0.5;
  FingerFit tube = fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.023, 0.27), kOpening, kSpan);
  tube.hold_depth = holdDepth(cylinder(0.023, 0.27), at(p).inverse() * sideGrasp(p), kMu);
  // the bottle stands: from the side its section across the fingers is a disc
  EXPECT_NEAR(tube.hold_depth, 0.023 * (1.0 - kMu / std::sqrt(1.0 + kMu * kMu)), 1e-3);
  const double short_by = 0.023 + kReach - tube.hold_depth;  // how far short the pads just hold
  EXPECT_TRUE(holdsWhenClosed(tube, -short_by + 1e-3, kReach));
  EXPECT_FALSE(holdsWhenClosed(tube, -short_by - 1e-3, kReach));
  EXPECT_FALSE(holdsWhenClosed(tube, -0.029, kReach));  // where g547_00075 closed, from the object as it really was
  // a box holds wherever the pads touch it; without the friction asked for, nothing is held back
  FingerFit flat = fingerFit(sideGrasp(p), at(p), sideGrasp(p), box(0.05, 0.05, 0.2), kOpening, kSpan);
  flat.hold_depth = holdDepth(box(0.05, 0.05, 0.2), at(p).inverse() * sideGrasp(p), kMu);
  EXPECT_TRUE(holdsWhenClosed(flat, -0.03, kReach));
  EXPECT_TRUE(holdsWhenClosed(fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.023, 0.27), kOpening, kSpan),
                              -0.03, kReach));
}

// The funnel's mouth: the fingertips wait just in front of the object, not a
// fixed distance back (a longer slide buys nothing once they are in front of it).
TEST(GraspFunnel, TheMouthPutsTheFingertipsJustInFrontOfTheObject) {
  const Vector3 p(0.5, 0.0, 0.3);
  constexpr double kReach = 0.0095;
  GraspFunnel funnel;
  funnel.max_standoff = 0.08;
  const FingerFit bottle = fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.03, 0.2), kOpening, kSpan);
  EXPECT_EQ(funnel.mouth(bottle, kReach), 0.08);  // no mouth_clearance: the fixed mouth
  funnel.mouth_clearance = 0.02;
  // a bottle from the side: its radius, the pads' reach and the clearance
  EXPECT_NEAR(funnel.mouth(bottle, kReach), 0.03 + kReach + 0.02, 1e-9);
  // a deep grasp never waits farther back than max_standoff
  const FingerFit barrel = fingerFit(sideGrasp(p), at(p), sideGrasp(p), cylinder(0.07, 0.3), kOpening, kSpan);
  EXPECT_EQ(funnel.mouth(barrel, kReach), 0.08);
  // an unknown shape, or a grasp frame outside the object: the whole standoff
  EXPECT_EQ(funnel.mouth(fingerFit(sideGrasp(p), at(p), sideGrasp(p), io::ObjectShape{}, kOpening, kSpan), kReach),
            0.08);
  const Isometry outside = sideGrasp(p + Vector3(-0.05, 0, 0));
  EXPECT_EQ(funnel.mouth(fingerFit(outside, at(p), outside, cylinder(0.03, 0.2), kOpening, kSpan), kReach), 0.08);
  // the funnel's standoff at that mouth: all of it while the object does not fit
  FingerFit off = bottle;
  off.fit = -0.01;
  EXPECT_NEAR(funnelStandoff(off, funnel.mouth(bottle, kReach), 0.5), 0.0595, 1e-9);
}

}  // namespace
}  // namespace handover::fsm
