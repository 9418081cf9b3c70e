#include "control/qp/qp_problem.hpp"

#include <limits>
#include <string>

#include "config/input_error.hpp"

namespace handover::control {

void QpProblem::reserve(int num_vars, int capacity_eq, int capacity_in) {
  if (num_vars < 1 || capacity_eq < 0 || capacity_in < 0) {
    throw InputError("QpProblem::reserve: invalid sizes (num_vars=" + std::to_string(num_vars) +
                     ", capacity_eq=" + std::to_string(capacity_eq) +
                     ", capacity_in=" + std::to_string(capacity_in) +
                     "); need num_vars >= 1 and capacities >= 0");
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  n = num_vars;
  n_eq = 0;
  n_in = 0;
  H.setZero(num_vars, num_vars);
  g.setZero(num_vars);
  A_eq.setZero(capacity_eq, num_vars);
  b_eq.setZero(capacity_eq);
  C.setZero(capacity_in, num_vars);
  c_lb.setConstant(capacity_in, -kInf);
  c_ub.setConstant(capacity_in, kInf);
  x_lb.setConstant(num_vars, -kInf);
  x_ub.setConstant(num_vars, kInf);
  soft_in.setZero(capacity_in);
}

const char* toString(QpStatus status) {
  switch (status) {
    case QpStatus::kOptimal: return "optimal";
    case QpStatus::kInfeasible: return "infeasible";
    case QpStatus::kMaxIterations: return "max_iterations";
    case QpStatus::kInvalidProblem: return "invalid_problem";
  }
  return "unknown";
}

}  // namespace handover::control
