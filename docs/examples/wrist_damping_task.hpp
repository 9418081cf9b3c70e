// Example task (docs/architecture.md): damp the wrist joint's velocity,
// qddot_7 = -d qdot_7, as one least-squares row over the QP's variables.
#pragma once

#include <string>

#include "control/formulation/task.hpp"

namespace handover::examples {

class WristDampingTask : public control::Task {
 public:
  explicit WristDampingTask(double damping) : damping_(damping) {}
  const std::string& name() const override { return name_; }
  int rows() const override { return 1; }
  void compute(const control::ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
               Eigen::Ref<Eigen::VectorXd> b) override {
    A.setZero();
    A(0, control::VariableLayout::kQdd + 6) = 1.0;  // qddot of joint 7
    b(0) = -damping_ * ctx.data->v[6];
    ++calls;
  }
  long calls = 0;  ///< cycles in which the QP asked for the rows

 private:
  std::string name_ = "wrist_damping";
  double damping_;  ///< 1/s
};

}  // namespace handover::examples
