// What a person's hand can do, for the simulated person: a script step or a
// tracked person faster than this is slowed to it (issue 16: a hand that
// "jumps" used to teleport the simulated body into the robot). Pure;
// real-time safe.
#pragma once

namespace handover::human {

/// What a person's hand can do (the simulated person never moves faster):
/// hands peak at 0.5-1.2 m/s in handovers and 2-3 m/s in fast motions
/// (facts file); 40 m/s^2 is 7x a 0.6 m reach in 0.5 s (5.8 D / T^2). The
/// wrist's turn rate is approximate. The tracker's plausibility gates
/// (config/perception.yaml gates) use the same speed and acceleration.
struct HandMotionLimits {
  double max_speed = 3.0;            ///< m/s, grip point
  double max_acceleration = 40.0;    ///< m/s^2, grip point
  double max_angular_speed = 10.0;   ///< rad/s, hand rotation (approx)
};

/// The shortest duration (s) of a rest-to-rest minimum-jerk motion over
/// `distance` (m) and `angle` (rad) within `limits`, and at least `written`.
double plausibleDuration(double written, double distance, double angle, const HandMotionLimits& limits);

}  // namespace handover::human
