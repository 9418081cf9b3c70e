// The way a large turn goes with a joint plan (planned_turn.hpp): the lift of
// the TCP's orientation along the joint path against a fine one, and the
// error's way, size and continuity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "control/model/algorithms.hpp"
#include "control/so3.hpp"
#include "control/tasks/planned_turn.hpp"
#include "tests/support/panda_model.hpp"

using namespace handover::control;
using handover::test::panda;

namespace {

Quaternion rotationAt(const Vector7& q) { return Quaternion(frameRotation(panda(), panda().frameId("tcp"), q)); }

Vector7 randomConfiguration(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector7 q;
  for (int i = 0; i < kArmDofs; ++i) q[i] = panda().q_min[i] + u(rng) * (panda().q_max[i] - panda().q_min[i]);
  return q;
}

Quaternion about(const Vector3& axis, double angle) { return Quaternion(Eigen::AngleAxisd(angle, axis.normalized())); }

}  // namespace

// Across the whole joint range (joints moving up to their full span at
// once), the coarse lift ends on the same sign as a lift in 4000 steps,
// whose steps are far too small to be ambiguous.
TEST(PlannedTurn, TheLiftAlongTheJointPathAgreesWithAFineOne) {
  std::mt19937 rng(3);
  const int tcp = panda().frameId("tcp");
  int opposite_signs = 0;  // lifts that end on -Q(q_plan): the test is not trivial
  for (int s = 0; s < 300; ++s) {
    const Vector7 q = randomConfiguration(rng), q_plan = randomConfiguration(rng);
    const Quaternion now = rotationAt(q);
    const Quaternion coarse = planOrientationAlongJointPath(panda(), tcp, q, now, q_plan);
    Quaternion fine = now;
    for (int k = 1; k <= 4000; ++k) {
      Quaternion next = rotationAt(q + (q_plan - q) * (k / 4000.0));
      if (next.dot(fine) < 0.0) next.coeffs() = -next.coeffs();
      fine = next;
    }
    ASSERT_GT(coarse.dot(fine), 1.0 - 1e-9) << "sample " << s;
    if (coarse.dot(rotationAt(q_plan)) < 0.0) ++opposite_signs;
  }
  EXPECT_GT(opposite_signs, 30);
}

// Wrist joint 7 alone: a turn of 4.8 rad about the tool axis is lifted to
// the quaternion of that turn, not of the 1.48 rad the other way.
TEST(PlannedTurn, AWristTurnPastHalfATurnLiftsToTheFarSign) {
  Vector7 q;
  q << 0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 2.3;
  Vector7 q_plan = q;
  q_plan[6] -= 4.8;
  const Quaternion now = rotationAt(q);
  const Quaternion plan = planOrientationAlongJointPath(panda(), panda().frameId("tcp"), q, now, q_plan);
  // joint 7 turns about the tool's z axis: plan = now * turn about local z by -4.8
  const Quaternion expected = now * about(Vector3::UnitZ(), -4.8);
  EXPECT_GT(plan.dot(expected), 1.0 - 1e-9);
  EXPECT_LT(plan.dot(now), 0.0);  // more than half a turn away: the far sign
}

// A target 2.4 rad about z from the TCP: short way when the plan lies on the
// short side, the long way (norm 2 pi - 2.4, the other direction) when the
// plan's lifted orientation lies on the long side.
TEST(PlannedTurn, TheErrorGoesTheWayThePlanLies) {
  const Quaternion now = about(Vector3(0.3, -0.2, 1.0), 0.7);
  const Quaternion target = about(Vector3::UnitZ(), -2.4) * now;  // R_now R_target^T = 2.4 about z
  const Vector3 shortest = orientationError(now.toRotationMatrix(), target.toRotationMatrix());
  ASSERT_NEAR(shortest.z(), 2.4, 1e-9);
  bool long_way = false;
  // a plan near the target reached the short way
  const Quaternion plan_short = about(Vector3(1.0, 0.0, 0.0), 0.1) * target;
  EXPECT_LT((plannedTurnError(now, target, plan_short, long_way) - shortest).norm(), 1e-9);
  EXPECT_FALSE(long_way);
  // the same plan orientation reached the long way round: the far sign
  const Quaternion plan_long(-plan_short.coeffs());
  const Vector3 far = plannedTurnError(now, target, plan_long, long_way);
  EXPECT_TRUE(long_way);
  EXPECT_NEAR(far.z(), -(2.0 * M_PI - 2.4), 1e-9);
  EXPECT_NEAR(far.head<2>().norm(), 0.0, 1e-9);
  // the target's sign does not matter, only the plan's
  const Quaternion flipped(-target.coeffs());
  EXPECT_LT((plannedTurnError(now, flipped, plan_long, long_way) - far).norm(), 1e-9);
  EXPECT_LT((plannedTurnError(now, flipped, plan_short, long_way) - shortest).norm(), 1e-9);
}

// A plan more than a quarter turn off the target (a stale plan, the
// gripper's half-turn twin) says nothing: the last way holds. Near the
// target the short way, whatever the plan (a full turn has no axis).
TEST(PlannedTurn, APlanFarFromTheTargetKeepsTheLastWayAndNearTheTargetTheShortWayHolds) {
  const Quaternion now = Quaternion::Identity();
  const Quaternion target = about(Vector3::UnitZ(), -2.4);
  const Quaternion far_plan(-(about(Vector3::UnitX(), 2.0) * target).coeffs());
  bool long_way = true;
  EXPECT_NEAR(plannedTurnError(now, target, far_plan, long_way).norm(), 2.0 * M_PI - 2.4, 1e-9);
  EXPECT_TRUE(long_way);
  long_way = false;
  EXPECT_NEAR(plannedTurnError(now, target, far_plan, long_way).norm(), 2.4, 1e-9);
  EXPECT_FALSE(long_way);
  // 0.05 rad from the target, the plan a full turn round: the short way
  const Quaternion near = about(Vector3::UnitY(), 0.05);
  long_way = true;
  EXPECT_NEAR(plannedTurnError(now, near, Quaternion(-near.coeffs()), long_way).norm(), 0.05, 1e-9);
  EXPECT_FALSE(long_way);
}

// Turning the long way, the TCP passes the antipode of the target (short
// angle pi): the error the PD sees changes smoothly there, its norm falling
// through pi, instead of flipping to the other side. The cycle's quaternions
// come with either sign (from a rotation matrix): the error does not care.
TEST(PlannedTurn, TheErrorIsContinuousThroughHalfATurn) {
  const Quaternion target = about(Vector3(0.5, -0.1, 0.3), 1.1);
  const Vector3 axis = Vector3(0.2, 1.0, -0.4).normalized();
  // the joints turn the TCP by +5 rad about the axis to the plan, which is at the target
  const Quaternion start = about(axis, -5.0) * target;
  const Quaternion plan = about(axis, 5.0) * start;  // lifted from `start`: -Q(start) side
  ASSERT_LT(plan.dot(start), 0.0);
  bool long_way = false;
  Vector3 last = plannedTurnError(start, target, plan, long_way);
  EXPECT_TRUE(long_way);
  EXPECT_NEAR(last.norm(), 5.0, 1e-9);
  double largest_jump = 0.0;
  for (int k = 1; k <= 500; ++k) {
    const double s = 1.0 - 2.0 * (k % 2);  // the cycle's arbitrary sign, shared by now and the lift from it
    const Quaternion now(s * (about(axis, 5.0 * k / 500.0) * start).coeffs());
    const Vector3 e = plannedTurnError(now, target, Quaternion(s * plan.coeffs()), long_way);
    EXPECT_NEAR(e.norm(), 5.0 * (1.0 - k / 500.0), 1e-6) << k;
    largest_jump = std::max(largest_jump, (e - last).norm());
    last = e;
  }
  EXPECT_LT(largest_jump, 0.0101);  // 5 rad / 500 steps, nothing more
  EXPECT_LT(last.norm(), 1e-6);
}

// Once per plan: along a continuous joint motion (with the plan changing now
// and then, and one jump of the arm), the cached lift gives the error the
// lift recomputed every step gives, and it lifts the path only when the plan
// changes or q jumps.
TEST(PlannedTurn, TheLiftOncePerPlanGivesTheErrorOfTheLiftEveryStep) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int tcp = panda().frameId("tcp");
  PlannedTurnLift lift;
  Vector7 q = randomConfiguration(rng), q_plan = randomConfiguration(rng);
  Quaternion target = rotationAt(q_plan);  // the plan's TCP orientation, as the planner's IK puts it
  bool way_cached = false, way_fresh = false;
  Vector7 qd = Vector7::Zero();
  int disagreements = 0;
  for (int k = 0; k < 3000; ++k) {
    if (k % 700 == 699) {  // a new plan
      q_plan = randomConfiguration(rng);
      target = rotationAt(q_plan);
    }
    if (k == 1500) q = randomConfiguration(rng);             // the arm jumps (a reset)
    for (int i = 0; i < kArmDofs; ++i) qd[i] = 0.9 * qd[i] + 0.2 * u(rng);
    q += 0.01 * qd;  // rad per step: a fast arm at 1 kHz moves far less
    // the cycle's quaternion comes with either sign
    Quaternion now = rotationAt(q);
    if (k % 3 == 0) now.coeffs() = -now.coeffs();
    const Quaternion fresh = planOrientationAlongJointPath(panda(), tcp, q, now, q_plan);
    const Vector3 e_fresh = plannedTurnError(now, target, fresh, way_fresh);
    Quaternion tracked = now;
    const Quaternion cached = lift.plan(panda(), tcp, q, tracked, q_plan);
    const Vector3 e_cached = plannedTurnError(tracked, target, cached, way_cached);
    disagreements += (e_cached - e_fresh).norm() > 1e-9;
  }
  EXPECT_EQ(disagreements, 0);
}
