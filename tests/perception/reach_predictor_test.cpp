#include "perception/reach_predictor.hpp"
#include "interfaces/minimum_jerk.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace handover::perception {
namespace {

// A minimum-jerk reach: rests at `from` until t0, arrives at `to` at t0 + T,
// turning by `turn` rad about z on the same phase.
struct Reach {
  Eigen::Vector3d from{0.9, 0.2, 0.15}, to{0.55, 0.05, 0.35};
  double t0 = 0.5, T = 1.2, turn = 1.5;
  Eigen::Isometry3d pose(double t) const {
    const double s = minimumJerkPhase((t - t0) / T);
    Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
    x.translation() = from + s * (to - from);
    x.linear() = Eigen::AngleAxisd(s * turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return x;
  }
  double speed(double t) const { return (pose(t + 1e-4).translation() - pose(t - 1e-4).translation()).norm() / 2e-4; }
  Eigen::Isometry3d end() const { return pose(t0 + T + 1.0); }
};

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

// Feeds the reach at 1 kHz up to `until` (the predictor decimates).
void feed(ReachPredictor& p, const Reach& r, double from, double until, double noise = 0.0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise > 0.0 ? noise : 1.0);
  for (double t = from; t <= until + 1e-9; t += 0.001) {
    Eigen::Isometry3d x = r.pose(t);
    if (noise > 0.0) x.translation() += Eigen::Vector3d(n(rng), n(rng), n(rng));
    p.add(t, x, r.speed(t));
  }
}

TEST(ReachPredictor, AHandAtRestIsItsOwnEnd) {
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, 0.45);
  EXPECT_FALSE(p.prediction().reaching);
  EXPECT_EQ(p.prediction().lead, 0.0);
  const Eigen::Isometry3d x = r.pose(0.45);
  EXPECT_TRUE(p.ledPose(x, x).isApprox(x));
}

TEST(ReachPredictor, DoesNotLeadBeforeTheSpeedPeaks) {
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, r.t0 + 0.35 * r.T);
  EXPECT_TRUE(p.prediction().reaching);
  EXPECT_EQ(p.prediction().lead, 0.0);  // D and T are not separable yet
}

TEST(ReachPredictor, FindsTheRestingPoseOnceTheSpeedHasPeaked) {
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, r.t0 + 0.6 * r.T);
  const ReachPrediction& e = p.prediction();
  EXPECT_GT(e.lead, 0.0);
  EXPECT_NEAR(e.duration, r.T, 0.05);
  EXPECT_LT((e.end.translation() - r.to).norm(), 0.01) << e.end.translation().transpose();
  EXPECT_LT(angleBetween(e.end.linear(), r.end().linear()), 3.0 * M_PI / 180.0);
  // still 40 % of the way to go: the lead takes the hand most of it
  const Eigen::Isometry3d now = r.pose(r.t0 + 0.6 * r.T);
  EXPECT_LT((p.ledPose(now, now).translation() - r.to).norm(),
            0.5 * (now.translation() - r.to).norm());
}

TEST(ReachPredictor, NoisySamplesStillGiveTheEndWithinCentimetres) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    ReachPredictor p;
    Reach r;
    feed(p, r, 0.0, r.t0 + 0.7 * r.T, 0.003, seed);
    const ReachPrediction& e = p.prediction();
    EXPECT_EQ(e.lead, 1.0) << "seed " << seed << " phase " << e.phase << " residual " << e.residual;
    EXPECT_LT((e.end.translation() - r.to).norm(), 0.03) << "seed " << seed;
  }
}

TEST(ReachPredictor, LedPoseMovesAHeldObjectRigidlyWithTheHand) {
  ReachPredictor p;
  Reach r;
  const double t = r.t0 + 0.8 * r.T;
  feed(p, r, 0.0, t);
  ASSERT_EQ(p.prediction().lead, 1.0);
  const Eigen::Isometry3d hand = r.pose(t);
  Eigen::Isometry3d object = hand * Eigen::Translation3d(0.0, 0.1, 0.05);
  const Eigen::Isometry3d led_hand = p.ledPose(hand, hand), led_object = p.ledPose(hand, object);
  EXPECT_TRUE(led_hand.isApprox(p.prediction().end, 1e-9));
  EXPECT_TRUE((led_hand.inverse() * led_object).isApprox(hand.inverse() * object, 1e-9));
}

TEST(ReachPredictor, AWanderingHandIsNotLedAnywhere) {
  // a hand that starts smoothly and keeps circling at 0.3 m/s: for a moment an
  // arc looks like the start of a reach, soon no straight minimum-jerk path fits
  ReachPredictor p;
  double late_lead = 0.0, farthest = 0.0;
  double a = 0.0;
  for (double t = 0.0; t < 4.0; t += 0.001) {
    const double speed = t > 0.5 ? 0.3 * minimumJerkPhase((t - 0.5) / 0.5) : 0.0;
    a += speed / 0.1 * 0.001;
    Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
    x.translation() = Eigen::Vector3d(0.6 + 0.1 * std::cos(a), 0.1 * std::sin(a), 0.3);
    p.add(t, x, speed);
    if (t > 1.5) late_lead = std::max(late_lead, p.prediction().lead);
    farthest = std::max(farthest, (p.ledPose(x, x).translation() - x.translation()).norm());
  }
  EXPECT_TRUE(p.prediction().reaching);
  EXPECT_EQ(late_lead, 0.0) << "residual " << p.prediction().residual;
  EXPECT_LT(farthest, 0.1);
}

TEST(ReachPredictor, ComingToRestEndsTheReach) {
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, r.t0 + r.T + 0.2);
  EXPECT_FALSE(p.prediction().reaching);
  EXPECT_EQ(p.prediction().lead, 0.0);
  EXPECT_LT((p.prediction().end.translation() - r.to).norm(), 1e-6);
}

TEST(ReachPredictor, ATrustedEndStaysTrustedOnceTheHandRestsThereUntilTheNextReach) {
  // the arm set off toward the fitted end: once the hand rests there that end is
  // still the one it heads for (the grasp chosen for it is kept); a new reach is not
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, r.t0 + 0.3 * r.T);
  EXPECT_TRUE(p.prediction().reaching);
  EXPECT_FALSE(p.prediction().end_trusted) << "before the speed peak";
  feed(p, r, r.t0 + 0.3 * r.T + 0.001, r.t0 + 0.7 * r.T);
  EXPECT_TRUE(p.prediction().end_trusted);
  feed(p, r, r.t0 + 0.7 * r.T + 0.001, r.t0 + r.T + 0.3);
  EXPECT_FALSE(p.prediction().reaching);
  EXPECT_TRUE(p.prediction().end_trusted) << "the hand rests where the trusted end was";
  Reach next;
  next.from = r.to;
  next.to = r.to + Eigen::Vector3d(0.0, -0.25, 0.05);
  next.t0 = r.t0 + r.T + 0.3;
  feed(p, next, next.t0, next.t0 + 0.3 * next.T);
  EXPECT_TRUE(p.prediction().reaching);
  EXPECT_FALSE(p.prediction().end_trusted) << "a new reach, its end not fitted yet";
}

TEST(ReachPredictor, AReachLostInAGapEndsWithNoTrustedEnd) {
  // the person unseen from before the speed peak until the hand has stopped: the
  // reach's end was never trusted, so nothing the arm chose on the way is to be kept
  ReachPredictor p;
  Reach r;
  feed(p, r, 0.0, r.t0 + 0.2 * r.T);
  const double back = r.t0 + r.T + 0.1;
  for (double t = back; t <= back + 1.0; t += 0.001) p.add(t, r.pose(t), 0.0);
  EXPECT_FALSE(p.prediction().reaching);
  EXPECT_FALSE(p.prediction().end_trusted);
}

TEST(ReachPredictor, AGapInTheSamplesLosesTheReachUntilTheHandRests) {
  // the person unseen for 0.4 s mid-reach (longer than the estimator's reseed gap):
  // its track restarts at rest, so the first speeds after the gap are 0 and rise
  // over a few samples. Neither a rest nor the start of a new reach: no end is
  // trusted until the hand has rested
  ReachPredictor p;
  Reach r;
  const double gap_from = r.t0 + 0.3 * r.T, gap_to = gap_from + 0.4;
  feed(p, r, 0.0, gap_from);
  double lead_after_gap = 0.0;
  for (double t = gap_to; t <= r.t0 + r.T - 0.05; t += 0.001) {
    const double restarted_speed = r.speed(t) * std::min(1.0, (t - gap_to) / 0.05);  // the filter's rise
    p.add(t, r.pose(t), restarted_speed);
    lead_after_gap = std::max(lead_after_gap, p.prediction().lead);
  }
  EXPECT_EQ(lead_after_gap, 0.0) << "a reach fitted from a restart that was no rest";
  EXPECT_FALSE(p.prediction().reaching);
  // the hand rests: the next reach is fitted again
  feed(p, r, r.t0 + r.T - 0.05, r.t0 + r.T + 0.3);
  Reach next;
  next.from = r.to;
  next.to = r.to + Eigen::Vector3d(0.0, -0.25, 0.05);
  next.t0 = r.t0 + r.T + 0.3;
  next.turn = 0.0;
  feed(p, next, next.t0, next.t0 + 0.7 * next.T);
  EXPECT_EQ(p.prediction().lead, 1.0);
  EXPECT_LT((p.prediction().end.translation() - next.to).norm(), 0.01);
}

TEST(ReachPredictor, AFitAtTheEdgeOfTheDurationsIsNotTrusted) {
  // a hand drifting in over 6 s, twice the longest reach fitted: the best
  // duration sits at max_duration, which brackets no minimum
  ReachPredictorSettings s;
  ReachPredictor p(s);
  Reach slow;
  slow.T = 2.0 * s.max_duration;
  slow.to = slow.from + Eigen::Vector3d(-0.9, -0.3, 0.5);  // fast enough to count as a reach
  double worst = 0.0;
  for (double t = 0.0; t <= slow.t0 + 0.8 * slow.T; t += 0.001) {
    p.add(t, slow.pose(t), slow.speed(t));
    if (p.prediction().lead > 0.0) worst = std::max(worst, p.prediction().duration);
  }
  ASSERT_TRUE(p.prediction().reaching);
  EXPECT_EQ(worst, 0.0) << "trusted a fit of duration " << worst << " s";
}

}  // namespace
}  // namespace handover::perception
