// The interface the controller uses to solve its QP every cycle, so the
// solver can be swapped without touching the formulation.
//
// Usage: reserve() once with the largest sizes (allocates), then solve() every
// cycle. solve() is real-time safe (no allocation, bounded work) as long as
// the problem fits the reserved sizes and x already has size n.
#pragma once

#include <Eigen/Core>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_result.hpp"

namespace handover::control {

struct QpSolverOptions {
  /// Dual active-set changes allowed per solve before giving up with kMaxIterations.
  int max_iterations = 1000;
  /// Relative primal tolerance: a side n'x >= b counts as violated when
  /// n'x - b < -tolerance * (|n| + |b|). Also the width under which
  /// c_lb, c_ub (x_lb, x_ub) count as equal.
  double tolerance = 1e-11;
  /// Seed each solve with the previous optimal active set.
  bool warm_start = true;
};

/// Throws InputError naming the option when a value is out of range.
void validate(const QpSolverOptions& options);

class QpSolver {
 public:
  virtual ~QpSolver() = default;
  /// Sizes all workspace for up to num_vars variables and the given row
  /// capacities (allocates; not real-time safe). Forgets the warm start.
  /// Throws InputError on negative sizes.
  virtual void reserve(int num_vars, int capacity_eq, int capacity_in) = 0;
  /// Solves `problem`; writes x (size problem.n; resized only if it differs)
  /// and result(). Never throws; failures are reported in the status. When
  /// the status is not kOptimal, x is the last iterate (zero for invalid
  /// problems) and must not be applied as a command.
  /// Real-time safe after reserve().
  virtual QpStatus solve(const QpProblem& problem, Eigen::VectorXd& x) = 0;
  virtual const QpResult& result() const = 0;
  /// Throws InputError for invalid options (see validate()).
  virtual void setOptions(const QpSolverOptions& options) = 0;
  virtual const QpSolverOptions& options() const = 0;
  /// Makes the next solve a cold start.
  virtual void resetWarmStart() = 0;
};

}  // namespace handover::control
