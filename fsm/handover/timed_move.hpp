// Timed moves: the lift-off off the person's hand (Retract) follows a
// minimum-jerk profile and a carry in joint space (HeldObjectCarry, when
// params.carry.joint_speed is set) a cruise profile, their velocity and
// acceleration fed forward to the task, instead of a set-point step that the
// task's PD closes on its own time constant (the pose task's K = 6 took 1.1 s
// for a 10 cm lift-off; the posture task's K = 10 settles a carry's last
// fifth slowly). A profile takes as long as what limits the move needs: no
// joint faster than a peak speed, the held object no harder than the
// acceleration the grip was sized for (params.gripper.grip.acceleration),
// and a floor for short moves. Real-time safe.
#pragma once

#include <algorithm>
#include <cmath>

#include "fsm/handover/handover_io.hpp"
#include "interfaces/minimum_jerk.hpp"

namespace handover::fsm {

/// Peak speed and peak acceleration of a rest-to-rest minimum-jerk move of
/// length 1 over time 1.
constexpr double kMinimumJerkPeakRate = 1.875;
constexpr double kMinimumJerkPeakAccel = 5.7735;

/// Duration (s) of a rest-to-rest minimum-jerk move of `travel` (m) no
/// harder than `acceleration` (m/s^2; 0: unbounded), at least `min_duration`.
inline double minimumJerkDuration(double travel, double acceleration, double min_duration) {
  double T = min_duration;
  if (acceleration > 0.0) T = std::max(T, std::sqrt(kMinimumJerkPeakAccel * std::abs(travel) / acceleration));
  return T;
}

/// A straight minimum-jerk move of `distance` (m) along the unit `direction`
/// over `duration` (s), at `t` s from its start: the offset from where it
/// began (m) and its velocity (m/s), for a pose set-point and its feed-forward.
inline void minimumJerkAlong(double distance, double duration, double t, const Vector3& direction, Vector3& offset,
                             Vector3& velocity) {
  const double u = t / duration;
  offset = (distance * minimumJerkPhase(u)) * direction;
  velocity = (distance * minimumJerkRate(u) / duration) * direction;
}

/// A rest-to-rest phase profile p(t) from 0 to 1 that cruises: the rate
/// rises to `rate` (1/s) along a minimum-jerk-shaped ramp of `ramp` s,
/// holds, and falls back the same way. A minimum-jerk move peaks at 1.875
/// times its mean rate, so one held under a speed limit spends most of a long
/// move well below it; this one spends it at the limit. A move too short to
/// reach `rate` within its ramps peaks lower (two ramps, no cruise).
class CruiseProfile {
 public:
  /// rate > 0 (1/s), ramp > 0 (s).
  void set(double rate, double ramp) {
    ramp_ = std::max(ramp, 1e-3);
    rate_ = std::min(std::max(rate, 1e-9), 1.0 / ramp_);
    cruise_ = 1.0 / rate_ - ramp_;
  }
  double duration() const { return 2.0 * ramp_ + cruise_; }
  /// Phase, rate (1/s) and its rate (1/s^2) at t (s from the start).
  void sample(double t, double& p, double& pd, double& pdd) const {
    const double T = duration();
    if (t <= 0.0 || t >= T) {
      p = t <= 0.0 ? 0.0 : 1.0;
      pd = pdd = 0.0;
      return;
    }
    if (t <= ramp_) return rampUp(t, p, pd, pdd);
    if (t < ramp_ + cruise_) {
      p = 0.5 * rate_ * ramp_ + rate_ * (t - ramp_);
      pd = rate_;
      pdd = 0.0;
      return;
    }
    rampUp(T - t, p, pd, pdd);  // the fall mirrors the rise
    p = 1.0 - p;
    pdd = -pdd;
  }

 private:
  void rampUp(double t, double& p, double& pd, double& pdd) const {
    const double s = t / ramp_;
    // the rate is rate_ * minimumJerkPhase(s); its integral over the ramp, s^4 (2.5 - 3 s + s^2)
    p = rate_ * ramp_ * s * s * s * s * (2.5 + s * (-3.0 + s));
    pd = rate_ * minimumJerkPhase(s);
    pdd = rate_ * minimumJerkRate(s) / ramp_;
  }

  double rate_ = 1.0, ramp_ = 0.5, cruise_ = 0.5;
};

/// The cruise of a joint-space move: the joint travelling farthest
/// (`joint_travel`, rad) at most at `joint_speed` (rad/s) and
/// `joint_acceleration` (rad/s^2, the ramp's peak), a TCP path of
/// `tcp_travel` (m, on its straight line) at most at `acceleration` (m/s^2),
/// at least `min_duration` (s) in all.
inline CruiseProfile cruiseFor(double joint_travel, double joint_speed, double joint_acceleration, double tcp_travel,
                               double acceleration, double min_duration) {
  const double travel = std::max(std::abs(joint_travel), 1e-9);
  const double rate = joint_speed / travel;  // phase per second at the joint speed
  double ramp = kMinimumJerkPeakRate * joint_speed / std::max(joint_acceleration, 1e-9);
  if (acceleration > 0.0) ramp = std::max(ramp, kMinimumJerkPeakRate * rate * std::abs(tcp_travel) / acceleration);
  CruiseProfile profile;
  profile.set(rate, ramp);
  if (profile.duration() < min_duration) profile.set(2.0 / min_duration, 0.5 * min_duration);
  return profile;
}

/// A joint-space move from one configuration to another along a phase profile.
class JointMove {
 public:
  void start(const Vector7& from, const Vector7& to, const CruiseProfile& profile, double now) {
    from_ = from;
    to_ = to;
    profile_ = profile;
    start_ = now;
    active_ = true;
  }
  void stop() { active_ = false; }
  bool active() const { return active_; }
  double duration() const { return profile_.duration(); }
  /// Reference at time `now` (rad, rad/s, rad/s^2); the goal at rest once done.
  void sample(double now, Vector7& q, Vector7& qd, Vector7& qdd) const {
    double p, pd, pdd;
    profile_.sample(now - start_, p, pd, pdd);
    const Vector7 d = to_ - from_;
    q = from_ + p * d;
    qd = pd * d;
    qdd = pdd * d;
  }

 private:
  Vector7 from_ = Vector7::Zero(), to_ = Vector7::Zero();
  CruiseProfile profile_;
  double start_ = 0.0;
  bool active_ = false;
};

}  // namespace handover::fsm
