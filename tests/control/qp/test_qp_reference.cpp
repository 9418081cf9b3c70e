// Independent check of optimality for small problems: enumerate every set of
// constraint sides that could be active, solve its equality-constrained KKT
// system with a dense LU, and keep the best point that satisfies all
// constraints. For a strictly convex QP that point is the unique optimum (the
// optimum always has a linearly independent active subset), and no feasible
// point at all means the problem is infeasible. No code is shared with the
// solver or with the KKT checker.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "control/qp/goldfarb_idnani.hpp"

namespace handover::control {
namespace {

struct Side {
  Eigen::RowVectorXd a;  // a x >= b, or a x = b when equality
  double b;
  bool equality;
};

std::vector<Side> sidesOf(const QpProblem& p) {
  std::vector<Side> s;
  const int n = p.n;
  for (int i = 0; i < p.n_eq; ++i) s.push_back({p.A_eq.row(i), p.b_eq[i], true});
  for (int i = 0; i < p.n_in; ++i) {
    if (p.c_lb[i] > -kQpInfinity) s.push_back({p.C.row(i), p.c_lb[i], false});
    if (p.c_ub[i] < kQpInfinity) s.push_back({-p.C.row(i), -p.c_ub[i], false});
  }
  for (int j = 0; j < n; ++j) {
    Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(n);
    e[j] = 1.0;
    if (p.x_lb[j] > -kQpInfinity) s.push_back({e, p.x_lb[j], false});
    if (p.x_ub[j] < kQpInfinity) s.push_back({-e, -p.x_ub[j], false});
  }
  return s;
}

/// Returns false when no subset yields a feasible point.
bool bruteForce(const QpProblem& p, Eigen::VectorXd& x_best, double& f_best) {
  const std::vector<Side> sides = sidesOf(p);
  const int n = p.n;
  std::vector<int> eq, in;
  for (int k = 0; k < static_cast<int>(sides.size()); ++k)
    (sides[k].equality ? eq : in).push_back(k);
  const int m = static_cast<int>(in.size());
  bool found = false;
  for (long mask = 0; mask < (1L << m); ++mask) {
    std::vector<int> act = eq;
    for (int k = 0; k < m; ++k)
      if (mask & (1L << k)) act.push_back(in[k]);
    const int na = static_cast<int>(act.size());
    if (na > n) continue;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + na, n + na);
    Eigen::VectorXd rhs(n + na);
    K.topLeftCorner(n, n) = p.H;
    rhs.head(n) = -p.g;
    for (int r = 0; r < na; ++r) {
      K.block(n + r, 0, 1, n) = sides[act[r]].a;
      K.block(0, n + r, n, 1) = sides[act[r]].a.transpose();
      rhs[n + r] = sides[act[r]].b;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
    if (!lu.isInvertible()) continue;
    const Eigen::VectorXd x = lu.solve(rhs).head(n);
    bool feasible = true;
    for (const Side& s : sides) {
      const double v = s.a.dot(x) - s.b;
      const double tol = 1e-9 * (1.0 + std::abs(s.b) + s.a.norm() * x.cwiseAbs().maxCoeff());
      if (s.equality ? std::abs(v) > tol : v < -tol) {
        feasible = false;
        break;
      }
    }
    if (!feasible) continue;
    const double f = 0.5 * x.dot(p.H * x) + p.g.dot(x);
    if (!found || f < f_best) {
      found = true;
      f_best = f;
      x_best = x;
    }
  }
  return found;
}

void randomSmallProblem(std::mt19937& rng, QpProblem& p) {
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  std::uniform_int_distribution<int> nvar(1, 4);
  const int n = nvar(rng);
  const int n_eq = ud(rng) < 0.3 ? 1 : 0;
  const int n_in = std::uniform_int_distribution<int>(0, 3)(rng);
  p.reserve(n, 1, 3);
  p.n_eq = n_eq;
  p.n_in = n_in;
  Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return nd(rng); });
  p.H = M.transpose() * M + 0.2 * Eigen::MatrixXd::Identity(n, n);
  p.g = Eigen::VectorXd::NullaryExpr(n, [&] { return 4.0 * nd(rng); });
  for (int i = 0; i < n_eq; ++i) {
    for (int j = 0; j < n; ++j) p.A_eq(i, j) = nd(rng);
    p.b_eq[i] = nd(rng);
  }
  // no feasibility guarantee: some problems are infeasible on purpose
  for (int i = 0; i < n_in; ++i) {
    for (int j = 0; j < n; ++j) p.C(i, j) = nd(rng);
    const double lb = nd(rng);
    p.c_lb[i] = ud(rng) < 0.3 ? -kQpInfinity * 10 : lb;
    p.c_ub[i] = ud(rng) < 0.3 ? kQpInfinity * 10 : lb + 2.0 * ud(rng);
  }
  for (int j = 0; j < n; ++j) {
    const double lb = nd(rng);
    p.x_lb[j] = ud(rng) < 0.4 ? -std::numeric_limits<double>::infinity() : lb;
    p.x_ub[j] = ud(rng) < 0.4 ? std::numeric_limits<double>::infinity() : lb + 2.0 * ud(rng);
  }
}

TEST(QpReference, MatchesBruteForceOverActiveSets) {
  std::mt19937 rng(2024);
  GoldfarbIdnaniSolver solver;
  int optimal = 0, infeasible = 0;
  for (int trial = 0; trial < 600; ++trial) {
    QpProblem p;
    randomSmallProblem(rng, p);
    Eigen::VectorXd x_ref;
    double f_ref = 0.0;
    const bool feasible = bruteForce(p, x_ref, f_ref);
    solver.reserve(p.n, p.capacityEq(), p.capacityIn());
    Eigen::VectorXd x;
    const QpStatus st = solver.solve(p, x);
    SCOPED_TRACE(trial);
    if (!feasible) {
      EXPECT_EQ(st, QpStatus::kInfeasible);
      ++infeasible;
      continue;
    }
    ASSERT_EQ(st, QpStatus::kOptimal) << solver.result().message;
    ++optimal;
    const double xs = 1.0 + x_ref.cwiseAbs().maxCoeff();
    EXPECT_LE((x - x_ref).cwiseAbs().maxCoeff(), 1e-8 * xs);
    EXPECT_NEAR(solver.result().objective, f_ref, 1e-10 * (1.0 + std::abs(f_ref)));
  }
  // both outcomes must be exercised for the comparison to mean anything
  EXPECT_GT(optimal, 300);
  EXPECT_GT(infeasible, 20);
}

}  // namespace
}  // namespace handover::control
