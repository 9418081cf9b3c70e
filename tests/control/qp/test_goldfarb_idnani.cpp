// Goldfarb-Idnani solver: optimality by KKT on random problems, degenerate
// cases, infeasibility, invalid input, iteration limit and warm start.
#include "control/qp/goldfarb_idnani.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/input_error.hpp"
#include "tests/control/qp/qp_test_problems.hpp"

namespace handover::control {
namespace {

using test::kInfinity;
using test::kktResiduals;
using test::makeRandomQp;
using test::RandomQpSpec;

constexpr double kKktTol = 1e-9;

QpStatus solveFresh(const QpProblem& p, Eigen::VectorXd& x, GoldfarbIdnaniSolver& s) {
  s.reserve(p.n, p.capacityEq(), p.capacityIn());
  return s.solve(p, x);
}

void expectKkt(const QpProblem& p, const Eigen::VectorXd& x, const QpResult& r) {
  const test::KktResiduals k = kktResiduals(p, x, r);
  EXPECT_LE(k.stationarity, kKktTol);
  EXPECT_LE(k.primal, kKktTol);
  EXPECT_LE(k.dual, kKktTol);
  EXPECT_LE(k.complementarity, kKktTol);
  // every reported active side really holds with equality
  for (const QpActiveRow& a : r.active) {
    double value = 0.0, target = 0.0, scale = 1.0;
    switch (a.kind) {
      case QpRowKind::kEquality:
        value = p.A_eq.row(a.index).dot(x), target = p.b_eq[a.index];
        scale = 1.0 + std::abs(target) + p.A_eq.row(a.index).norm() * x.cwiseAbs().maxCoeff();
        break;
      case QpRowKind::kRowLower:
      case QpRowKind::kRowFixed:
      case QpRowKind::kRowUpper:
        value = p.C.row(a.index).dot(x);
        target = a.kind == QpRowKind::kRowUpper ? p.c_ub[a.index] : p.c_lb[a.index];
        scale = 1.0 + std::abs(target) + p.C.row(a.index).norm() * x.cwiseAbs().maxCoeff();
        break;
      case QpRowKind::kBoundLower:
      case QpRowKind::kBoundFixed:
      case QpRowKind::kBoundUpper:
        value = x[a.index];
        target = a.kind == QpRowKind::kBoundUpper ? p.x_ub[a.index] : p.x_lb[a.index];
        scale = 1.0 + std::abs(target);
        break;
    }
    EXPECT_LE(std::abs(value - target) / scale, kKktTol) << toString(a.kind) << " " << a.index;
  }
  EXPECT_LE(static_cast<int>(r.active.size()), p.n);
  const double obj = 0.5 * x.dot(p.H * x) + p.g.dot(x);
  EXPECT_NEAR(r.objective, obj, 1e-12 * (1.0 + std::abs(obj)));
}

// ------------------------------------------------------------------ random

struct SizeCase {
  int n, n_eq, n_in;
  bool bounds;
  int seeds;
};

class RandomKkt : public ::testing::TestWithParam<SizeCase> {};

TEST_P(RandomKkt, SatisfiesKktConditions) {
  const SizeCase c = GetParam();
  GoldfarbIdnaniSolver solver;
  int total_active = 0;
  for (int seed = 0; seed < c.seeds; ++seed) {
    std::mt19937 rng(1000 * c.n + seed);
    RandomQpSpec spec;
    spec.n = c.n;
    spec.n_eq = c.n_eq;
    spec.n_in = c.n_in;
    spec.bounds = c.bounds;
    QpProblem p;
    makeRandomQp(spec, rng, p);
    Eigen::VectorXd x;
    ASSERT_EQ(solveFresh(p, x, solver), QpStatus::kOptimal)
        << "seed " << seed << ": " << solver.result().message;
    SCOPED_TRACE(seed);
    expectKkt(p, x, solver.result());
    total_active += static_cast<int>(solver.result().active.size());
  }
  // the generator must really produce constrained optima, not trivial ones
  EXPECT_GE(total_active, c.seeds * std::min(c.n, c.n_eq + 1) / 2);
}

INSTANTIATE_TEST_SUITE_P(Sizes, RandomKkt,
                         ::testing::Values(SizeCase{1, 0, 2, true, 50}, SizeCase{2, 0, 4, true, 100},
                                           SizeCase{5, 2, 10, true, 100},
                                           SizeCase{8, 0, 20, false, 100},
                                           SizeCase{13, 7, 40, true, 200},
                                           SizeCase{13, 0, 40, true, 100},
                                           SizeCase{20, 5, 60, true, 50},
                                           SizeCase{13, 13, 0, false, 20}));

// Badly scaled data: weighted task terms (weights 1e3 .. 1e-6, condition
// number ~1e10 like the controller's H with a tiny regularisation) and rows
// scaled by 1e-3 .. 1e3. The relative KKT residuals must stay as small.
TEST(GoldfarbIdnani, BadlyScaledProblemsStillSatisfyKkt) {
  GoldfarbIdnaniSolver solver;
  for (int seed = 0; seed < 100; ++seed) {
    std::mt19937 rng(7000 + seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    RandomQpSpec spec;
    spec.n = 13;
    spec.n_eq = seed % 4;
    spec.n_in = 30;
    QpProblem p;
    makeRandomQp(spec, rng, p);
    Eigen::MatrixXd Jt = Eigen::MatrixXd::NullaryExpr(6, 13, [&] { return nd(rng); });
    Eigen::MatrixXd Jo = Eigen::MatrixXd::Zero(6, 13);
    Jo.rightCols(6).setIdentity();
    Eigen::MatrixXd Jp = Eigen::MatrixXd::Zero(7, 13);
    Jp.leftCols(7).setIdentity();
    p.H = 1000.0 * Jt.transpose() * Jt + Jo.transpose() * Jo + 5.0 * Jp.transpose() * Jp;
    p.H.diagonal().array() += 1e-6;
    p.g *= 100.0;
    const double row_scale = std::pow(10.0, (seed % 7) - 3);  // 1e-3 .. 1e3
    for (int i = 0; i < p.n_in; ++i) {
      const double f = i % 2 ? row_scale : 1.0 / row_scale;
      p.C.row(i) *= f;
      p.c_lb[i] *= f;
      p.c_ub[i] *= f;
    }
    Eigen::VectorXd x;
    solver.reserve(p.n, p.capacityEq(), p.capacityIn());
    ASSERT_EQ(solver.solve(p, x), QpStatus::kOptimal) << seed << " " << solver.result().message;
    SCOPED_TRACE(seed);
    expectKkt(p, x, solver.result());
  }
}

// H with eigenvalues spread over eight decades: the iterate accumulates
// errors of order eps * cond(H), which the final refinement step must remove.
TEST(GoldfarbIdnani, IllConditionedHessianStillSatisfiesKkt) {
  GoldfarbIdnaniSolver solver;
  for (int seed = 0; seed < 200; ++seed) {
    std::mt19937 rng(9100 + seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    RandomQpSpec spec;
    spec.n = 2 + seed % 12;
    spec.n_eq = seed % 3;
    spec.n_in = 25;
    QpProblem p;
    makeRandomQp(spec, rng, p);
    const int n = spec.n;
    Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return nd(rng); });
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(M).householderQ();
    Eigen::VectorXd ev(n);
    for (int j = 0; j < n; ++j) ev[j] = std::pow(10.0, -4.0 + 8.0 * j / (n - 1));
    p.H = Q * ev.asDiagonal() * Q.transpose();
    p.H = (0.5 * (p.H + p.H.transpose())).eval();
    Eigen::VectorXd x;
    solver.reserve(p.n, p.capacityEq(), p.capacityIn());
    ASSERT_EQ(solver.solve(p, x), QpStatus::kOptimal) << seed << " " << solver.result().message;
    SCOPED_TRACE(seed);
    expectKkt(p, x, solver.result());
  }
}

// ------------------------------------------------------------------ degenerate

QpProblem smallProblem(int n, int cap_eq, int cap_in) {
  QpProblem p;
  p.reserve(n, cap_eq, cap_in);
  p.H.setIdentity();
  return p;
}

TEST(GoldfarbIdnani, UnconstrainedMinimum) {
  QpProblem p = smallProblem(3, 0, 0);
  p.H.diagonal() << 2.0, 4.0, 8.0;
  p.g << 2.0, -4.0, 8.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  EXPECT_NEAR(x[0], -1.0, 1e-14);
  EXPECT_NEAR(x[1], 1.0, 1e-14);
  EXPECT_NEAR(x[2], -1.0, 1e-14);
  EXPECT_TRUE(s.result().active.empty());
  EXPECT_EQ(s.result().iterations, 0);
}

TEST(GoldfarbIdnani, RedundantEqualityRows) {
  std::mt19937 rng(7);
  RandomQpSpec spec;
  spec.n = 6;
  spec.n_eq = 3;
  spec.n_in = 8;
  QpProblem base;
  makeRandomQp(spec, rng, base);
  QpProblem p;
  p.reserve(6, 6, 8);
  p.H = base.H;
  p.g = base.g;
  p.x_lb = base.x_lb;
  p.x_ub = base.x_ub;
  p.n_in = 8;
  p.C.topRows(8) = base.C.topRows(8);
  p.c_lb.head(8) = base.c_lb.head(8);
  p.c_ub.head(8) = base.c_ub.head(8);
  // rows 0..2 independent; 3 = 0 + 1; 4 = 2 * row 2; 5 = row 0 again
  p.n_eq = 6;
  p.A_eq.topRows(3) = base.A_eq.topRows(3);
  p.b_eq.head(3) = base.b_eq.head(3);
  p.A_eq.row(3) = p.A_eq.row(0) + p.A_eq.row(1);
  p.b_eq[3] = p.b_eq[0] + p.b_eq[1];
  p.A_eq.row(4) = 2.0 * p.A_eq.row(2);
  p.b_eq[4] = 2.0 * p.b_eq[2];
  p.A_eq.row(5) = p.A_eq.row(0);
  p.b_eq[5] = p.b_eq[0];
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  expectKkt(p, x, s.result());
  // same optimum as without the redundant rows
  Eigen::VectorXd x_ref;
  GoldfarbIdnaniSolver s_ref;
  p.n_eq = 3;
  ASSERT_EQ(solveFresh(p, x_ref, s_ref), QpStatus::kOptimal);
  EXPECT_LE((x - x_ref).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + x_ref.cwiseAbs().maxCoeff()));
}

TEST(GoldfarbIdnani, ParallelAndDuplicateInequalityRows) {
  // minimise |x - (3, 3)|^2 subject to several copies of x0 + x1 <= 2 (scaled,
  // duplicated, and one slightly looser), and x0 - x1 <= 0 twice
  QpProblem p = smallProblem(2, 0, 6);
  p.g << -3.0, -3.0;
  p.n_in = 6;
  p.C.row(0) << 1.0, 1.0;  p.c_ub[0] = 2.0;
  p.C.row(1) << 1.0, 1.0;  p.c_ub[1] = 2.0;
  p.C.row(2) << 3.0, 3.0;  p.c_ub[2] = 6.0;
  p.C.row(3) << -1.0, -1.0; p.c_lb[3] = -2.0 - 1e-6;  // lower side, looser
  p.C.row(4) << 1.0, -1.0; p.c_ub[4] = 0.0;
  p.C.row(5) << -2.0, 2.0; p.c_lb[5] = 0.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  EXPECT_NEAR(x[0], 1.0, 1e-12);
  EXPECT_NEAR(x[1], 1.0, 1e-12);
  expectKkt(p, x, s.result());
  EXPECT_EQ(s.result().active.size(), 1u);  // only one copy can be independent
}

TEST(GoldfarbIdnani, OppositeRowsFormingAnEquality) {
  // x0 + x1 <= 1 and -(x0 + x1) <= -1 pin x0 + x1 = 1 without being one row
  QpProblem p = smallProblem(2, 0, 2);
  p.g << -5.0, 1.0;
  p.n_in = 2;
  p.C.row(0) << 1.0, 1.0;   p.c_ub[0] = 1.0;
  p.C.row(1) << -1.0, -1.0; p.c_ub[1] = -1.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  EXPECT_NEAR(x[0] + x[1], 1.0, 1e-12);
  // optimum on the line: minimise 1/2|x|^2 + g'x with x1 = 1 - x0 -> x0 = 3.5
  EXPECT_NEAR(x[0], 3.5, 1e-12);
  expectKkt(p, x, s.result());
}

TEST(GoldfarbIdnani, ZeroWidthBoundsAndRowsActAsEqualities) {
  std::mt19937 rng(11);
  RandomQpSpec spec;
  spec.n = 7;
  spec.n_eq = 1;
  spec.n_in = 12;
  QpProblem p;
  makeRandomQp(spec, rng, p);
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  // fix variable 2 and row 5 at values away from the optimum but feasible:
  // a point between the optimum and a feasible interior-ish point
  const Eigen::VectorXd x_first = x;
  p.g = -p.g;  // a different optimum, still feasible for the same constraints
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  const Eigen::VectorXd x_mid = 0.5 * (x + x_first);  // feasible (convex set)
  p.g = -p.g;
  p.x_lb[2] = p.x_ub[2] = x_mid[2];
  const double v = p.C.row(5).dot(x_mid);
  p.c_lb[5] = p.c_ub[5] = v;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << s.result().message;
  EXPECT_NEAR(x[2], p.x_lb[2], 1e-12 * (1.0 + std::abs(p.x_lb[2])));
  EXPECT_NEAR(p.C.row(5).dot(x), v, 1e-12 * (1.0 + std::abs(v)));
  expectKkt(p, x, s.result());
  bool fixed_row = false, fixed_bound = false;
  for (const QpActiveRow& a : s.result().active) {
    fixed_row |= a.kind == QpRowKind::kRowFixed && a.index == 5;
    fixed_bound |= a.kind == QpRowKind::kBoundFixed && a.index == 2;
  }
  EXPECT_TRUE(fixed_row);
  EXPECT_TRUE(fixed_bound);
}

// n sides meet at one vertex, plus extra sides through the same vertex
// (primal degeneracy): the optimum is that vertex with n independent active sides.
TEST(GoldfarbIdnani, FullyActiveDegenerateVertex) {
  for (int seed = 0; seed < 30; ++seed) {
    std::mt19937 rng(500 + seed);
    std::normal_distribution<double> nd(0.0, 1.0);
    std::uniform_real_distribution<double> ud(0.5, 2.0);
    const int n = 13, extra = 6;
    QpProblem p;
    p.reserve(n, 0, n + extra);
    Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return nd(rng); });
    p.H = M.transpose() * M + Eigen::MatrixXd::Identity(n, n);
    Eigen::VectorXd xs = Eigen::VectorXd::NullaryExpr(n, [&] { return nd(rng); });
    Eigen::VectorXd y(n);
    p.n_in = n + extra;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) p.C(i, j) = nd(rng);
      p.c_lb[i] = p.C.row(i).dot(xs);
      y[i] = -ud(rng);  // lower side active with a strictly negative multiplier
    }
    for (int i = n; i < n + extra; ++i) {
      // a positive combination of two vertex rows: active at xs, never binding alone
      const int a = i - n, b = (i - n + 1) % n;
      p.C.row(i) = ud(rng) * p.C.row(a) + ud(rng) * p.C.row(b);
      p.c_lb[i] = p.C.row(i).dot(xs);
    }
    p.g = -p.H * xs - p.C.topRows(n).transpose() * y;
    GoldfarbIdnaniSolver s;
    Eigen::VectorXd x;
    ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal) << seed << " " << s.result().message;
    SCOPED_TRACE(seed);
    EXPECT_LE((x - xs).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + xs.cwiseAbs().maxCoeff()));
    EXPECT_EQ(static_cast<int>(s.result().active.size()), n);
    expectKkt(p, x, s.result());
    // with all n sides active, a new side that cuts the vertex off must
    // first push an active one out (the dependent-normal path)
    QpProblem cut;
    cut.reserve(n, 0, n + extra + 1);
    cut.H = p.H;
    cut.g = p.g;
    cut.n_in = n + extra + 1;
    cut.C.topRows(n + extra) = p.C.topRows(n + extra);
    cut.c_lb.head(n + extra) = p.c_lb.head(n + extra);
    cut.C.row(n + extra) = p.C.row(0) + 0.3 * p.C.row(1);
    cut.c_lb[n + extra] = cut.C.row(n + extra).dot(xs) + 0.1;
    ASSERT_EQ(solveFresh(cut, x, s), QpStatus::kOptimal) << seed << " " << s.result().message;
    expectKkt(cut, x, s.result());
  }
}

TEST(GoldfarbIdnani, AllBoundsActive) {
  const int n = 13;
  QpProblem p = smallProblem(n, 0, 0);
  for (int j = 0; j < n; ++j) {
    p.H(j, j) = 1.0 + j;
    p.g[j] = (j % 2 ? 100.0 : -100.0);
    p.x_lb[j] = -1.0;
    p.x_ub[j] = 1.0;
  }
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  for (int j = 0; j < n; ++j) EXPECT_NEAR(x[j], j % 2 ? -1.0 : 1.0, 1e-12);
  EXPECT_EQ(static_cast<int>(s.result().active.size()), n);
  expectKkt(p, x, s.result());
}

TEST(GoldfarbIdnani, InfiniteSidesAreIgnored) {
  QpProblem p = smallProblem(2, 0, 3);
  p.g << -4.0, -4.0;
  p.n_in = 3;
  p.C.row(0) << 1.0, 0.0;  // both sides infinite: no constraint
  p.C.row(1) << 0.0, 1.0;  p.c_lb[1] = -1e30; p.c_ub[1] = 1e25;  // beyond kQpInfinity
  p.C.row(2) << 1.0, 1.0;  p.c_ub[2] = 2.0;  // only an upper side
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  EXPECT_NEAR(x[0], 1.0, 1e-12);
  EXPECT_NEAR(x[1], 1.0, 1e-12);
  ASSERT_EQ(s.result().active.size(), 1u);
  EXPECT_EQ(s.result().active[0].kind, QpRowKind::kRowUpper);
  EXPECT_EQ(s.result().active[0].index, 2);
  EXPECT_GT(s.result().y_in[2], 0.0);  // upper side: positive multiplier
  expectKkt(p, x, s.result());
}

TEST(GoldfarbIdnani, MultiplierSignsFollowTheConvention) {
  // pull x0 down against a lower bound and x1 up against a row's upper side
  QpProblem p = smallProblem(2, 1, 1);
  p.g << 5.0, -5.0;
  p.x_lb[0] = 1.0;
  p.n_in = 1;
  p.C.row(0) << 0.0, 2.0;  p.c_lb[0] = -3.0; p.c_ub[0] = 2.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  EXPECT_NEAR(x[0], 1.0, 1e-12);
  EXPECT_NEAR(x[1], 1.0, 1e-12);
  // stationarity by hand: x0 + 5 + y_x0 = 0 -> y_x0 = -6; x1 - 5 + 2 y_in = 0 -> y_in = 2
  EXPECT_NEAR(s.result().y_x[0], -6.0, 1e-12);
  EXPECT_NEAR(s.result().y_in[0], 2.0, 1e-12);
  EXPECT_EQ(s.result().y_x[1], 0.0);
}

// ------------------------------------------------------------------ infeasible

TEST(GoldfarbIdnani, ContradictingBoundsAreInfeasible) {
  QpProblem p = smallProblem(3, 0, 0);
  p.x_lb[1] = 2.0;
  p.x_ub[1] = 1.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  EXPECT_EQ(solveFresh(p, x, s), QpStatus::kInfeasible);
  EXPECT_STRNE(s.result().message, "");
}

TEST(GoldfarbIdnani, ContradictingRowsAreInfeasible) {
  // x0 + x1 >= 2 (row 0) and 2 x0 + 2 x1 <= 2 (row 1): parallel, no overlap
  QpProblem p = smallProblem(2, 0, 2);
  p.n_in = 2;
  p.C.row(0) << 1.0, 1.0;  p.c_lb[0] = 2.0;
  p.C.row(1) << 2.0, 2.0;  p.c_ub[1] = 2.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  EXPECT_EQ(solveFresh(p, x, s), QpStatus::kInfeasible);
  // a row whose own sides contradict
  QpProblem p2 = smallProblem(2, 0, 1);
  p2.n_in = 1;
  p2.C.row(0) << 1.0, -1.0;  p2.c_lb[0] = 1.0; p2.c_ub[0] = 0.5;
  EXPECT_EQ(solveFresh(p2, x, s), QpStatus::kInfeasible);
}

TEST(GoldfarbIdnani, NonParallelInfeasibleSetIsDetected) {
  // x0 >= 1, x1 >= 1 (bounds) and x0 + x1 <= 1.5, plus a slack row
  QpProblem p = smallProblem(3, 0, 2);
  p.g << 1.0, 2.0, -3.0;
  p.x_lb[0] = 1.0;
  p.x_lb[1] = 1.0;
  p.n_in = 2;
  p.C.row(0) << 1.0, 1.0, 0.0;  p.c_ub[0] = 1.5;
  p.C.row(1) << 0.0, 0.0, 1.0;  p.c_ub[1] = 10.0;
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  EXPECT_EQ(solveFresh(p, x, s), QpStatus::kInfeasible);
}

TEST(GoldfarbIdnani, InfeasibleEqualitySystems) {
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  // x0 + x1 = 1 and x0 + x1 = 2
  QpProblem p = smallProblem(3, 2, 0);
  p.n_eq = 2;
  p.A_eq.row(0) << 1.0, 1.0, 0.0;  p.b_eq[0] = 1.0;
  p.A_eq.row(1) << 1.0, 1.0, 0.0;  p.b_eq[1] = 2.0;
  EXPECT_EQ(solveFresh(p, x, s), QpStatus::kInfeasible);
  // four equalities in three variables with no common solution
  QpProblem p2 = smallProblem(3, 4, 0);
  p2.n_eq = 4;
  p2.A_eq.topRows(3).setIdentity();
  p2.b_eq.head(3) << 1.0, 2.0, 3.0;
  p2.A_eq.row(3) << 1.0, 1.0, 1.0;  p2.b_eq[3] = 7.0;
  EXPECT_EQ(solveFresh(p2, x, s), QpStatus::kInfeasible);
  p2.b_eq[3] = 6.0;  // now consistent (redundant) -> optimal
  EXPECT_EQ(solveFresh(p2, x, s), QpStatus::kOptimal);
  EXPECT_NEAR(x[2], 3.0, 1e-12);
  // an equality against a bound
  QpProblem p3 = smallProblem(2, 1, 0);
  p3.n_eq = 1;
  p3.A_eq.row(0) << 1.0, 0.0;  p3.b_eq[0] = 5.0;
  p3.x_ub[0] = 1.0;
  EXPECT_EQ(solveFresh(p3, x, s), QpStatus::kInfeasible);
}

TEST(GoldfarbIdnani, RandomInfeasibleProblemsAreReported) {
  // a feasible random problem made infeasible by a row that excludes the
  // whole box: sum of x >= sum of upper bounds + 1
  for (int seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(900 + seed);
    RandomQpSpec spec;
    spec.n = 13;
    spec.n_eq = 0;
    spec.n_in = 20;
    spec.p_inf = 0.0;
    QpProblem p;
    makeRandomQp(spec, rng, p);
    p.C.row(19).setOnes();
    p.c_lb[19] = p.x_ub.sum() + 1.0;
    p.c_ub[19] = kInfinity;
    GoldfarbIdnaniSolver s;
    Eigen::VectorXd x;
    EXPECT_EQ(solveFresh(p, x, s), QpStatus::kInfeasible) << seed;
  }
}

// ------------------------------------------------------------------ invalid

TEST(GoldfarbIdnani, AControllerStepWithNearlyOppositeRowsIsNotCalledOptimal) {
  // Two soft collision rows whose normals differ by 1e-3 (the gripper straddling
  // a capsule) and the joints' acceleration bounds leave no feasible point. The
  // dual steps along the nearly dependent normal reached x ~ 1e14 whose rows and
  // bounds no longer held, and the solve said kOptimal: the controller integrated
  // that acceleration and its observed object flew off.
  QpProblem p;
  ASSERT_TRUE(test::loadQpText(test::nearlyInconsistentRowsFile(), p));
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x(p.n);
  const QpStatus status = solveFresh(p, x, s);
  if (status == QpStatus::kOptimal) {
    EXPECT_LE(test::largestViolation(p, x), 1e-6) << "an optimum that violates its rows";
  } else {
    EXPECT_EQ(status, QpStatus::kInfeasible);
  }
  // and it is infeasible indeed: rows 9 and 10 (both C x >= c_lb) need their
  // sum to reach c_lb[9] + c_lb[10], more than it can inside the bounds
  const Eigen::RowVectorXd sum = p.C.row(9) + p.C.row(10);
  double reach = 0.0;
  for (int j = 0; j < p.n; ++j) reach += std::abs(sum[j]) * std::max(std::abs(p.x_lb[j]), std::abs(p.x_ub[j]));
  EXPECT_LT(reach, p.c_lb[9] + p.c_lb[10]);
}

TEST(GoldfarbIdnani, InvalidInputsAreReported) {
  std::mt19937 rng(3);
  RandomQpSpec spec;
  spec.n = 4;
  spec.n_eq = 1;
  spec.n_in = 5;
  QpProblem good;
  makeRandomQp(spec, rng, good);
  GoldfarbIdnaniSolver s;
  s.reserve(4, 1, 5);
  Eigen::VectorXd x(4);
  ASSERT_EQ(s.solve(good, x), QpStatus::kOptimal);

  auto expectInvalid = [&](QpProblem p, const char* what) {
    EXPECT_EQ(s.solve(p, x), QpStatus::kInvalidProblem) << what;
    EXPECT_STRNE(s.result().message, "") << what;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  { QpProblem p = good; p.H(1, 1) = nan; expectInvalid(p, "NaN in H"); }
  { QpProblem p = good; p.g[0] = nan; expectInvalid(p, "NaN in g"); }
  { QpProblem p = good; p.g[0] = kInfinity; expectInvalid(p, "inf in g"); }
  { QpProblem p = good; p.C(2, 3) = nan; expectInvalid(p, "NaN in C"); }
  { QpProblem p = good; p.c_lb[4] = nan; expectInvalid(p, "NaN in c_lb"); }
  { QpProblem p = good; p.A_eq(0, 0) = kInfinity; expectInvalid(p, "inf in A_eq"); }
  { QpProblem p = good; p.b_eq[0] = nan; expectInvalid(p, "NaN in b_eq"); }
  { QpProblem p = good; p.x_ub[3] = nan; expectInvalid(p, "NaN in x_ub"); }
  { QpProblem p = good; p.H(0, 0) = -1.0; expectInvalid(p, "indefinite H"); }
  {
    QpProblem p = good;  // singular (rank one) H
    Eigen::VectorXd v = Eigen::VectorXd::Ones(4);
    p.H = v * v.transpose();
    expectInvalid(p, "singular H");
  }
  { QpProblem p = good; p.H(0, 1) += 1.0; expectInvalid(p, "asymmetric H"); }
  { QpProblem p = good; p.n_in = 6; expectInvalid(p, "n_in beyond capacity"); }
  { QpProblem p = good; p.n_eq = 2; expectInvalid(p, "n_eq beyond capacity"); }
  {
    QpProblem p;
    makeRandomQp({5, 0, 2, true, 0.2, 10.0}, rng, p);
    expectInvalid(p, "more variables than reserved");
  }
  {
    GoldfarbIdnaniSolver unreserved;
    EXPECT_EQ(unreserved.solve(good, x), QpStatus::kInvalidProblem);
  }
  // NaN data must not poison the next, valid, solve
  EXPECT_EQ(s.solve(good, x), QpStatus::kOptimal);
  expectKkt(good, x, s.result());
}

TEST(GoldfarbIdnani, BadOptionsAndSizesThrowInputError) {
  QpSolverOptions o;
  o.max_iterations = 0;
  EXPECT_THROW(GoldfarbIdnaniSolver{o}, InputError);
  o = QpSolverOptions{};
  o.tolerance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(GoldfarbIdnaniSolver{o}, InputError);
  GoldfarbIdnaniSolver s;
  EXPECT_THROW(s.reserve(0, 1, 1), InputError);
  EXPECT_THROW(s.reserve(3, -1, 1), InputError);
  QpProblem p;
  EXPECT_THROW(p.reserve(2, 0, -4), InputError);
}

// ------------------------------------------------------------------ limits

TEST(GoldfarbIdnani, IterationLimitIsReported) {
  std::mt19937 rng(21);
  RandomQpSpec spec;
  spec.n = 13;
  spec.n_in = 40;
  spec.g_scale = 100.0;
  QpProblem p;
  makeRandomQp(spec, rng, p);
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  const int needed = s.result().iterations;
  ASSERT_GE(needed, 3);
  QpSolverOptions o;
  o.max_iterations = needed - 1;
  o.warm_start = false;
  s.setOptions(o);
  EXPECT_EQ(s.solve(p, x), QpStatus::kMaxIterations);
  EXPECT_EQ(s.result().iterations, needed - 1);
  o.max_iterations = needed;
  s.setOptions(o);
  EXPECT_EQ(s.solve(p, x), QpStatus::kOptimal);
}

// ------------------------------------------------------------------ warm start

// A slowly varying sequence, like consecutive control cycles: warm and cold
// solves agree, and warm ones need fewer dual iterations overall.
TEST(GoldfarbIdnani, WarmStartMatchesColdStartOnASlowSequence) {
  std::mt19937 rng(77);
  RandomQpSpec spec;
  spec.n = 13;
  spec.n_eq = 7;
  spec.n_in = 40;
  spec.g_scale = 30.0;
  QpProblem base;
  makeRandomQp(spec, rng, base);
  QpProblem p = base;
  GoldfarbIdnaniSolver warm, cold;
  QpSolverOptions no_warm;
  no_warm.warm_start = false;
  cold.setOptions(no_warm);
  warm.reserve(p.n, p.capacityEq(), p.capacityIn());
  cold.reserve(p.n, p.capacityEq(), p.capacityIn());
  Eigen::VectorXd xw(p.n), xc(p.n);
  int it_warm = 0, it_cold = 0, warm_used = 0, changes = 0;
  std::vector<QpActiveRow> last;
  const int steps = 300;
  for (int k = 0; k < steps; ++k) {
    const double t = 0.04 * k;
    for (int j = 0; j < p.n; ++j) p.g[j] = base.g[j] * (1.0 + 0.5 * std::sin(t + j));
    // sides only move outward from the generator's, so every problem stays feasible
    for (int i = 0; i < p.n_in; ++i) {
      p.c_lb[i] = base.c_lb[i] - 0.3 * (1.0 + std::sin(0.7 * t + i));
      p.c_ub[i] = base.c_ub[i] + 0.3 * (1.0 + std::cos(0.9 * t + i));
    }
    ASSERT_EQ(cold.solve(p, xc), QpStatus::kOptimal) << k;
    ASSERT_EQ(warm.solve(p, xw), QpStatus::kOptimal) << k;
    EXPECT_LE((xw - xc).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + xc.cwiseAbs().maxCoeff())) << k;
    expectKkt(p, xw, warm.result());
    it_warm += warm.result().iterations;
    it_cold += cold.result().iterations;
    warm_used += warm.result().warm_started;
    if (k > 0 && warm.result().active != last) ++changes;
    last = warm.result().active;
  }
  RecordProperty("active_set_changes", changes);
  RecordProperty("iterations_warm", it_warm);
  RecordProperty("iterations_cold", it_cold);
  RecordProperty("warm_started", warm_used);
  EXPECT_GT(changes, 0);  // the active set really changes along the sequence
  EXPECT_GT(warm_used, steps / 2);
  EXPECT_LT(it_warm, it_cold / 2);
}

TEST(GoldfarbIdnani, WarmStartSurvivesAbruptChanges) {
  // consecutive unrelated problems of the same size: the stale active set
  // must be repaired or discarded, never trusted
  GoldfarbIdnaniSolver warm, cold;
  QpSolverOptions no_warm;
  no_warm.warm_start = false;
  cold.setOptions(no_warm);
  warm.reserve(13, 7, 40);
  cold.reserve(13, 7, 40);
  Eigen::VectorXd xw(13), xc(13);
  for (int seed = 0; seed < 60; ++seed) {
    std::mt19937 rng(3000 + seed);
    RandomQpSpec spec;
    spec.n = 13;
    spec.n_eq = seed % 8;
    spec.n_in = 10 + seed % 31;
    QpProblem p;
    makeRandomQp(spec, rng, p);
    QpProblem q;  // same data in the reserved shape
    q.reserve(13, 7, 40);
    q.n_eq = p.n_eq;
    q.n_in = p.n_in;
    q.H = p.H;
    q.g = p.g;
    q.x_lb = p.x_lb;
    q.x_ub = p.x_ub;
    q.A_eq.topRows(p.n_eq) = p.A_eq.topRows(p.n_eq);
    q.b_eq.head(p.n_eq) = p.b_eq.head(p.n_eq);
    q.C.topRows(p.n_in) = p.C.topRows(p.n_in);
    q.c_lb.head(p.n_in) = p.c_lb.head(p.n_in);
    q.c_ub.head(p.n_in) = p.c_ub.head(p.n_in);
    ASSERT_EQ(cold.solve(q, xc), QpStatus::kOptimal) << seed;
    ASSERT_EQ(warm.solve(q, xw), QpStatus::kOptimal) << seed;
    EXPECT_LE((xw - xc).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + xc.cwiseAbs().maxCoeff())) << seed;
  }
}

TEST(GoldfarbIdnani, ResetWarmStartForcesColdStart) {
  std::mt19937 rng(5);
  QpProblem p;
  makeRandomQp({8, 2, 16, true, 0.2, 20.0}, rng, p);
  GoldfarbIdnaniSolver s;
  Eigen::VectorXd x;
  ASSERT_EQ(solveFresh(p, x, s), QpStatus::kOptimal);
  ASSERT_FALSE(s.result().active.empty());
  ASSERT_EQ(s.solve(p, x), QpStatus::kOptimal);
  EXPECT_TRUE(s.result().warm_started);
  EXPECT_EQ(s.result().iterations, 0);  // the old active set is already optimal
  s.resetWarmStart();
  ASSERT_EQ(s.solve(p, x), QpStatus::kOptimal);
  EXPECT_FALSE(s.result().warm_started);
  EXPECT_GT(s.result().iterations, 0);
}

}  // namespace
}  // namespace handover::control
