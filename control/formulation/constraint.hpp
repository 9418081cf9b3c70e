// A constraint adds two-sided inequality rows lb <= C chi <= ub over the fixed
// variable layout (VariableLayout), and/or tightens the variable bounds.
// Real-time safe: compute() must not allocate.
#pragma once

#include <string>

#include "control/formulation/control_context.hpp"

namespace handover::control {

class Constraint {
 public:
  virtual ~Constraint() = default;
  virtual const std::string& name() const = 0;
  /// Most rows compute() may ever write (reserved once by the formulation).
  virtual int maxRows() const = 0;
  /// Whether the QP may relax these rows, by the least amount, when the rows
  /// cannot all hold (SoftRowRelaxation). Hard by default: limits the arm
  /// physically has. Soft: rows that protect against a world the robot does
  /// not control (a person may move into it faster than it can escape).
  virtual bool soft() const { return false; }
  /// Writes up to maxRows() rows into C (maxRows() x kNumVars), lb, ub and
  /// returns how many it used. May also tighten chi_lb / chi_ub (never loosen).
  virtual int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C,
                      Eigen::Ref<Eigen::VectorXd> lb, Eigen::Ref<Eigen::VectorXd> ub,
                      Eigen::Ref<Eigen::VectorXd> chi_lb, Eigen::Ref<Eigen::VectorXd> chi_ub) = 0;
};

}  // namespace handover::control
