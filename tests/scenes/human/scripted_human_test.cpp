#include "scenes/human/scripted_human.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "interfaces/minimum_jerk.hpp"
#include "scenes/scenario/scenario_parser.hpp"

using namespace handover;
using namespace handover::human;

namespace {

constexpr double kDt = 0.001;

// a scenario around `script` (YAML list items, indented by 4)
scenario::Scenario make(const std::string& script, bool r2h = false) {
  std::string t = std::string("name: t\nmode: ") + (r2h ? "robot_to_human" : "human_to_robot") +
                  "\nduration: 20\nobject: {shape: sphere, size: [0.04], mass: 0.2}\n"
                  "robot: {holds_object: " + (r2h ? "true" : "false") + "}\n"
                  "human:\n  stand: {pos: [1.0, 0.0], yaw: 3.14159265358979}\n  height: 1.75\n  hand: right\n"
                  "  start: {pos: [0.85, 0.25, 0.10]}\n" +
                  (r2h ? "" : "  holds_object: {pos: [0, 0, 0.04]}\n") + "  script:\n" + script;
  return scenario::parseScenarioString(t, "/tmp/inline.yaml");
}

bool hasEvent(const HumanOutput& o, HumanEventKind k, double* when = nullptr) {
  for (int i = 0; i < o.num_events; ++i) {
    if (o.events[i].kind == k) {
      if (when) *when = o.events[i].time;
      return true;
    }
  }
  return false;
}

}  // namespace

TEST(MinimumJerk, EndpointsAndPeak) {
  EXPECT_DOUBLE_EQ(minimumJerkPhase(0.0), 0.0);
  EXPECT_DOUBLE_EQ(minimumJerkPhase(1.0), 1.0);
  EXPECT_DOUBLE_EQ(minimumJerkPhase(0.5), 0.5);
  EXPECT_DOUBLE_EQ(minimumJerkRate(0.5), 1.875);
  // the rate is the derivative of the phase
  for (double s = 0.05; s < 1.0; s += 0.1) {
    const double h = 1e-6;
    EXPECT_NEAR((minimumJerkPhase(s + h) - minimumJerkPhase(s - h)) / (2 * h), minimumJerkRate(s), 1e-6);
    EXPECT_NEAR((minimumJerkRate(s + h) - minimumJerkRate(s - h)) / (2 * h), minimumJerkAccel(s), 1e-5);
  }
}

TEST(ScriptedHuman, ReachFollowsMinimumJerk) {
  const double T = 1.2;
  const auto sc = make("    - reach: {pos: [0.55, 0.05, 0.30], rpy: [0, 0, 0.8], duration: 1.2}\n");
  ScriptedHuman h(sc);
  const Eigen::Vector3d p0(0.85, 0.25, 0.10), p1(0.55, 0.05, 0.30);
  const double D = (p1 - p0).norm();
  double peak = 0.0, t_peak = -1.0;
  for (int k = 0; k <= 2000; ++k) {
    const double t = k * kDt;
    const HumanOutput& o = h.step(t, {});
    if (k == 0) {
      EXPECT_NEAR((o.poses.hand.translation() - p0).norm(), 0.0, 1e-12);
      EXPECT_NEAR(o.hand_speed, 0.0, 1e-12);
    }
    if (o.hand_speed > peak) {
      peak = o.hand_speed;
      t_peak = t;
    }
    if (k == 600) {
      // halfway in time: halfway in space, and halfway in rotation (same phase)
      EXPECT_NEAR((o.poses.hand.translation() - 0.5 * (p0 + p1)).norm(), 0.0, 1e-9);
      EXPECT_NEAR(Eigen::AngleAxisd(o.poses.hand.rotation()).angle(), 0.4, 1e-9);
    }
    if (k == 300) {
      const double phase = minimumJerkPhase(0.25);
      EXPECT_NEAR((o.poses.hand.translation() - (p0 + phase * (p1 - p0))).norm(), 0.0, 1e-9);
      EXPECT_NEAR(Eigen::AngleAxisd(o.poses.hand.rotation()).angle(), 0.8 * phase, 1e-9);
    }
  }
  EXPECT_NEAR(peak, 1.875 * D / T, 1e-9);
  EXPECT_NEAR(t_peak, T / 2, 1e-9);
  const HumanOutput& end = h.output();
  EXPECT_TRUE(end.done);
  EXPECT_NEAR((end.poses.hand.translation() - p1).norm(), 0.0, 1e-12);
  EXPECT_NEAR(end.hand_speed, 0.0, 1e-12);
}

TEST(ScriptedHuman, RpyOmittedKeepsOrientation) {
  const auto sc = make("    - reach: {pos: [0.6, 0.1, 0.3], rpy: [0.3, 0, 0], duration: 0.5}\n"
                       "    - reach: {pos: [0.55, 0.05, 0.30], duration: 0.5}\n");
  ScriptedHuman h(sc);
  for (int k = 0; k <= 1200; ++k) h.step(k * kDt, {});
  EXPECT_NEAR(Eigen::AngleAxisd(h.output().poses.hand.rotation()).angle(), 0.3, 1e-9);
  EXPECT_NEAR((h.output().poses.hand.translation() - Eigen::Vector3d(0.55, 0.05, 0.30)).norm(), 0, 1e-12);
}

TEST(ScriptedHuman, WaitFiresAfterContinuousDelay) {
  const auto sc = make("    - wait: {until: fingers_on_object, timeout: 10.0, delay: 0.2}\n    - release: {}\n");
  ScriptedHuman h(sc);
  double released_at = -1.0;
  for (int k = 0; k <= 3000 && released_at < 0; ++k) {
    const double t = k * kDt;
    HumanFacts f;
    // touching 1.0-1.1 s (too short), then from 1.5 s on
    f.fingers_on_object = (t >= 1.0 && t < 1.1) || t >= 1.5;
    const HumanOutput& o = h.step(t, f);
    if (hasEvent(o, HumanEventKind::Released, &released_at)) {
      EXPECT_FALSE(o.holds_object);
      EXPECT_TRUE(hasEvent(o, HumanEventKind::WaitFired));
    } else {
      EXPECT_TRUE(o.holds_object) << t;
    }
  }
  EXPECT_NEAR(released_at, 1.7, 1.5 * kDt);
}

TEST(ScriptedHuman, WaitTimesOutAndMovesOn) {
  const auto sc = make("    - wait: {until: fingers_on_object, timeout: 0.75}\n"
                       "    - reach: {pos: [0.55, 0.05, 0.30], duration: 1.0}\n");
  ScriptedHuman h(sc);
  double timed_out = -1.0;
  for (int k = 0; k <= 2000; ++k) {
    const HumanOutput& o = h.step(k * kDt, {});  // never touched
    double when;
    if (hasEvent(o, HumanEventKind::WaitTimedOut, &when)) timed_out = when;
    if (k * kDt < 0.75) {
      EXPECT_NEAR(o.hand_speed, 0.0, 1e-12);
    }
  }
  EXPECT_NEAR(timed_out, 0.75, 1e-12);
  // the reach started at the timeout: it ends at 1.75 s
  ScriptedHuman h2(sc);
  for (int k = 0; k <= 1740; ++k) h2.step(k * kDt, {});
  EXPECT_FALSE(h2.output().done);
  for (int k = 1741; k <= 1751; ++k) h2.step(k * kDt, {});
  EXPECT_TRUE(h2.output().done);
}

TEST(ScriptedHuman, GraspClosesOnlyWithinReach) {
  const auto sc = make("    - grasp: {}\n    - hold: {duration: 0.5}\n    - grasp: {}\n", true);
  ScriptedHuman h(sc);
  HumanFacts far;
  far.object_in_reach = false;
  far.object_distance = 0.2;
  const HumanOutput& o = h.step(0.0, far);
  EXPECT_TRUE(hasEvent(o, HumanEventKind::GraspMissed));
  EXPECT_FALSE(o.holds_object);
  HumanFacts near;
  near.object_in_reach = true;
  for (int k = 1; k < 500; ++k) EXPECT_FALSE(h.step(k * kDt, near).holds_object);
  const HumanOutput& o2 = h.step(0.5, near);
  EXPECT_TRUE(hasEvent(o2, HumanEventKind::Grasped));
  EXPECT_TRUE(o2.holds_object);
}

TEST(ScriptedHuman, PullMovesAlongDirectionWhileHolding) {
  const auto sc = make("    - grasp: {}\n    - pull: {dir: [2, 0, 0], distance: 0.1, duration: 0.6}\n", true);
  ScriptedHuman h(sc);
  HumanFacts near;
  near.object_in_reach = true;
  for (int k = 0; k <= 700; ++k) {
    const HumanOutput& o = h.step(k * kDt, near);
    EXPECT_TRUE(o.holds_object);
    EXPECT_NEAR(o.hand_velocity.y(), 0.0, 1e-12);
  }
  EXPECT_NEAR((h.output().poses.hand.translation() - Eigen::Vector3d(0.95, 0.25, 0.10)).norm(), 0.0, 1e-12);
}

TEST(ScriptedHuman, ArmBodiesMeetTheHand) {
  const auto sc = make("    - reach: {pos: [0.55, 0.05, 0.30], duration: 1.0}\n    - withdraw: {pos: [0.85, 0.25, 0.10], duration: 1.0}\n");
  ScriptedHuman h(sc);
  for (int k = 0; k <= 2100; k += 50) {
    const HumanOutput& o = h.step(k * kDt, {});
    const sim::HumanBodyPoses& p = o.poses;
    const Eigen::Vector3d elbow = p.upper_arm.translation() + p.upper_arm_length * p.upper_arm.linear().col(2);
    EXPECT_NEAR((p.forearm.translation() - elbow).norm(), 0.0, 1e-9);
    const Eigen::Vector3d wrist = p.forearm.translation() + p.forearm_length * p.forearm.linear().col(2);
    EXPECT_NEAR((p.hand.translation() - wrist).norm(), h.body().wrist_to_grip, 1e-9);
    EXPECT_NEAR((p.upper_arm.translation() - h.shoulder()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(p.upper_arm_length, h.body().upper_arm, 1e-12);
    EXPECT_NEAR(p.torso.translation().z(), scenario::kFloorZ, 1e-12);
  }
  double when;
  ScriptedHuman h2(sc);
  bool withdrawing = false;
  for (int k = 0; k <= 2100; ++k) withdrawing = withdrawing || hasEvent(h2.step(k * kDt, {}), HumanEventKind::Withdrawing, &when);
  EXPECT_TRUE(withdrawing);
  EXPECT_NEAR(when, 1.0, 1e-12);
}

// Issue 16: a reach written as 5 ms (a hand that jumps into the robot) used to
// teleport the simulated person: the hand moved 0.15 m in 5 steps, its body
// struck the arm. The person takes as long as a hand needs (3 m/s, 40 m/s^2)
// and says so (stretchedSteps); later steps start that much later.
TEST(ScriptedHuman, AReachFasterThanAHandCanIsSlowedToWhatAHandCan) {
  const auto sc = make(
      "    - reach: {pos: [0.55, 0.05, 0.30], duration: 1.2}\n"
      "    - reach: {pos: [0.50, 0.03, 0.44], duration: 0.005}\n"
      "    - hold: {duration: 0.5}\n");
  const HandMotionLimits limits;
  ScriptedHuman h(sc, limits);
  const double D = (Eigen::Vector3d(0.50, 0.03, 0.44) - Eigen::Vector3d(0.55, 0.05, 0.30)).norm();
  ASSERT_EQ(h.stretchedSteps().size(), 1u);  // the 1.2 s reach is ordinary
  const StretchedStep& st = h.stretchedSteps()[0];
  EXPECT_EQ(st.step, 1);
  EXPECT_DOUBLE_EQ(st.written, 0.005);
  EXPECT_NEAR(st.distance, D, 1e-12);
  EXPECT_NEAR(st.used, std::max(1.875 * D / limits.max_speed, std::sqrt(5.7735 * D / limits.max_acceleration)), 1e-12);

  Eigen::Vector3d last = h.step(0.0, HumanFacts{}).poses.hand.translation();
  double peak_speed = 0.0, peak_step = 0.0, reached = -1.0;
  for (int k = 1; k <= 2000; ++k) {
    const double t = k * kDt;
    const HumanOutput& o = h.step(t, HumanFacts{});
    const Eigen::Vector3d p = o.poses.hand.translation();
    peak_step = std::max(peak_step, (p - last).norm());
    peak_speed = std::max(peak_speed, o.hand_speed);
    if (reached < 0.0 && (p - Eigen::Vector3d(0.50, 0.03, 0.44)).norm() < 1e-9) reached = t;
    last = p;
  }
  EXPECT_LE(peak_speed, limits.max_speed + 1e-9);
  EXPECT_LE(peak_step, limits.max_speed * kDt + 1e-9);  // no teleport between two steps
  EXPECT_NEAR(reached, 1.2 + st.used, 2 * kDt);
}

TEST(ScriptedHuman, PlausibleDurationKeepsSpeedAccelerationAndTurnRate) {
  const HandMotionLimits lim;
  EXPECT_DOUBLE_EQ(plausibleDuration(1.0, 0.3, 0.5, lim), 1.0);  // an ordinary reach keeps its time
  const double T = plausibleDuration(0.0, 0.6, 0.0, lim);
  EXPECT_LE(1.875 * 0.6 / T, lim.max_speed + 1e-12);
  EXPECT_LE(5.7735 * 0.6 / (T * T), lim.max_acceleration + 1e-9);
  const double R = plausibleDuration(0.0, 0.0, 3.0, lim);  // a half turn of the wrist in no time
  EXPECT_NEAR(1.875 * 3.0 / R, lim.max_angular_speed, 1e-9);
}
