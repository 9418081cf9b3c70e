// Timed moves: a carry in joint space (HeldObjectCarry) and the lift-off off
// the person's hand (Retract) follow a minimum-jerk profile, its velocity and
// acceleration fed forward to the task, instead of a set-point step that the
// task's PD closes on its own time constant. At the posture task's K = 10 a
// step settled a carry in about 2 s and crawled over its last 20 %; the pose
// task's K = 6 took 1.1 s for a 10 cm lift-off. The profile takes as long as
// what limits the move needs: no joint faster than a peak speed, the held
// object no harder than the acceleration the grip was sized for
// (params.gripper.grip.acceleration), and a floor for short moves.
// Real-time safe.
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

/// Duration (s) of a rest-to-rest minimum-jerk move: the joint travelling
/// farthest (`joint_travel`, rad) no faster than `joint_speed` (rad/s), a TCP
/// path of `tcp_travel` (m) no harder than `acceleration` (m/s^2, taken on
/// its straight line), at least `min_duration`.
inline double minimumJerkDuration(double joint_travel, double joint_speed, double tcp_travel, double acceleration,
                                  double min_duration) {
  double T = min_duration;
  if (joint_speed > 0.0) T = std::max(T, kMinimumJerkPeakRate * std::abs(joint_travel) / joint_speed);
  if (acceleration > 0.0) T = std::max(T, std::sqrt(kMinimumJerkPeakAccel * std::abs(tcp_travel) / acceleration));
  return T;
}

/// A joint-space minimum-jerk move from one configuration to another.
class JointMove {
 public:
  void start(const Vector7& from, const Vector7& to, double duration, double now) {
    from_ = from;
    to_ = to;
    duration_ = std::max(duration, 1e-3);
    start_ = now;
    active_ = true;
  }
  void stop() { active_ = false; }
  bool active() const { return active_; }
  /// Reference at time `now` (rad, rad/s, rad/s^2); the goal at rest once done.
  void sample(double now, Vector7& q, Vector7& qd, Vector7& qdd) const {
    const double u = (now - start_) / duration_;
    const Vector7 d = to_ - from_;
    q = from_ + minimumJerkPhase(u) * d;
    qd = (minimumJerkRate(u) / duration_) * d;
    qdd = (minimumJerkAccel(u) / (duration_ * duration_)) * d;
  }
  const Vector7& goal() const { return to_; }

 private:
  Vector7 from_ = Vector7::Zero(), to_ = Vector7::Zero();
  double duration_ = 1.0, start_ = 0.0;
  bool active_ = false;
};

}  // namespace handover::fsm
