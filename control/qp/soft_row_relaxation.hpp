// When the rows of a QP cannot all hold, relax its soft rows (QpProblem::
// soft_in) by the least common amount and solve again: a lexicographic
// solve, the constraint violation first, the cost second.
//
//   phase 1:  min_{x, s}  1/2 s^2 + 1/2 eps ||x||^2
//             s.t.  hard rows and bounds as given,
//                   c_lb - s <= C x <= c_ub + s   on every soft row,  s >= 0
//   phase 2:  the original problem with every soft row widened by s* (the
//             phase-1 optimum, plus a hair for round-off); phase 1's x is
//             feasible for it, so it has a solution whenever phase 1 had one.
//
// One shared s minimises the largest violation: with soft collision rows
// (units m/s^2 along each pair's normal) no pair gives up more than the
// others. Why not a penalty in one solve: a finite penalty weight trades
// violation against the tasks and violates the rows a little on every
// cycle they bind; the two phases keep the solution exact when the
// problem is feasible (this runs only after the hard solve failed).
//
// Real-time safe after reserve(): no allocation, two bounded solves.
#pragma once

#include <Eigen/Core>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_solver.hpp"

namespace handover::control {

class SoftRowRelaxation {
 public:
  /// Sizes the two phase problems for up to num_vars variables and the given
  /// row capacities (allocates; start-up). The solver passed to solve() must
  /// be reserved for num_vars + 1 variables and 2 x capacity_in rows.
  void reserve(int num_vars, int capacity_eq, int capacity_in);
  /// Variables and rows the solver must be reserved for.
  static int solverVars(int num_vars) { return num_vars + 1; }
  static int solverRowsIn(int capacity_in) { return 2 * capacity_in; }

  /// Solves `problem` with its soft rows relaxed (see above). On kOptimal, x
  /// (size problem.n) satisfies every hard row and bound and every soft row
  /// widened by slack(). Resets the solver's warm start. Real-time safe.
  QpStatus solve(const QpProblem& problem, QpSolver& solver, Eigen::VectorXd& x);

  /// Widening used by the last successful solve (>= 0, units of the rows).
  double slack() const { return slack_; }
  /// Solver iterations of both phases of the last solve.
  int iterations() const { return iterations_; }

  /// Weight eps of ||x||^2 in phase 1 (keeps its Hessian positive definite).
  static constexpr double kPhaseOneRegularisation = 1e-8;

 private:
  QpProblem phase1_;
  QpProblem phase2_;
  Eigen::VectorXd x1_;
  double slack_ = 0.0;
  int iterations_ = 0;
};

}  // namespace handover::control
