// Timed moves (fsm/handover/timed_move.hpp): the duration rule and the
// minimum-jerk joint-space profile with its fed-forward derivatives.
#include <gtest/gtest.h>

#include <cmath>

#include "fsm/handover/timed_move.hpp"

namespace handover::fsm {
namespace {

TEST(MinimumJerkDuration, TheTightestLimitSetsIt) {
  // 1 rad at 0.8 rad/s peak: 1.875 / 0.8 s
  EXPECT_NEAR(minimumJerkDuration(1.0, 0.8, 0.0, 3.0, 0.3), 1.875 / 0.8, 1e-12);
  // 0.1 m at 3 m/s^2 peak: sqrt(5.7735 * 0.1 / 3)
  EXPECT_NEAR(minimumJerkDuration(0.0, 0.8, 0.1, 3.0, 0.3), std::sqrt(5.7735 * 0.1 / 3.0), 1e-12);
  // a short move takes the floor
  EXPECT_NEAR(minimumJerkDuration(0.01, 0.8, 0.001, 3.0, 0.3), 0.3, 1e-12);
  // a limit of 0 does not bound it
  EXPECT_NEAR(minimumJerkDuration(5.0, 0.0, 5.0, 0.0, 0.3), 0.3, 1e-12);
  // the joint-speed bound holds the fastest joint to that speed, whatever its sign
  EXPECT_NEAR(minimumJerkDuration(-2.0, 1.0, 0.0, 0.0, 0.1), 3.75, 1e-12);
}

TEST(JointMove, GoesFromRestToRestWithinItsPeakSpeedAndFeedsItsDerivativesForward) {
  Vector7 from, to;
  from << 0.1, -0.5, 0.2, -2.0, 0.1, 1.5, 0.7;
  to << 0.6, -0.2, 0.0, -1.5, 0.3, 1.2, -0.1;
  const double travel = (to - from).cwiseAbs().maxCoeff();
  const double T = minimumJerkDuration(travel, 0.8, 0.0, 0.0, 0.3);
  JointMove move;
  EXPECT_FALSE(move.active());
  move.start(from, to, T, 2.0);
  EXPECT_TRUE(move.active());
  Vector7 q, qd, qdd;
  move.sample(2.0, q, qd, qdd);
  EXPECT_LT((q - from).norm(), 1e-12);
  EXPECT_LT(qd.norm(), 1e-12);
  double peak = 0.0;
  const double h = 1e-5;
  for (double t = 2.0; t <= 2.0 + T; t += T / 50) {
    move.sample(t, q, qd, qdd);
    peak = std::max(peak, qd.cwiseAbs().maxCoeff());
    Vector7 qa, qb, va, vb, aa, ab;
    move.sample(t - h, qa, va, aa);
    move.sample(t + h, qb, vb, ab);
    if (t - h > 2.0 && t + h < 2.0 + T) {
      EXPECT_LT((qd - (qb - qa) / (2 * h)).norm(), 1e-6) << t;  // qd is q's rate
      EXPECT_LT((qdd - (vb - va) / (2 * h)).norm(), 1e-5) << t;  // qdd is qd's
    }
  }
  EXPECT_NEAR(peak, 0.8, 1e-3);  // the fastest joint peaks at the given speed
  move.sample(2.0 + T + 1.0, q, qd, qdd);  // after the end: at the goal, at rest
  EXPECT_LT((q - to).norm(), 1e-12);
  EXPECT_LT(qd.norm() + qdd.norm(), 1e-12);
  move.stop();
  EXPECT_FALSE(move.active());
}

}  // namespace
}  // namespace handover::fsm
