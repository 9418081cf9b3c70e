#include "control/constraints/joint_acceleration_limit.hpp"

#include "control/constraints/bound_tightening.hpp"

namespace handover::control {

JointAccelerationLimit::JointAccelerationLimit(const Model& model, double scale, std::string name)
    : name_(std::move(name)), a_max_(model.a_max), scale_(scale) {}

int JointAccelerationLimit::compute(const ControlContext&, Eigen::Ref<Eigen::MatrixXd>, Eigen::Ref<Eigen::VectorXd>,
                                    Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> chi_lb,
                                    Eigen::Ref<Eigen::VectorXd> chi_ub) {
  for (int i = 0; i < kArmDofs; ++i) {
    const double a = scale_ * a_max_[i];
    tightenBounds(chi_lb, chi_ub, VariableLayout::kQdd + i, -a, a);
  }
  return 0;
}

}  // namespace handover::control
