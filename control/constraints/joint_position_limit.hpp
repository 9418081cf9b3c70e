// Joint position limits with a velocity damper (mc_rtc style), so the arm
// slows down before a limit and never passes it.
//
// Per joint and side, with range = q_max - q_min, d = distance to the limit:
//   di = interaction * range (the damper switches on below di),
//   ds = safety * range      (the arm stops at ds from the limit).
// Inside the interaction zone the velocity toward the limit is bounded by
//   v >= -xi (d - ds) / (di - ds)          (sign shown for the lower limit)
// with xi chosen when the joint enters the zone so the bound starts at the
// current velocity (plus offset * (di - ds) per second of slack), and kept
// until it leaves. Over one period dt the bound becomes an acceleration bound
// on qddot; a second bound keeps the constant-acceleration prediction
// q + qdot dt + qddot dt^2 / 2 at least ds/2 away from the limit. Both only
// tighten the variable bounds and give way to bounds registered earlier (the
// acceleration limits), so they never make the QP infeasible by themselves.
//
// Stateful (xi per joint and side); reset() forgets it. Real-time safe.
#pragma once

#include <array>
#include <string>

#include "control/formulation/constraint.hpp"

namespace handover::control {

struct JointPositionLimitParams {
  double interaction = 0.10;   ///< fraction of the range where the damper starts
  double safety = 0.01;        ///< fraction of the range kept free at the limit
  double damper_offset = 0.5;  ///< extra damping, fraction of (di - ds) per s
  /// Largest speed (rad/s) the damper may demand to leave the safety zone.
  double recovery_speed = 0.1;
};

class JointPositionLimit : public Constraint {
 public:
  /// Throws std::invalid_argument on parameters out of 0 <= safety < interaction <= 0.5.
  JointPositionLimit(const Model& model, const JointPositionLimitParams& params = JointPositionLimitParams(),
                     std::string name = "joint_position");
  const std::string& name() const override { return name_; }
  int maxRows() const override { return 0; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;
  void reset();
  const JointPositionLimitParams& params() const { return params_; }
  /// True while joint i's damper toward its lower (upper) limit is on.
  bool lowerActive(int i) const { return xi_lower_[i] > 0.0; }
  bool upperActive(int i) const { return xi_upper_[i] > 0.0; }

 private:
  std::string name_;
  JointPositionLimitParams params_;
  Vector7 q_min_, q_max_;
  std::array<double, kArmDofs> xi_lower_{}, xi_upper_{};  // 0 = damper off
};

}  // namespace handover::control
