// A task is a least-squares objective || A chi - b ||^2 over the fixed
// variable layout (VariableLayout). The formulation owns its weight; the
// task only fills its rows. Real-time safe: compute() must not allocate.
#pragma once

#include <string>

#include "control/formulation/control_context.hpp"

namespace handover::control {

class Task {
 public:
  virtual ~Task() = default;
  virtual const std::string& name() const = 0;
  /// Number of rows (fixed for the task's lifetime).
  virtual int rows() const = 0;
  /// Fills A (rows() x kNumVars) and b (rows()) so that the task wants A chi = b.
  virtual void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
                       Eigen::Ref<Eigen::VectorXd> b) = 0;
};

}  // namespace handover::control
