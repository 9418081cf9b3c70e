// Bounds on controller settings that keep the controller stable, beyond each
// value's own range: PD gains against the control period, weights against the
// QP's regularisation, the posture target inside the joint limits (of the
// robot description's model). Checked by
// parseControllerConfig after reading; start-up only.
#pragma once

#include <string>

#include "control/controller_config.hpp"
#include "control/model/joint_limits.hpp"

namespace handover::control {

/// Largest |pole| x period allowed for a PD task (see pdGainsProblem).
constexpr double kMaxPolePeriod = 0.5;
/// Regularisation must be at least this fraction of the largest task weight.
constexpr double kMinRegularisationRatio = 1e-11;

/// Why the PD pair (K, D) is unstable or under-sampled at period `dt`, or ""
/// when it is fine. The QP realises the task's acceleration a = -K e - D edot
/// one period at a time, through two discrete integrators: the observed
/// object's (exact for a constant acceleration over the step) and the
/// simulator's (semi-implicit Euler). Both must be stable, and the fastest
/// continuous pole s of s^2 + D s + K must be sampled at least ~12 times per
/// radian: |s| dt <= kMaxPolePeriod. With critical damping this is
/// sqrt(K) dt <= 0.5, i.e. K dt^2 <= 0.25 and D dt <= 1.
std::string pdGainsProblem(double stiffness, double damping, double dt);

/// Throws InputError through `root` (file and line of the config) naming the
/// first setting that breaks a bound. `joints`: the robot's position limits
/// (its description's model), which the posture target must respect.
void checkControllerBounds(const ControllerConfig& cfg, const YamlReader& root, const JointLimits& joints);

}  // namespace handover::control
