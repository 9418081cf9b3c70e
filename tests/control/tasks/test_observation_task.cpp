// Observation task + observed-object integrator: the closed loop alone must
// reproduce the critically damped PD response x(t) = x0 (1 + w t) e^(-w t),
// w = sqrt(K), solved through the real QP formulation and solver.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "control/formulation/formulation.hpp"
#include "control/qp/goldfarb_idnani.hpp"
#include "control/so3.hpp"
#include "control/tasks/observation_task.hpp"
#include "control/tasks/observed_object_integrator.hpp"

using namespace handover::control;

namespace {

struct StepResponse {
  double max_pos_dev = 0.0;  // |x - analytic| / x0 over the run
  double max_rot_dev = 0.0;
};

// Starts at rest at the identity, steps the target to (x0 along a direction,
// angle0 about an axis), runs the observation task alone for `duration`.
StepResponse runStep(double K, double dt, double duration) {
  const double x0 = 0.1, angle0 = 0.4;
  const Vector3 dir = Vector3(1, -2, 0.5).normalized();
  const Vector3 axis = Vector3(0.3, 1, -0.2).normalized();
  auto task = std::make_shared<ObservationTask>("observation", PdGains::critical(K), PdGains::critical(K));
  Isometry target = Isometry::Identity();
  target.translation() = x0 * dir;
  target.linear() = expRotation(angle0 * axis);
  task->setTarget(target);

  Formulation f;
  f.addTask(task, 1e5);
  QpProblem p;
  f.reserveProblem(p);
  GoldfarbIdnaniSolver solver;
  solver.reserve(kNumVars, p.capacityEq(), p.capacityIn());
  ObservedObjectIntegrator integ;
  integ.reset(Isometry::Identity());
  Eigen::VectorXd x(kNumVars);

  const double w = std::sqrt(K);
  StepResponse r;
  const int steps = static_cast<int>(std::lround(duration / dt));
  for (int k = 0; k < steps; ++k) {
    ControlContext ctx;
    ctx.dt = dt;
    ctx.observed = integ.state();
    f.build(ctx, p);
    EXPECT_EQ(solver.solve(p, x), QpStatus::kOptimal);
    integ.integrate(x.tail<6>(), dt);
    const double t = (k + 1) * dt;
    const double analytic = (1.0 + w * t) * std::exp(-w * t);  // remaining error fraction
    const Vector3 e_p = integ.state().pose.translation() - target.translation();
    const Vector3 e_o = orientationError(integ.state().pose.linear(), target.linear());
    // error stays on the step direction / axis and follows the analytic decay
    r.max_pos_dev = std::max(r.max_pos_dev, (e_p - (-x0 * analytic) * dir).norm() / x0);
    r.max_rot_dev = std::max(r.max_rot_dev, (e_o - (-angle0 * analytic) * axis).norm() / angle0);
  }
  return r;
}

}  // namespace

TEST(ObservationTask, ReproducesCriticallyDampedStepResponse) {
  const StepResponse coarse = runStep(1500.0, 1e-3, 0.5);
  EXPECT_LT(coarse.max_pos_dev, 0.02);
  EXPECT_LT(coarse.max_rot_dev, 0.02);
  // the deviation is discretisation only: it shrinks with the period
  const StepResponse fine = runStep(1500.0, 1e-4, 0.5);
  EXPECT_LT(fine.max_pos_dev, 0.003);
  EXPECT_LT(fine.max_rot_dev, 0.003);
  EXPECT_LT(fine.max_pos_dev, 0.2 * coarse.max_pos_dev);
  // another stiffness: the law, not a tuned constant
  const StepResponse soft = runStep(100.0, 1e-3, 1.0);
  EXPECT_LT(soft.max_pos_dev, 0.01);
}

TEST(ObservationTask, RowsAreThePdLawOnTheObjectBlock) {
  ObservationTask task("obs", PdGains{1500.0, 50.0}, PdGains{700.0, 20.0});
  Isometry target = Isometry::Identity();
  target.translation() = Vector3(0.5, 0.1, 0.3);
  target.linear() = expRotation(Vector3(0.1, 0.2, -0.3));
  task.setTarget(target);
  ControlContext ctx;
  ctx.observed.pose.translation() = Vector3(0.45, 0.12, 0.31);
  ctx.observed.velocity << 0.1, -0.2, 0.3, 0.5, -0.4, 0.2;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, kNumVars);
  Eigen::VectorXd b(6);
  task.compute(ctx, A, b);
  EXPECT_TRUE(A.leftCols(kArmDofs).isZero());
  EXPECT_TRUE(A.rightCols(6).isIdentity());
  const Vector3 e_p = ctx.observed.pose.translation() - target.translation();
  const Vector3 e_o = logRotation(target.linear().transpose()).eval();  // obs at identity: log(R_t')
  EXPECT_LT((b.head<3>() - (-1500.0 * e_p - 50.0 * ctx.observed.velocity.head<3>())).norm(), 1e-12);
  EXPECT_LT((b.tail<3>() - (-700.0 * e_o - 20.0 * ctx.observed.velocity.tail<3>())).norm(), 1e-9);
}

TEST(ObservedObjectIntegrator, IntegratesConstantAccelerationExactly) {
  ObservedObjectIntegrator integ;
  Isometry X0 = Isometry::Identity();
  X0.translation() = Vector3(1, 2, 3);
  Vector6 v0;
  v0 << 0.1, 0.2, -0.3, 0.0, 0.0, 0.5;
  integ.reset(X0, v0);
  Vector6 a;
  a << 1.0, -2.0, 0.5, 0.0, 0.0, 2.0;  // angular accel about the same fixed axis as v0
  const double dt = 1e-3;
  for (int k = 0; k < 500; ++k) integ.integrate(a, dt);
  const double T = 0.5;
  const Vector3 p = X0.translation() + v0.head<3>() * T + 0.5 * a.head<3>() * T * T;
  EXPECT_LT((integ.state().pose.translation() - p).norm(), 1e-12);
  const double angle = 0.5 * T + 0.5 * 2.0 * T * T;  // fixed axis z: angle integrates exactly
  EXPECT_LT((integ.state().pose.linear() - expRotation(Vector3(0, 0, angle))).norm(), 1e-9);
  EXPECT_LT((integ.state().velocity - (v0 + a * T)).norm(), 1e-12);
  // a NaN acceleration leaves the state coasting instead of poisoning it
  integ.integrate(Vector6::Constant(std::nan("")), dt);
  EXPECT_TRUE(integ.state().pose.matrix().allFinite());
  EXPECT_TRUE(integ.state().velocity.allFinite());
}
