// The plausibility gates, through the estimator that applies them to every
// source (issue 16: a tracker value of 1e300, a body 10^5 m away or a hand
// that jumps 0.5 m between two samples was believed).
#include <gtest/gtest.h>

#include "perception/csv_pose_source.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/plausibility_gate.hpp"

using namespace handover::perception;

namespace {

constexpr double kPeriod = 1.0 / 60.0;

PoseSample sampleAt(double t, double x, double y = 0.0) {
  PoseSample s;
  s.stamp = t;
  s.hand.position = {x, y, 0.3};
  s.forearm.position = {x + 0.25, y, 0.3};
  s.upper_arm.position = {x + 0.5, y, 0.5};
  return s;
}

// a hand at rest at x = 0.5 for 0.5 s, 60 Hz
void settle(PerceptionEstimator& est, double until = 0.5) {
  for (double t = 0.0; t <= until + 1e-9; t += kPeriod) ASSERT_TRUE(est.addSample(sampleAt(t, 0.5)));
}

}  // namespace

TEST(PlausibilityGate, AFarOrAbsurdSampleIsRefusedAndLeavesTheEstimate) {
  PerceptionEstimator est;
  settle(est);
  const double t = 0.5 + kPeriod;
  EXPECT_FALSE(est.addSample(sampleAt(t, 1e5)));  // 10^5 m away
  PoseSample absurd = sampleAt(t, 0.5);
  absurd.forearm.position.y() = 1e300;  // finite, but no person's elbow
  EXPECT_FALSE(est.addSample(absurd));
  EXPECT_EQ(est.rejected(), 2);
  EXPECT_EQ(est.rejects()[RejectReason::kWorkspace], 2);
  const auto& e = est.estimate(t, ObjectHolder::Person);
  EXPECT_NEAR(e.human.hand.translation().x(), 0.5, 1e-9);
  EXPECT_LT(e.human.forearm.translation().norm(), 2.0);
}

TEST(PlausibilityGate, AHandThatJumpsHalfAMetreIsNotBelieved) {
  PerceptionEstimator est;
  settle(est);
  double t = 0.5 + kPeriod;
  EXPECT_FALSE(est.addSample(sampleAt(t, 1.0)));  // 0.5 m in 17 ms
  EXPECT_EQ(est.rejects()[RejectReason::kJump], 1);
  // the track goes on where it was
  t += kPeriod;
  EXPECT_TRUE(est.addSample(sampleAt(t, 0.5)));
  EXPECT_NEAR(est.estimate(t, ObjectHolder::Person).human.hand.translation().x(), 0.5, 1e-6);
}

TEST(PlausibilityGate, SpeedAndAccelerationBeyondAHandsAreRefused) {
  EstimatorSettings cfg;
  PerceptionEstimator est(cfg);
  settle(est);
  // 0.2 m in 17 ms: 12 m/s (below max_jump, above max_speed * dt + tolerance)
  EXPECT_FALSE(est.addSample(sampleAt(0.5 + kPeriod, 0.7)));
  EXPECT_EQ(est.rejects()[RejectReason::kSpeed], 1);

  // a hand moving steadily at 1 m/s, then one sample 0.1 m off its path: a
  // speed it could have (1 m/s + 6 m/s for one sample is within the speed
  // bound with tolerance) but an acceleration of 700 m/s^2
  PerceptionEstimator est2(cfg);
  double t = 0.0, x = 0.3;
  for (int k = 0; k < 60; ++k, t += kPeriod, x += kPeriod) ASSERT_TRUE(est2.addSample(sampleAt(t, x)));
  EXPECT_FALSE(est2.addSample(sampleAt(t, x + 0.1)));
  EXPECT_EQ(est2.rejects()[RejectReason::kAcceleration], 1);
  EXPECT_TRUE(est2.addSample(sampleAt(t + 1e-3, x + 1e-3)));  // the path itself is fine
}

TEST(PlausibilityGate, ReacquisitionAfterADropoutIsBelievedNotRejectedAsAJump) {
  PerceptionEstimator est;
  settle(est);
  // a 3 s dropout; the person reappears 0.5 m away
  const double t = 3.5;
  EXPECT_TRUE(est.addSample(sampleAt(t, 1.0)));
  EXPECT_EQ(est.rejected(), 0);
  for (int k = 1; k < 5; ++k) EXPECT_TRUE(est.addSample(sampleAt(t + k * kPeriod, 1.0)));
  const auto& e = est.estimate(t + 4 * kPeriod, ObjectHolder::Person);
  EXPECT_FALSE(e.human.stale);
  EXPECT_NEAR(e.human.hand.translation().x(), 1.0, 1e-6);
  EXPECT_EQ(est.reseeds(), 2);  // the first sample and the reacquisition
}

TEST(PlausibilityGate, AFailingSourceGoesStaleNeverMotionThenRestartsTheTrack) {
  EstimatorSettings cfg;
  PerceptionEstimator est(cfg);
  settle(est);
  // the tracker now reports the hand 0.5 m away at every sample (a swapped
  // marker): refused, so the estimate goes stale where the hand was
  double t = 0.5;
  for (int k = 0; k < 12; ++k) {
    t += kPeriod;
    est.addSample(sampleAt(t, 1.0), t);
  }
  EXPECT_GE(est.rejects()[RejectReason::kJump], 6);
  const auto& e = est.estimate(t, ObjectHolder::Person);
  EXPECT_TRUE(e.human.stale);
  EXPECT_NEAR(e.human.hand.translation().x(), 0.5, 1e-6);
  // it persists past reseed_gap: a new track starts where the data says
  for (int k = 0; k < 12; ++k) {
    t += kPeriod;
    est.addSample(sampleAt(t, 1.0), t);
  }
  const auto& e2 = est.estimate(t, ObjectHolder::Person);
  EXPECT_FALSE(e2.human.stale);
  EXPECT_NEAR(e2.human.hand.translation().x(), 1.0, 1e-6);
}

TEST(PlausibilityGate, ClockFaultsAndInvalidValuesAreCountedApart) {
  PerceptionEstimator est;
  settle(est);
  EXPECT_FALSE(est.addSample(sampleAt(0.2, 0.5)));             // before the latest
  EXPECT_FALSE(est.addSample(sampleAt(1e300, 0.5), 0.6));      // stamped far in the future
  PoseSample q = sampleAt(0.6, 0.5);
  q.hand.orientation.coeffs() << 0.0, 0.0, 0.0, 2.0;     // not a rotation
  EXPECT_FALSE(est.addSample(q, 0.6));
  EXPECT_EQ(est.rejects()[RejectReason::kTime], 2);
  EXPECT_EQ(est.rejects()[RejectReason::kInvalid], 1);
  EXPECT_EQ(est.rejected(), 3);
  // and the stream goes on
  EXPECT_TRUE(est.addSample(sampleAt(0.5 + kPeriod, 0.5)));
}

TEST(PlausibilityGate, TheGateAloneJudgesEveryTrackedBody) {
  PlausibilityGate gate;
  PoseSample a = sampleAt(1.0, 0.5);
  a.has_object = true;
  a.object.position = {0.5, 0.0, 0.35};
  EXPECT_EQ(gate.check(a, {}).verdict, GateVerdict::kReseed);
  gate.accept(a);
  PoseSample b = a;
  b.stamp += kPeriod;
  b.object.position.x() += 0.5;  // only the object jumps
  const GateResult r = gate.check(b, {});
  EXPECT_EQ(r.verdict, GateVerdict::kReject);
  EXPECT_EQ(r.reason, RejectReason::kJump);
  b = a;
  b.stamp += kPeriod;
  b.upper_arm.position.z() = -5.0;  // below the floor
  EXPECT_EQ(gate.check(b, {}).reason, RejectReason::kWorkspace);
}
