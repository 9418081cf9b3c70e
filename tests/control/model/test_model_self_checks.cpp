// Checks of the model against itself and the published numbers: drifts vs
// numerical differentiation, CRBA vs RNEA columns, datasheet FK values.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "mujoco_oracle.hpp"

namespace handover::control {
namespace {

using test::sourcePath;

class ModelSelfChecks : public ::testing::Test {
 protected:
  ModelSelfChecks() : model(loadModel(sourcePath("scenes/panda.urdf"))), data(model) {}
  void sample(Vector7& q, Vector7& v) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < kArmDofs; ++i) {
      q[i] = model.q_min[i] + u(rng) * (model.q_max[i] - model.q_min[i]);
      v[i] = (2.0 * u(rng) - 1.0) * model.v_max[i];
    }
  }
  Model model;
  Data data;
  std::mt19937 rng{7};
};

TEST_F(ModelSelfChecks, FlangeAtZeroAndTcpAtReadyPoseMatchTheDatasheet) {
  forwardKinematics(model, data, Vector7::Zero(), Vector7::Zero());
  const Vector3 flange = framePlacement(model, data, model.frameId("ft_sensor")).translation();
  EXPECT_LT((flange - Vector3(0.088, 0.0, 0.926)).norm(), 1e-9);

  Vector7 ready;
  ready << 0, -M_PI / 4, 0, -3 * M_PI / 4, 0, M_PI / 2, M_PI / 4;
  forwardKinematics(model, data, ready, Vector7::Zero());
  const Isometry tcp = framePlacement(model, data, model.frameId("tcp"));
  EXPECT_LT((tcp.translation() - Vector3(0.3069, 0.0, 0.4869)).norm(), 1e-4);  // published to 0.1 mm
  EXPECT_LT((tcp.linear() - Vector3(1, -1, -1).asDiagonal().toDenseMatrix()).norm(), 1e-9);
}

TEST_F(ModelSelfChecks, FrameDriftIsTheTimeDerivativeOfJacobianTimesVelocity) {
  Vector7 q, v;
  Matrix6x7 Jp, Jm;
  const double eps = 1e-6;
  for (const char* frame : {"tcp", "panda_link4", "ft_sensor", "panda_leftfinger"}) {
    const int f = model.frameId(frame);
    for (int s = 0; s < 50; ++s) {
      sample(q, v);
      forwardKinematics(model, data, q + eps * v, v);
      frameJacobian(model, data, f, Jp);
      forwardKinematics(model, data, q - eps * v, v);
      frameJacobian(model, data, f, Jm);
      const Vector6 numeric = (Jp - Jm) * v / (2 * eps);
      forwardKinematics(model, data, q, v);
      const Vector6 drift = frameDrift(model, data, f);
      ASSERT_LE((drift - numeric).norm(), 1e-6 * (1.0 + numeric.norm())) << frame << " sample " << s;
      // pointDrift / pointJacobian of the frame origin agree with the frame's
      const Vector3 p = framePlacement(model, data, f).translation();
      Matrix3x7 Jv;
      pointJacobian(model, data, model.frames[f].body, p, Jv);
      forwardKinematics(model, data, q, v);
      ASSERT_LE((pointDrift(model, data, model.frames[f].body, p) - drift.head<3>()).norm(), 1e-12 * (1 + drift.norm()));
      frameJacobian(model, data, f, Jp);
      ASSERT_LE((Jv - Jp.topRows<3>()).norm(), 1e-12);
    }
  }
}

TEST_F(ModelSelfChecks, JacobianMatchesFiniteDifferenceOfPose) {
  Vector7 q, v;
  Matrix6x7 J;
  const double eps = 1e-6;
  const int f = model.frameId("tcp");
  for (int s = 0; s < 50; ++s) {
    sample(q, v);
    forwardKinematics(model, data, q, v);
    frameJacobian(model, data, f, J);
    forwardKinematics(model, data, q + eps * v, v);
    const Isometry Xp = framePlacement(model, data, f);
    forwardKinematics(model, data, q - eps * v, v);
    const Isometry Xm = framePlacement(model, data, f);
    Vector6 numeric;
    numeric.head<3>() = (Xp.translation() - Xm.translation()) / (2 * eps);
    const Eigen::AngleAxisd dR(Xp.linear() * Xm.linear().transpose());
    numeric.tail<3>() = dR.axis() * dR.angle() / (2 * eps);
    ASSERT_LE((J * v - numeric).norm(), 1e-6 * (1.0 + numeric.norm())) << "sample " << s;
  }
}

// The orientation-only kinematics (for configurations other than the cycle's)
// is the full forward kinematics' orientation, for every kind of frame.
TEST_F(ModelSelfChecks, FrameRotationIsTheForwardKinematicsOrientation) {
  Vector7 q, v;
  for (const char* frame : {"tcp", "panda_link0", "panda_link4", "ft_sensor", "panda_leftfinger"}) {
    const int f = model.frameId(frame);
    for (int s = 0; s < 50; ++s) {
      sample(q, v);
      forwardKinematics(model, data, q, v);
      ASSERT_LE((frameRotation(model, f, q) - framePlacement(model, data, f).linear()).norm(), 1e-12)
          << frame << " sample " << s;
    }
  }
}

TEST_F(ModelSelfChecks, CrbaEqualsRneaColumns) {
  Vector7 q, v;
  for (int s = 0; s < 100; ++s) {
    sample(q, v);
    computeAll(model, data, q, v);
    const Vector7 h = rnea(model, data, Vector7::Zero());
    EXPECT_LE((h - data.h).norm(), 1e-12 * (1 + h.norm()));
    for (int k = 0; k < kArmDofs; ++k) {
      const Vector7 col = rnea(model, data, Vector7::Unit(k)) - h;
      ASSERT_LE((col - data.M.col(k)).norm(), 1e-10 * data.M.norm()) << "column " << k << " sample " << s;
    }
    // a mass matrix is symmetric positive definite
    EXPECT_LE((data.M - data.M.transpose()).norm(), 1e-14 * data.M.norm());
    EXPECT_EQ(Eigen::LLT<Matrix7>(data.M).info(), Eigen::Success);
  }
}

TEST_F(ModelSelfChecks, InverseDynamicsIsLinearInAcceleration) {
  Vector7 q, v, a;
  sample(q, v);
  sample(a, a);  // any vector
  computeAll(model, data, q, v);
  EXPECT_LE((rnea(model, data, a) - (data.M * a + data.h)).norm(), 1e-10 * (1 + data.h.norm()));
}

TEST_F(ModelSelfChecks, PayloadOfZeroMassChangesNothingAndMassShowsInGravity) {
  Vector7 q, v;
  sample(q, v);
  computeAll(model, data, q, v);
  const Matrix7 M0 = data.M;
  const Vector7 g0 = data.g;
  Payload none;
  setPayload(model, data, none);
  computeAll(model, data, q, v);
  EXPECT_LE((data.M - M0).norm(), 1e-12 * M0.norm());
  // a point mass at the tcp adds J^T m g_world to the gravity torques
  Payload point;
  point.mass = 1.0;
  setPayload(model, data, point);
  computeAll(model, data, q, v);
  Matrix6x7 J;
  frameJacobian(model, data, model.frameId("tcp"), J);
  const Vector7 expected = g0 - J.topRows<3>().transpose() * (point.mass * model.gravity);
  EXPECT_LE((data.g - expected).norm(), 1e-10 * (1 + expected.norm()));
  Payload bad;
  bad.mass = -1.0;
  EXPECT_THROW(setPayload(model, data, bad), InputError);
  clearPayload(model, data);
  computeAll(model, data, q, v);
  EXPECT_LE((data.g - g0).norm(), 1e-12 * g0.norm());
}

TEST_F(ModelSelfChecks, GravityJacobianIsTheDerivativeOfTheGravityTorques) {
  // with and without an off-centre payload: the analytic columns against
  // central differences of Data::g
  Payload held;
  held.mass = 1.2;
  held.com = Vector3(0.02, -0.01, 0.08);
  for (const bool payload : {false, true}) {
    if (payload) setPayload(model, data, held); else clearPayload(model, data);
    Vector7 q, v;
    for (int s = 0; s < 50; ++s) {
      sample(q, v);
      computeAll(model, data, q, v);
      Matrix7 G;
      gravityJacobian(model, data, G);
      const double eps = 1e-6;
      Matrix7 fd;
      for (int i = 0; i < kArmDofs; ++i) {
        computeAll(model, data, q + eps * Vector7::Unit(i), v);
        const Vector7 plus = data.g;
        computeAll(model, data, q - eps * Vector7::Unit(i), v);
        fd.col(i) = (plus - data.g) / (2 * eps);
      }
      ASSERT_LE((G - fd).norm(), 1e-6 * (1 + fd.norm())) << "payload " << payload << " sample " << s << "\n"
                                                        << G << "\n\n" << fd;
      ASSERT_GT(fd.norm(), 1.0);  // not vacuous: gravity does change with the configuration
    }
  }
}

}  // namespace
}  // namespace handover::control
