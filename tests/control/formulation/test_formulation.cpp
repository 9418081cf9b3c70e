// Formulation: H/g assembly against a dense reference, run-time
// reconfiguration by name, constraint stacking and bound tightening.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <random>
#include <stdexcept>

#include "control/constraints/bound_tightening.hpp"
#include "control/formulation/formulation.hpp"

using namespace handover::control;

namespace {

// A task with fixed, given rows (no model needed).
class FixedTask : public Task {
 public:
  FixedTask(std::string name, Eigen::MatrixXd A, Eigen::VectorXd b) : name_(std::move(name)), A_(A), b_(b) {}
  const std::string& name() const override { return name_; }
  int rows() const override { return static_cast<int>(A_.rows()); }
  void compute(const ControlContext&, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) override {
    A = A_;
    b = b_;
  }
  Eigen::MatrixXd A_;
  Eigen::VectorXd b_;

 private:
  std::string name_;
};

class FixedConstraint : public Constraint {
 public:
  FixedConstraint(std::string name, Eigen::MatrixXd C, Eigen::VectorXd lb, Eigen::VectorXd ub, int bound_var,
                  double bound)
      : name_(std::move(name)), C_(C), lb_(lb), ub_(ub), var_(bound_var), bound_(bound) {}
  const std::string& name() const override { return name_; }
  int maxRows() const override { return static_cast<int>(C_.rows()); }
  int compute(const ControlContext&, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override {
    C = C_;
    lb = lb_;
    ub = ub_;
    tightenBounds(chi_lb, chi_ub, var_, -bound_, bound_);
    return maxRows();
  }

 private:
  std::string name_;
  Eigen::MatrixXd C_;
  Eigen::VectorXd lb_, ub_;
  int var_;
  double bound_;
};

Eigen::MatrixXd randomMatrix(int r, int c, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd M(r, c);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) M(i, j) = u(rng);
  return M;
}

}  // namespace

TEST(Formulation, AssemblesWeightedLeastSquares) {
  std::mt19937 rng(7);
  auto t1 = std::make_shared<FixedTask>("a", randomMatrix(6, kNumVars, rng), randomMatrix(6, 1, rng));
  auto t2 = std::make_shared<FixedTask>("b", randomMatrix(7, kNumVars, rng), randomMatrix(7, 1, rng));
  Formulation f;
  Eigen::VectorXd rw(6);
  rw << 1, 2, 3, 0.5, 0.0, 4;
  f.addTask(t1, 10.0, rw);
  f.addTask(t2, 0.3);
  f.setRegularisation(1e-3);
  QpProblem p;
  f.reserveProblem(p);
  ControlContext ctx;
  f.build(ctx, p);

  // dense reference: sum w A' W A + rho I, -sum w A' W b
  Eigen::MatrixXd H = 1e-3 * Eigen::MatrixXd::Identity(kNumVars, kNumVars);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(kNumVars);
  H += 10.0 * t1->A_.transpose() * rw.asDiagonal() * t1->A_ + 0.3 * t2->A_.transpose() * t2->A_;
  g -= 10.0 * t1->A_.transpose() * rw.asDiagonal() * t1->b_ + 0.3 * t2->A_.transpose() * t2->b_;
  EXPECT_EQ(p.n, kNumVars);
  EXPECT_LT((p.H - H).norm(), 1e-12 * H.norm());
  EXPECT_LT((p.g - g).norm(), 1e-12 * g.norm());
  EXPECT_LT((p.H - p.H.transpose()).norm(), 1e-15);

  // disabling a task removes its contribution; re-enabling restores it
  f.setTaskEnabled("b", false);
  f.build(ctx, p);
  Eigen::MatrixXd H1 = 1e-3 * Eigen::MatrixXd::Identity(kNumVars, kNumVars) +
                       10.0 * t1->A_.transpose() * rw.asDiagonal() * t1->A_;
  EXPECT_LT((p.H - H1).norm(), 1e-12 * H1.norm());
  f.setTaskEnabled("b", true);
  f.build(ctx, p);
  EXPECT_LT((p.H - H).norm(), 1e-12 * H.norm());

  // weights can change by name
  f.setTaskWeight("b", 0.0);
  f.build(ctx, p);
  EXPECT_LT((p.H - H1).norm(), 1e-12 * H1.norm());
  EXPECT_TRUE(f.removeTask("b"));
  EXPECT_FALSE(f.hasTask("b"));
  EXPECT_FALSE(f.removeTask("b"));
}

TEST(Formulation, RejectsMisuse) {
  std::mt19937 rng(1);
  auto t = std::make_shared<FixedTask>("a", randomMatrix(3, kNumVars, rng), randomMatrix(3, 1, rng));
  FormulationCapacity cap;
  cap.max_tasks = 1;
  cap.max_constraint_rows = 2;
  Formulation f(cap);
  f.addTask(t, 1.0);
  EXPECT_THROW(f.addTask(t, 1.0), std::invalid_argument);  // duplicate
  auto t2 = std::make_shared<FixedTask>("b", randomMatrix(3, kNumVars, rng), randomMatrix(3, 1, rng));
  EXPECT_THROW(f.addTask(t2, 1.0), std::invalid_argument);  // capacity
  EXPECT_THROW(f.setTaskEnabled("nope", true), std::invalid_argument);
  EXPECT_THROW(f.setRowWeights("a", Eigen::VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(f.setTaskWeight("a", -1.0), std::invalid_argument);
  auto c = std::make_shared<FixedConstraint>("c", randomMatrix(3, kNumVars, rng), Eigen::VectorXd::Zero(3),
                                             Eigen::VectorXd::Ones(3), 0, 1.0);
  EXPECT_THROW(f.addConstraint(c), std::invalid_argument);  // 3 rows > capacity 2
}

TEST(Formulation, StacksConstraintRowsAndTightensBounds) {
  std::mt19937 rng(3);
  auto t = std::make_shared<FixedTask>("a", randomMatrix(13, kNumVars, rng), randomMatrix(13, 1, rng));
  Eigen::MatrixXd C1 = randomMatrix(2, kNumVars, rng), C2 = randomMatrix(3, kNumVars, rng);
  auto c1 = std::make_shared<FixedConstraint>("c1", C1, -Eigen::VectorXd::Ones(2), Eigen::VectorXd::Ones(2), 4, 2.0);
  auto c2 = std::make_shared<FixedConstraint>("c2", C2, -2 * Eigen::VectorXd::Ones(3), 2 * Eigen::VectorXd::Ones(3),
                                              4, 1.0);
  Formulation f;
  f.addTask(t, 1.0);
  f.addConstraint(c1);
  f.addConstraint(c2);
  QpProblem p;
  f.reserveProblem(p);
  ControlContext ctx;
  f.build(ctx, p);
  ASSERT_EQ(p.n_in, 5);
  EXPECT_EQ(p.C.topRows(2), C1);
  EXPECT_EQ(p.C.middleRows(2, 3), C2);
  EXPECT_EQ(p.c_ub[4], 2.0);
  EXPECT_EQ(p.x_lb[4], -1.0);  // tightest of the two
  EXPECT_EQ(p.x_ub[4], 1.0);
  EXPECT_TRUE(std::isinf(p.x_ub[3]));

  f.setConstraintEnabled("c1", false);
  f.build(ctx, p);
  ASSERT_EQ(p.n_in, 3);
  EXPECT_EQ(p.C.topRows(3), C2);
  EXPECT_TRUE(f.removeConstraint("c2"));
  f.build(ctx, p);
  EXPECT_EQ(p.n_in, 0);
  EXPECT_TRUE(std::isinf(p.x_lb[4]));
}

TEST(BoundTightening, NeverCrossesEarlierBounds) {
  Eigen::VectorXd lb = Eigen::VectorXd::Constant(1, -1.0), ub = Eigen::VectorXd::Constant(1, 1.0);
  tightenBounds(lb, ub, 0, 5.0, 10.0);  // asks for more than the earlier bounds allow
  EXPECT_EQ(lb[0], 1.0);
  EXPECT_EQ(ub[0], 1.0);
  lb[0] = -1.0;
  tightenBounds(lb, ub, 0, -0.5, 0.5);
  EXPECT_EQ(lb[0], -0.5);
  EXPECT_EQ(ub[0], 0.5);
  tightenBounds(lb, ub, 0, -3.0, 3.0);  // never loosens
  EXPECT_EQ(lb[0], -0.5);
  EXPECT_EQ(ub[0], 0.5);
}
