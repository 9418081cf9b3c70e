#include "control/qp/soft_row_relaxation.hpp"

#include <limits>

namespace handover::control {

void SoftRowRelaxation::reserve(int num_vars, int capacity_eq, int capacity_in) {
  phase1_.reserve(solverVars(num_vars), capacity_eq, solverRowsIn(capacity_in));
  phase2_.reserve(num_vars, capacity_eq, capacity_in);
  x1_.setZero(solverVars(num_vars));
  slack_ = 0.0;
  iterations_ = 0;
}

QpStatus SoftRowRelaxation::solve(const QpProblem& problem, QpSolver& solver, Eigen::VectorXd& x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  iterations_ = 0;
  const int n = problem.n;
  if (n != phase2_.n || problem.n_eq > phase2_.capacityEq() || problem.n_in > phase2_.capacityIn())
    return QpStatus::kInvalidProblem;

  // phase 1: the least common widening s of the soft rows
  QpProblem& p1 = phase1_;
  p1.H.setZero();
  p1.H.diagonal().head(n).setConstant(kPhaseOneRegularisation);
  p1.H(n, n) = 1.0;
  p1.g.setZero();
  p1.n_eq = problem.n_eq;
  if (problem.n_eq > 0) {
    p1.A_eq.topLeftCorner(problem.n_eq, n) = problem.A_eq.topRows(problem.n_eq);
    p1.A_eq.col(n).head(problem.n_eq).setZero();
    p1.b_eq.head(problem.n_eq) = problem.b_eq.head(problem.n_eq);
  }
  int rows = 0;
  auto addRow = [&](int i, double s_coeff, double lb, double ub) {
    p1.C.row(rows).head(n) = problem.C.row(i);
    p1.C(rows, n) = s_coeff;
    p1.c_lb[rows] = lb;
    p1.c_ub[rows] = ub;
    ++rows;
  };
  for (int i = 0; i < problem.n_in; ++i) {
    const double lb = problem.c_lb[i];
    const double ub = problem.c_ub[i];
    if (problem.soft_in[i] == 0) {
      addRow(i, 0.0, lb, ub);
      continue;
    }
    if (hasLowerSide(lb)) addRow(i, 1.0, lb, kInf);    // C x + s >= lb
    if (hasUpperSide(ub)) addRow(i, -1.0, -kInf, ub);  // C x - s <= ub
  }
  p1.n_in = rows;
  p1.x_lb.head(n) = problem.x_lb;
  p1.x_ub.head(n) = problem.x_ub;
  p1.x_lb[n] = 0.0;
  p1.x_ub[n] = kInf;

  solver.resetWarmStart();
  const QpStatus s1 = solver.solve(p1, x1_);
  iterations_ += solver.result().iterations;
  if (s1 != QpStatus::kOptimal || !x1_.allFinite()) {
    solver.resetWarmStart();
    return s1 == QpStatus::kOptimal ? QpStatus::kInvalidProblem : s1;
  }
  // a hair more than phase 1 needed, so its x stays strictly admissible
  const double widen = x1_[n] * (1.0 + 1e-9) + 1e-9;

  // phase 2: the original cost, the soft rows widened by s*
  QpProblem& p2 = phase2_;
  p2.H = problem.H;
  p2.g = problem.g;
  p2.n_eq = problem.n_eq;
  if (problem.n_eq > 0) {
    p2.A_eq.topRows(problem.n_eq) = problem.A_eq.topRows(problem.n_eq);
    p2.b_eq.head(problem.n_eq) = problem.b_eq.head(problem.n_eq);
  }
  p2.n_in = problem.n_in;
  p2.C.topRows(problem.n_in) = problem.C.topRows(problem.n_in);
  for (int i = 0; i < problem.n_in; ++i) {
    double lb = problem.c_lb[i];
    double ub = problem.c_ub[i];
    if (problem.soft_in[i] != 0) {
      if (hasLowerSide(lb)) lb -= widen;
      if (hasUpperSide(ub)) ub += widen;
    }
    p2.c_lb[i] = lb;
    p2.c_ub[i] = ub;
  }
  p2.soft_in.head(problem.n_in) = problem.soft_in.head(problem.n_in);
  p2.x_lb = problem.x_lb;
  p2.x_ub = problem.x_ub;

  solver.resetWarmStart();
  const QpStatus s2 = solver.solve(p2, x);
  iterations_ += solver.result().iterations;
  if (s2 != QpStatus::kOptimal) return s2;
  slack_ = widen;
  return s2;
}

}  // namespace handover::control
