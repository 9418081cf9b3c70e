// Timed moves (fsm/handover/timed_move.hpp): the minimum-jerk duration rule,
// the cruise profile and the joint-space move with its fed-forward derivatives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fsm/handover/timed_move.hpp"

namespace handover::fsm {
namespace {

TEST(MinimumJerkDuration, TheAccelerationOrTheFloorSetsIt) {
  // 0.1 m at 3 m/s^2 peak: sqrt(5.7735 * 0.1 / 3)
  EXPECT_NEAR(minimumJerkDuration(0.1, 3.0, 0.3), std::sqrt(5.7735 * 0.1 / 3.0), 1e-12);
  // a short move takes the floor
  EXPECT_NEAR(minimumJerkDuration(0.001, 3.0, 0.3), 0.3, 1e-12);
  // an acceleration of 0 does not bound it
  EXPECT_NEAR(minimumJerkDuration(5.0, 0.0, 0.3), 0.3, 1e-12);
}

TEST(MinimumJerkAlong, GoesItsDistanceAlongItsDirectionFromRestToRest) {
  const Vector3 dir = Vector3(1.0, -2.0, 2.0).normalized();
  Vector3 x, v;
  minimumJerkAlong(0.08, 0.3, 0.0, dir, x, v);
  EXPECT_LT(x.norm() + v.norm(), 1e-12);
  minimumJerkAlong(0.08, 0.3, 0.15, dir, x, v);  // half way at half time, at its peak 1.875 x 0.08 / 0.3
  EXPECT_LT((x - 0.04 * dir).norm(), 1e-12);
  EXPECT_LT((v - (1.875 * 0.08 / 0.3) * dir).norm(), 1e-12);
  minimumJerkAlong(0.08, 0.3, 0.5, dir, x, v);  // done: there, at rest
  EXPECT_LT((x - 0.08 * dir).norm(), 1e-12);
  EXPECT_LT(v.norm(), 1e-12);
}

// The cruise: up to the joint speed along a smooth ramp, held, down again;
// p, pd and pdd consistent (each the rate of the one before).
void expectConsistent(const CruiseProfile& c) {
  const double h = 1e-6, T = c.duration();
  for (double t = 0.0; t <= T; t += T / 97) {
    double p, pd, pdd, pa, pda, pdda, pb, pdb, pddb;
    c.sample(t, p, pd, pdd);
    c.sample(t - h, pa, pda, pdda);
    c.sample(t + h, pb, pdb, pddb);
    if (t - h > 0.0 && t + h < T) {
      EXPECT_NEAR(pd, (pb - pa) / (2 * h), 1e-5) << t;
      EXPECT_NEAR(pdd, (pdb - pda) / (2 * h), 1e-3) << t;
    }
  }
  double p, pd, pdd;
  c.sample(0.0, p, pd, pdd);
  EXPECT_EQ(p, 0.0);
  EXPECT_EQ(pd, 0.0);
  c.sample(T, p, pd, pdd);
  EXPECT_EQ(p, 1.0);
  EXPECT_EQ(pd, 0.0);
}

TEST(CruiseProfile, CruisesAtItsRateBetweenSmoothRamps) {
  // 1.5 rad at 1 rad/s, ramps of 0.5 s: 0.5 + 1.5 s in all, most of it at the speed
  const CruiseProfile c = cruiseFor(1.5, 1.0, 1.875 / 0.5, 0.0, 0.0, 0.3);
  EXPECT_NEAR(c.duration(), 0.5 + 1.5, 1e-9);
  double p, pd, pdd, peak = 0.0, peak_accel = 0.0;
  for (double t = 0.0; t <= c.duration(); t += 1e-3) {
    c.sample(t, p, pd, pdd);
    peak = std::max(peak, 1.5 * pd);
    peak_accel = std::max(peak_accel, std::abs(1.5 * pdd));
  }
  EXPECT_NEAR(peak, 1.0, 1e-9);
  EXPECT_NEAR(peak_accel, 1.875 / 0.5, 1e-2);
  c.sample(1.0, p, pd, pdd);  // mid-cruise
  EXPECT_NEAR(1.5 * pd, 1.0, 1e-12);
  EXPECT_NEAR(pdd, 0.0, 1e-12);
  expectConsistent(c);
  // a minimum-jerk move within the same peak speed takes 1.875 x 1.5 s
  EXPECT_LT(c.duration(), 1.875 * 1.5);
}

TEST(CruiseProfile, AShortMovePeaksLowerAndAMoveHasAFloor) {
  // 0.2 rad with ramps of 0.5 s: no room to reach 1 rad/s
  const CruiseProfile c = cruiseFor(0.2, 1.0, 1.875 / 0.5, 0.0, 0.0, 0.3);
  EXPECT_NEAR(c.duration(), 1.0, 1e-9);  // two ramps
  double p, pd, pdd;
  c.sample(0.5, p, pd, pdd);
  EXPECT_NEAR(p, 0.5, 1e-12);
  EXPECT_LT(0.2 * pd, 1.0);
  expectConsistent(c);
  // the grip's acceleration lengthens the ramps of a long TCP path
  const CruiseProfile held = cruiseFor(1.5, 1.0, 1.875 / 0.5, 0.6, 0.5, 0.3);
  EXPECT_GT(held.duration(), c.duration());
  // the floor
  EXPECT_NEAR(cruiseFor(0.001, 1.0, 100.0, 0.0, 0.0, 0.3).duration(), 0.3, 1e-9);
}

TEST(JointMove, FollowsItsProfileFromRestToRestWithItsDerivativesFedForward) {
  Vector7 from, to;
  from << 0.1, -0.5, 0.2, -2.0, 0.1, 1.5, 0.7;
  to << 0.6, -0.2, 0.0, -1.5, 0.3, 1.2, -0.1;
  const double travel = (to - from).cwiseAbs().maxCoeff();
  const CruiseProfile c = cruiseFor(travel, 0.8, 4.0, 0.0, 0.0, 0.3);
  JointMove move;
  EXPECT_FALSE(move.active());
  move.start(from, to, c, 2.0);
  EXPECT_TRUE(move.active());
  EXPECT_NEAR(move.duration(), c.duration(), 1e-12);
  Vector7 q, qd, qdd;
  move.sample(2.0, q, qd, qdd);
  EXPECT_LT((q - from).norm(), 1e-12);
  EXPECT_LT(qd.norm(), 1e-12);
  double peak = 0.0;
  for (double t = 2.0; t <= 2.0 + c.duration(); t += 1e-3) {
    move.sample(t, q, qd, qdd);
    peak = std::max(peak, qd.cwiseAbs().maxCoeff());
  }
  EXPECT_NEAR(peak, 0.8, 1e-3);  // the farthest joint cruises at the given speed
  move.sample(2.0 + c.duration() + 1.0, q, qd, qdd);  // after the end: at the goal, at rest
  EXPECT_LT((q - to).norm(), 1e-12);
  EXPECT_LT(qd.norm() + qdd.norm(), 1e-12);
  move.stop();
  EXPECT_FALSE(move.active());
}

}  // namespace
}  // namespace handover::fsm
