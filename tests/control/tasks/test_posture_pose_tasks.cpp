// Posture and end-effector pose tasks: rows are the stated PD laws, and the
// pose task's rows predict the TCP acceleration of the true kinematics.
#include <gtest/gtest.h>

#include <random>

#include "control/model/algorithms.hpp"
#include "control/so3.hpp"
#include "control/tasks/end_effector_pose_task.hpp"
#include "control/tasks/posture_task.hpp"
#include "tests/support/panda_model.hpp"

using namespace handover::control;

namespace {
using handover::test::panda;
}  // namespace

TEST(PostureTask, RowsAreJointPdLaw) {
  Data data(panda());
  Vector7 q, v, ref;
  q << 0.1, -0.5, 0.2, -2.0, 0.1, 1.5, 0.7;
  v << 0.3, -0.1, 0.2, 0.0, -0.4, 0.1, 0.2;
  ref << 0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785;
  computeAll(panda(), data, q, v);
  PostureTask task("posture", PdGains{10.0, 6.0}, ref);
  ControlContext ctx;
  ctx.model = &panda();
  ctx.data = &data;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(7, kNumVars);
  Eigen::VectorXd b(7);
  task.compute(ctx, A, b);
  EXPECT_TRUE(A.leftCols(7).isIdentity());
  EXPECT_TRUE(A.rightCols(6).isZero());
  EXPECT_LT((b - (-10.0 * (q - ref) - 6.0 * v)).norm(), 1e-12);

  // a moving reference (a timed joint-space move): its acceleration and velocity fed forward
  TaskTarget moving;
  moving.kind = TaskTarget::Kind::kJoints;
  moving.q = ref;
  moving.qd << 0.2, -0.1, 0.0, 0.3, 0.0, 0.1, -0.2;
  moving.qdd << 1.0, 0.0, -0.5, 0.0, 0.2, 0.0, 0.3;
  ASSERT_TRUE(task.applyTarget(moving));
  task.compute(ctx, A, b);
  EXPECT_LT((b - (moving.qdd - 10.0 * (q - ref) - 6.0 * (v - moving.qd))).norm(), 1e-12);
  // back to the configured posture: at rest again
  ASSERT_TRUE(task.applyTarget(TaskTarget{}));
  task.setTarget(ref);
  task.compute(ctx, A, b);
  EXPECT_LT((b - (-10.0 * (q - ref) - 6.0 * v)).norm(), 1e-12);
}

TEST(EndEffectorPoseTask, RowsPredictTcpAcceleration) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Data data(panda());
  Vector7 q, v, a;
  q << 0.1, -0.5, 0.2, -2.0, 0.1, 1.5, 0.7;
  for (int i = 0; i < 7; ++i) {
    v[i] = 0.5 * u(rng);
    a[i] = 2.0 * u(rng);
  }
  const int tcp = panda().frameId("tcp");
  auto tcpVel = [&](double t) {
    Data d(panda());
    forwardKinematics(panda(), d, q + v * t + 0.5 * a * t * t, v + a * t);
    return Vector6(frameVelocity(panda(), d, tcp));
  };
  const double h = 1e-4;
  const Vector6 acc_fd = (tcpVel(h) - tcpVel(-h)) / (2 * h);

  computeAll(panda(), data, q, v);
  ControlContext ctx;
  ctx.model = &panda();
  ctx.data = &data;
  EndEffectorPoseTask zero(panda(), "pose", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, kNumVars);
  Eigen::VectorXd b(6);
  zero.compute(ctx, A, b);
  Eigen::VectorXd chi = Eigen::VectorXd::Zero(kNumVars);
  chi.head<7>() = a;
  EXPECT_LT((A * chi - b - acc_fd).norm(), 1e-5 * (1.0 + acc_fd.norm()));

  // with gains: -K e - D v on top
  EndEffectorPoseTask task(panda(), "pose", "tcp", PdGains{2.0, 3.0}, PdGains{4.0, 5.0});
  Isometry target = framePlacement(panda(), data, tcp);
  target.translation() += Vector3(0.05, -0.02, 0.1);
  target.linear() = expRotation(Vector3(0.1, 0.0, -0.2)) * target.linear();
  task.setTarget(target);
  Eigen::VectorXd b2(6);
  task.compute(ctx, A, b2);
  const Isometry X = framePlacement(panda(), data, tcp);
  const Vector6 vel = frameVelocity(panda(), data, tcp);
  Vector6 law;
  law.head<3>() = -2.0 * (X.translation() - target.translation()) - 3.0 * vel.head<3>();
  law.tail<3>() = -4.0 * orientationError(X.linear(), target.linear()) - 5.0 * vel.tail<3>();
  EXPECT_LT((b2 - b - law).norm(), 1e-9);

  // a moving set-point: the damping acts on the velocity relative to it
  Vector6 target_velocity;
  target_velocity << 0.3, -0.1, 0.2, 0.05, 0.0, -0.1;
  TaskTarget moving;
  moving.kind = TaskTarget::Kind::kPose;
  moving.pose = target;
  moving.velocity = target_velocity;
  ASSERT_TRUE(task.applyTarget(moving));
  Eigen::VectorXd b3(6);
  task.compute(ctx, A, b3);
  Vector6 fed;
  fed << 3.0 * target_velocity.head<3>(), 5.0 * target_velocity.tail<3>();
  EXPECT_LT((b3 - b2 - fed).norm(), 1e-9);
  // a pose target without a velocity is at rest again
  moving.velocity.setZero();
  ASSERT_TRUE(task.applyTarget(moving));
  task.compute(ctx, A, b3);
  EXPECT_LT((b3 - b2).norm(), 1e-12);
}
