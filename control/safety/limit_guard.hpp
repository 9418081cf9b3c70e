// The last line of defence between the controller and the arm: every period,
// whatever the QP (or its damped-stop fallback) asked for, the command sent
// to the arm never drives a joint past its position, velocity or torque
// limit. It reads only the measured state and the model, never the QP, in
// the spirit of the Panda's own reflexes: a braking law per joint, then the
// torque limits.
//
// Per joint i, with dt the period, a_b = deceleration_scale * a_max the
// braking it plans with, v_g = velocity_scale * v_max, and d the distance
// from q to the guarded limit (q_max - position_margin above, q_min +
// position_margin below), the velocity after this period v+ = qd + dt qdd
// (semi-implicit Euler, as the arm's state advances) is kept in
//   -v_g <= v+ <= v_g                                  (velocity limit)
//   v+ <= -a_b dt + sqrt((a_b dt)^2 + 2 a_b d)          (upper: can still stop)
//   v+ >= -(same with the lower distance)               (lower: can still stop)
// the last two being the largest speed from which, after moving for one more
// period, braking at a_b stops the joint before the guarded limit (0 at or
// beyond it: the joint does not go further; the QP's damper brings it back).
// That is a box lo <= qdd <= hi on the arm's acceleration. A torque the
// model misses (tau_unmodelled: the controller passes the last period's
// disturbance, DisturbanceObserver::latest, beyond what its dynamics hold)
// adds M^-1 tau_unmodelled to whatever is commanded, so the box on the
// command is shifted by that much: a person pressing on the gripper or the
// held object cannot turn a light wrist joint past its limit while the
// commands stay small. The commanded qdd is clamped into it, and
// tau = M qdd + h - tau_ext must then lie within +-torque_scale * tau_max:
// if not, the guard solves the small projection
//   min |qdd - qdd_box|^2  s.t.  lo <= qdd <= hi,  |M qdd + h - tau_ext| <= tau_lim
// (7 variables, its own Goldfarb-Idnani instance: no tie to the controller's
// QP); should that fail (no acceleration in the box is within the torque
// limits), the torque is clamped and its acceleration clamped into the box a
// few rounds (alternating projections). The final torque is always clamped,
// so the torque limit holds unconditionally, and the position and velocity
// limits hold whenever braking at a_b is within the torque limits.
//
// The guard never makes a command more aggressive: a command inside the box
// and the torque limits passes unchanged (bit for bit). Steps where it changed
// the command are counted (the run's limit_guard_steps).
//
// Frames: joint space. Units: rad, rad/s, rad/s^2, N m, s.
// Real-time safety: apply() and the read-outs allocate nothing and never
// throw; construction and parseLimitGuardSettings are start-up calls.
#pragma once

#include <Eigen/Cholesky>

#include "config/yaml_reader.hpp"
#include "control/model/model.hpp"
#include "control/qp/goldfarb_idnani.hpp"
#include "control/qp/qp_problem.hpp"
#include "control/types.hpp"

namespace handover::control {

/// config/controller.yaml `limit_guard` (validated by parseLimitGuardSettings
/// and, against the QP's limits, by checkControllerBounds).
struct LimitGuardSettings {
  double position_margin = 0.005;   ///< rad inside each position limit where the guard stops a joint
  double velocity_scale = 0.95;     ///< of the datasheet velocity limits, the most speed it lets through
  double deceleration_scale = 0.5;  ///< of the datasheet acceleration limits, the braking it plans with
  double torque_scale = 1.0;        ///< of the datasheet torque limits, the most torque it commands
};

/// Reads the `limit_guard` section: unknown keys and out-of-range values throw
/// InputError naming the file, key and line.
LimitGuardSettings parseLimitGuardSettings(const YamlReader& section);

class LimitGuard {
 public:
  /// Rounds of torque clamp / box clamp when the torque limits bind.
  static constexpr int kTorqueRounds = 4;

  /// Limits from `model` (q_min/q_max, v_max, a_max, tau_max); `period` dt in s.
  LimitGuard(const Model& model, const LimitGuardSettings& settings, double period);

  /// Makes the command safe in place. `data`: q, v (the measured state), M and
  /// h at it (computeAll); `tau_external`: the external torque the dynamics
  /// hold, tau = M qdd + h - tau_external. `qdd` in/out (rad/s^2), `tau` out
  /// (N m, always recomputed from qdd). Returns true when the command changed.
  /// Non-finite qdd entries count as a change and are replaced by the braking
  /// law's nearest admissible value. RT safe.
  bool apply(const Data& data, const Vector7& tau_external, Vector7& qdd, Vector7& tau,
             const Vector7& tau_unmodelled = Vector7::Zero());

  /// Steps where apply() changed the command since reset().
  long changedCount() const { return changed_count_; }
  bool lastChanged() const { return last_changed_; }
  void reset();

  /// The box of the last apply(), rad/s^2.
  const Vector7& lowerBound() const { return lo_; }
  const Vector7& upperBound() const { return hi_; }
  /// Largest speed toward a limit from which braking at a_b still stops
  /// `distance` (rad) short of it after one more period; 0 for distance <= 0.
  double stoppingSpeed(int joint, double distance) const;

  const LimitGuardSettings& settings() const { return settings_; }
  /// The guarded position limits (datasheet limits less the margin), rad.
  const Vector7& guardedMin() const { return q_min_; }
  const Vector7& guardedMax() const { return q_max_; }
  const Vector7& velocityLimit() const { return v_max_; }
  const Vector7& torqueLimit() const { return tau_max_; }

 private:
  LimitGuardSettings settings_;
  double dt_;
  Vector7 q_min_, q_max_, v_max_, a_brake_, tau_max_;
  Vector7 lo_ = Vector7::Zero(), hi_ = Vector7::Zero();
  Eigen::LLT<Matrix7> llt_;
  QpProblem projection_;               // 7 variables, 7 torque rows
  GoldfarbIdnaniSolver solver_;
  Eigen::VectorXd x_;                  // 7
  long changed_count_ = 0;
  bool last_changed_ = false;
};

}  // namespace handover::control
