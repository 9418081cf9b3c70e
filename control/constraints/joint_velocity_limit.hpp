// Joint velocity limits as acceleration bounds over one control period:
//   -s v_max <= qdot + qddot dt <= s v_max,   s = scale * speed_scale
// (scale default 0.5 of the datasheet value, Model::v_max). With `braking`
// b > 0 the speed toward a position limit is also capped where the joint
// could no longer stop before it with b times its datasheet acceleration:
//   |qdot| <= sqrt(2 b a_max (d - ds))   (d: distance to the limit,
//   ds: safety fraction of the range, as the position damper keeps free),
// so a joint enters the position damper's zone slow enough for the damper
// to brake it within its limits, however fast the arm may move elsewhere.
// Bounds only. Real-time safe.
#pragma once

#include <string>

#include "control/formulation/constraint.hpp"

namespace handover::control {

class JointVelocityLimit : public Constraint {
 public:
  /// `braking`: fraction of Model::a_max (0 = no braking cap); `safety`:
  /// fraction of each joint's range kept free at its limits.
  JointVelocityLimit(const Model& model, double scale = 0.5, std::string name = "joint_velocity",
                     double braking = 0.0, double safety = 0.0);
  const std::string& name() const override { return name_; }
  int maxRows() const override { return 0; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;
  /// Fraction of the datasheet limit.
  void setScale(double scale) { scale_ = scale; }
  double scale() const { return scale_; }
  /// Extra factor in (0, 1] set at run time (e.g. slower near the person).
  void setSpeedScale(double s) { speed_scale_ = s; }
  double speedScale() const { return speed_scale_; }
  /// Velocity limit in force now, rad/s.
  Vector7 limit() const { return scale_ * speed_scale_ * v_max_; }

 private:
  std::string name_;
  Vector7 v_max_;
  Vector7 a_max_, q_min_, q_max_;
  double scale_;
  double braking_ = 0.0, safety_ = 0.0;
  double speed_scale_ = 1.0;
};

}  // namespace handover::control
