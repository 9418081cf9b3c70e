// Joint torque limits through the equation of motion tau = M qddot + h
// (Data::M and Data::h include the payload):
//   -s tau_max - h <= M qddot <= s tau_max - h      (7 rows over qddot)
// s = scale (default 1: the datasheet Model::tau_max). Real-time safe.
#pragma once

#include <string>

#include "control/formulation/constraint.hpp"

namespace handover::control {

class JointTorqueLimit : public Constraint {
 public:
  JointTorqueLimit(const Model& model, double scale = 1.0, std::string name = "joint_torque");
  const std::string& name() const override { return name_; }
  int maxRows() const override { return kArmDofs; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;
  void setScale(double scale) { scale_ = scale; }
  double scale() const { return scale_; }

 private:
  std::string name_;
  Vector7 tau_max_;
  double scale_;
};

}  // namespace handover::control
