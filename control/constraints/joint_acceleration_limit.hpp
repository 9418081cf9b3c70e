// Joint acceleration limits: |qddot_i| <= scale * a_max_i (Model::a_max,
// datasheet). Bounds only (no rows); register it before the position and
// velocity limits so theirs give way to it. Real-time safe.
#pragma once

#include <string>

#include "control/formulation/constraint.hpp"

namespace handover::control {

class JointAccelerationLimit : public Constraint {
 public:
  JointAccelerationLimit(const Model& model, double scale = 1.0, std::string name = "joint_acceleration");
  const std::string& name() const override { return name_; }
  int maxRows() const override { return 0; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;
  /// Fraction (0, 1] of the datasheet limit.
  void setScale(double scale) { scale_ = scale; }
  double scale() const { return scale_; }

 private:
  std::string name_;
  Vector7 a_max_;
  double scale_;
};

}  // namespace handover::control
