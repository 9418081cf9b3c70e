// SoftRowRelaxation: the least common widening of the soft rows first, the
// original cost second; hard rows and bounds are never given up.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "control/qp/goldfarb_idnani.hpp"
#include "control/qp/soft_row_relaxation.hpp"
#include "tests/control/qp/qp_test_problems.hpp"

namespace handover::control {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Fixture {
  QpProblem p;
  GoldfarbIdnaniSolver solver;
  SoftRowRelaxation relaxation;
  Eigen::VectorXd x;
  explicit Fixture(int n, int capacity_in) {
    p.reserve(n, 0, capacity_in);
    p.H.setIdentity();
    solver.reserve(SoftRowRelaxation::solverVars(n), 0, SoftRowRelaxation::solverRowsIn(capacity_in));
    relaxation.reserve(n, 0, capacity_in);
    x.setZero(n);
  }
  // row i: lb <= x_k <= ub
  void row(int i, int k, double lb, double ub, bool soft) {
    p.C.row(i).setZero();
    p.C(i, k) = 1.0;
    p.c_lb[i] = lb;
    p.c_ub[i] = ub;
    p.soft_in[i] = soft ? 1 : 0;
    p.n_in = std::max(p.n_in, i + 1);
  }
};

TEST(SoftRowRelaxation, ConflictingSoftRowsMeetHalfWay) {
  Fixture f(2, 4);
  f.row(0, 0, 1.0, kInf, true);    // x0 >= 1
  f.row(1, 0, -kInf, -1.0, true);  // x0 <= -1
  ASSERT_EQ(f.solver.solve(f.p, f.x), QpStatus::kInfeasible);
  ASSERT_TRUE(f.p.hasSoftRows());
  ASSERT_EQ(f.relaxation.solve(f.p, f.solver, f.x), QpStatus::kOptimal);
  EXPECT_NEAR(f.relaxation.slack(), 1.0, 1e-6);  // one shared widening: the largest violation is least
  EXPECT_NEAR(f.x[0], 0.0, 1e-6);
}

TEST(SoftRowRelaxation, HardBoundsAndRowsAreKept) {
  Fixture f(2, 4);
  f.p.x_ub[0] = 0.0;                 // hard bound x0 <= 0
  f.row(0, 0, 2.0, kInf, true);      // soft: x0 >= 2
  f.row(1, 1, 3.0, kInf, false);     // hard: x1 >= 3
  ASSERT_EQ(f.solver.solve(f.p, f.x), QpStatus::kInfeasible);
  ASSERT_EQ(f.relaxation.solve(f.p, f.solver, f.x), QpStatus::kOptimal);
  EXPECT_NEAR(f.relaxation.slack(), 2.0, 1e-6);
  EXPECT_LE(f.x[0], 1e-9);
  EXPECT_NEAR(f.x[0], 0.0, 1e-6);
  EXPECT_GE(f.x[1], 3.0 - 1e-9);
}

TEST(SoftRowRelaxation, CostDecidesWhatTheWideningLeavesFree) {
  // phase 1 only fixes the widening: x1, untouched by the soft rows, goes
  // where the original cost puts it (5), not where phase 1's small
  // regularisation would (0)
  Fixture f(2, 4);
  f.p.g << 0.0, -5.0;                // min 1/2 |x|^2 - 5 x1
  f.row(0, 0, 1.0, kInf, true);
  f.row(1, 0, -kInf, -1.0, true);
  ASSERT_EQ(f.relaxation.solve(f.p, f.solver, f.x), QpStatus::kOptimal);
  EXPECT_NEAR(f.x[1], 5.0, 1e-6);
  EXPECT_NEAR(f.x[0], 0.0, 1e-6);
}

TEST(SoftRowRelaxation, ConflictingHardRowsStayInfeasible) {
  Fixture f(2, 4);
  f.row(0, 0, 1.0, kInf, false);
  f.row(1, 0, -kInf, -1.0, false);
  f.row(2, 1, 0.0, kInf, true);
  EXPECT_EQ(f.relaxation.solve(f.p, f.solver, f.x), QpStatus::kInfeasible);
}

TEST(SoftRowRelaxation, TwoSidedSoftRowWidensBothSides) {
  Fixture f(1, 4);
  f.p.x_lb[0] = 4.0;                 // hard: x0 >= 4
  f.row(0, 0, 0.0, 1.0, true);       // soft: 0 <= x0 <= 1
  ASSERT_EQ(f.relaxation.solve(f.p, f.solver, f.x), QpStatus::kOptimal);
  EXPECT_NEAR(f.relaxation.slack(), 3.0, 1e-6);
  EXPECT_NEAR(f.x[0], 4.0, 1e-6);
}

TEST(SoftRowRelaxation, AControllerStepWithNearlyOppositeRowsIsRelaxed) {
  // the step of tests/control/qp/test_goldfarb_idnani.cpp's nearly opposite rows:
  // infeasible as it stands, held by widening its soft collision rows only
  QpProblem p;
  ASSERT_TRUE(test::loadQpText(test::nearlyInconsistentRowsFile(), p));
  GoldfarbIdnaniSolver solver;
  solver.reserve(SoftRowRelaxation::solverVars(p.n), 0, SoftRowRelaxation::solverRowsIn(p.n_in));
  SoftRowRelaxation relaxation;
  relaxation.reserve(p.n, 0, p.n_in);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(p.n);
  ASSERT_EQ(solver.solve(p, x), QpStatus::kInfeasible);
  ASSERT_EQ(relaxation.solve(p, solver, x), QpStatus::kOptimal);
  EXPECT_GT(relaxation.slack(), 0.0);
  EXPECT_LE(test::largestViolation(p, x, relaxation.slack()), 1e-6);
  EXPECT_LT(x.cwiseAbs().maxCoeff(), 100.0);  // accelerations of the scale of the bounds, not 1e14
}

TEST(SoftRowRelaxation, RefusesAProblemOfAnotherSize) {
  Fixture f(2, 4);
  QpProblem other;
  other.reserve(3, 0, 4);
  other.H.setIdentity();
  Eigen::VectorXd x(3);
  EXPECT_EQ(f.relaxation.solve(other, f.solver, x), QpStatus::kInvalidProblem);
}

}  // namespace
}  // namespace handover::control
