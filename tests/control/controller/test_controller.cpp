// Controller end to end on a kinematic simulation (q integrated from the
// solved qddot): the TCP meets the grasp frame of a moving object, the
// observation target is held on invalid measurements, the joint limits hold
// under a posture that pushes beyond them, and failures fall back safely.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "control/controller.hpp"
#include "control/so3.hpp"

using namespace handover::control;

namespace {

const Model& panda() {
  static const Model m = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return m;
}

struct KinematicSim {
  Vector7 q, v = Vector7::Zero();
  double t = 0.0;
  ControlInputs inputs() const {
    ControlInputs in;
    in.time = t;
    in.q = q;
    in.qd = v;
    return in;
  }
  void advance(const Vector7& qdd, double dt) {
    q += v * dt + 0.5 * qdd * dt * dt;
    v += qdd * dt;
    t += dt;
  }
};

}  // namespace

TEST(Controller, TcpMeetsGraspFrameOfMovingObject) {
  Controller ctl(panda(), loadControllerConfig(defaultControllerConfigPath()));
  KinematicSim sim;
  sim.q = ctl.config().posture.target;
  ctl.reset(sim.inputs());
  GraspOffset offset;
  offset.placement.translation() = Vector3(0.0, 0.0, 0.03);
  offset.placement.linear() = expRotation(Vector3(M_PI, 0.0, 0.0));  // approach from above
  ctl.setGraspOffset(offset);

  // object carried by a person: from (0.7, 0.25, 0.35) to (0.5, 0.0, 0.25), then still
  const Isometry start_tcp = ctl.tcpPose();
  Isometry obj = Isometry::Identity();
  const Vector3 p0(0.7, 0.25, 0.35), p1(0.5, 0.0, 0.25);
  const double dt = ctl.config().period;
  for (int k = 0; k < 12000; ++k) {
    const double s = std::min(1.0, sim.t / 1.5);
    obj.translation() = p0 + (p1 - p0) * (10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s);
    obj.linear() = expRotation(Vector3(0.0, 0.0, 0.4 * s));
    ctl.setObservationTarget(obj, (k % 17) == 0);  // a 60 Hz-like sensor
    ctl.step(sim.inputs());
    ASSERT_FALSE(ctl.lastStepFellBack()) << "step " << k << " status " << toString(ctl.lastStatus());
    sim.advance(ctl.lastQdd(), dt);
  }
  // the observed object sits on the measurement, the TCP on the grasp frame
  EXPECT_LT((ctl.observedState().pose.translation() - obj.translation()).norm(), 1e-3);
  const GraspFrameState g = ctl.graspFrame();
  const Isometry expected_grasp = obj * offset.placement;
  EXPECT_LT((g.pose.translation() - expected_grasp.translation()).norm(), 2e-3);
  EXPECT_LT((ctl.tcpPose().translation() - g.pose.translation()).norm(), 5e-3);
  EXPECT_LT(logRotation(ctl.tcpPose().linear() * g.pose.linear().transpose()).norm(), 0.02);
  EXPECT_GT((start_tcp.translation() - ctl.tcpPose().translation()).norm(), 0.1);  // it did move
  EXPECT_EQ(ctl.fallbackCount(), 0);
}

TEST(Controller, HoldsTheLastValidObservation) {
  Controller ctl(panda(), ControllerConfig());
  KinematicSim sim;
  sim.q = ctl.config().posture.target;
  ctl.reset(sim.inputs());
  Isometry a = ctl.observationTarget();
  a.translation() += Vector3(0.02, 0.0, 0.0);
  ctl.setObservationTarget(a, true);
  Isometry bogus = a;
  bogus.translation() += Vector3(1.0, 1.0, 1.0);
  ctl.setObservationTarget(bogus, false);  // invalid: ignored
  Isometry nan_pose = a;
  nan_pose.translation()[1] = std::nan("");
  ctl.setObservationTarget(nan_pose, true);  // non-finite: ignored
  EXPECT_LT((ctl.observationTarget().translation() - a.translation()).norm(), 1e-15);
  for (int k = 0; k < 500; ++k) {
    ctl.step(sim.inputs());
    sim.advance(ctl.lastQdd(), ctl.config().period);
  }
  // converged on the held target, not drifting past it (no extrapolation)
  EXPECT_LT((ctl.observedState().pose.translation() - a.translation()).norm(), 1e-4);
  EXPECT_LT(ctl.observedState().velocity.norm(), 1e-2);
}

TEST(Controller, JointLimitsHoldAgainstAPostureBeyondThem) {
  ControllerConfig cfg;
  cfg.posture.gains = PdGains::critical(200.0);
  cfg.posture.weight = 1000.0;
  Controller ctl(panda(), cfg);
  KinematicSim sim;
  sim.q = cfg.posture.target;
  ctl.reset(sim.inputs());
  ctl.setTaskEnabled("tracking", false);
  const Model& m = panda();
  Vector7 beyond;
  for (int i = 0; i < 7; ++i) beyond[i] = (i % 2 == 0) ? m.q_max[i] + 0.5 : m.q_min[i] - 0.5;
  ctl.setPostureTarget(beyond);
  const Vector7 vlim = cfg.limits.velocity_scale * m.v_max;
  for (int k = 0; k < 5000; ++k) {
    ctl.step(sim.inputs());
    sim.advance(ctl.lastQdd(), ctl.config().period);
    for (int i = 0; i < 7; ++i) {
      ASSERT_GT(sim.q[i], m.q_min[i]) << "joint " << i + 1 << " step " << k;
      ASSERT_LT(sim.q[i], m.q_max[i]) << "joint " << i + 1 << " step " << k;
      ASSERT_LE(std::abs(sim.v[i]), vlim[i] + 1e-9) << "joint " << i + 1 << " step " << k;
    }
  }
  EXPECT_EQ(ctl.fallbackCount(), 0);
  // and it did go close to the limits it was pushed toward
  for (int i = 0; i < 7; ++i) {
    const double gap = (i % 2 == 0) ? m.q_max[i] - sim.q[i] : sim.q[i] - m.q_min[i];
    EXPECT_LT(gap, 0.1 * (m.q_max[i] - m.q_min[i])) << "joint " << i + 1;
  }
}

TEST(Controller, NanInputsGiveADampedStop) {
  Controller ctl(panda(), ControllerConfig());
  KinematicSim sim;
  sim.q = ctl.config().posture.target;
  sim.v << 0.3, -0.2, 0.1, 0.2, -0.1, 0.3, 0.2;
  ctl.reset(sim.inputs());
  ctl.step(sim.inputs());
  ASSERT_FALSE(ctl.lastStepFellBack());
  ControlInputs bad = sim.inputs();
  bad.qd[3] = std::nan("");
  const Vector7 tau = ctl.step(bad);
  EXPECT_TRUE(ctl.lastStepFellBack());
  EXPECT_EQ(ctl.fallbackCount(), 1);
  EXPECT_TRUE(tau.allFinite());
  // the stop opposes the last valid velocity, within the acceleration limits
  const double kd = ctl.config().fallback.damping;
  for (int i = 0; i < 7; ++i) {
    const double expected = std::clamp(-kd * sim.v[i], -panda().a_max[i], panda().a_max[i]);
    EXPECT_NEAR(ctl.lastQdd()[i], expected, 1e-12);
  }
  EXPECT_LT((tau - (ctl.data().M * ctl.lastQdd() + ctl.data().h)).cwiseAbs().maxCoeff(), 1e-9);
  // back to normal on the next good input
  ctl.step(sim.inputs());
  EXPECT_FALSE(ctl.lastStepFellBack());
  EXPECT_EQ(ctl.lastStatus(), QpStatus::kOptimal);
}

TEST(Controller, InfeasibleQpFallsBackAndCounts) {
  // torque limits below gravity at rest: no qddot satisfies them
  ControllerConfig cfg;
  cfg.limits.torque_scale = 0.01;
  Controller ctl(panda(), cfg);
  KinematicSim sim;
  sim.q = cfg.posture.target;
  sim.v << 0.2, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0;
  ctl.reset(sim.inputs());
  for (int k = 0; k < 3; ++k) ctl.step(sim.inputs());
  EXPECT_NE(ctl.lastStatus(), QpStatus::kOptimal);
  EXPECT_TRUE(ctl.lastStepFellBack());
  EXPECT_EQ(ctl.fallbackCount(), 3);
  EXPECT_LT(ctl.lastQdd()[0], 0.0);  // braking joint 1
  // the damped stop's torque comes from the model and the limit guard: it
  // holds the arm against gravity (the QP's own 1 % limit would drop it) and
  // stays within the guard's torque limits
  const Vector7 lim = cfg.limit_guard.torque_scale * panda().tau_max;
  EXPECT_TRUE((ctl.lastTau().cwiseAbs().array() <= lim.array() + 1e-12).all());
  EXPECT_LT((ctl.lastTau() - (ctl.data().M * ctl.lastQdd() + ctl.data().h)).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(std::abs(ctl.lastTau()[1]), 0.05 * panda().tau_max[1]);  // gravity at joint 2, beyond the QP's limit
}

TEST(Controller, FallbackStopsWithinEveryLimitWhenTheQpStaysInfeasible) {
  // issue 16: a QP kept infeasible (torque limits below gravity) with a
  // coasting fallback (damping 0, in range), every joint moving fast toward
  // its upper limit. The damped stop used to clip the torque to the QP's
  // limits (the arm fell) and to coast through the position limits; through
  // the limit guard, every joint stops before its limit, within its velocity
  // and torque limits. Plant: the model's own dynamics, semi-implicit Euler.
  ControllerConfig cfg;
  cfg.limits.torque_scale = 0.01;
  cfg.fallback.damping = 0.0;
  Controller ctl(panda(), cfg);
  const Model& m = panda();
  Vector7 q = cfg.posture.target, v;
  v << 1.5, 1.5, 1.5, 1.5, 2.0, 2.0, 2.0;
  ControlInputs in;
  in.q = q;
  in.qd = v;
  ctl.reset(in);
  Data plant(m);
  const double dt = cfg.period;
  for (int k = 0; k < 4000; ++k) {
    in.time = k * dt;
    in.q = q;
    in.qd = v;
    const Vector7 tau = ctl.step(in);
    ASSERT_TRUE(ctl.lastStepFellBack()) << "step " << k;
    computeAll(m, plant, q, v);
    const Vector7 qdd = plant.M.llt().solve(tau - plant.h);
    v += dt * qdd;
    q += dt * v;
    for (int i = 0; i < 7; ++i) {
      ASSERT_LE(q[i], m.q_max[i]) << "joint " << i + 1 << " step " << k;
      ASSERT_GE(q[i], m.q_min[i]) << "joint " << i + 1 << " step " << k;
      ASSERT_LE(std::abs(v[i]), m.v_max[i]) << "joint " << i + 1 << " step " << k;
      ASSERT_LE(std::abs(tau[i]), m.tau_max[i] + 1e-9) << "joint " << i + 1 << " step " << k;
    }
  }
  EXPECT_LT(v.cwiseAbs().maxCoeff(), 1e-2);  // it came to rest
  EXPECT_GT(ctl.guardCount(), 0);
}

namespace {
// A soft row demanding of joint 1 an acceleration twice its limit (as a
// collision row does when a person moves in faster than the arm can escape).
class ImpossibleEscape : public Constraint {
 public:
  const std::string& name() const override { return name_; }
  int maxRows() const override { return 1; }
  bool soft() const override { return true; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd>) override {
    C.row(0).setZero();
    C(0, VariableLayout::kQdd) = 1.0;
    lb[0] = 2.0 * ctx.model->a_max[0];
    ub[0] = std::numeric_limits<double>::infinity();
    return 1;
  }

 private:
  std::string name_ = "impossible_escape";
};
}  // namespace

TEST(Controller, InfeasibleSoftRowsAreRelaxedWithinTheLimits) {
  for (const bool relax : {true, false}) {
    ControllerConfig cfg = loadControllerConfig(defaultControllerConfigPath());
    cfg.qp.relax_soft_rows = relax;
    Controller ctl(panda(), cfg);
    ctl.formulation().addConstraint(std::make_shared<ImpossibleEscape>());
    KinematicSim sim;
    sim.q = cfg.posture.target;
    ctl.reset(sim.inputs());
    ctl.step(sim.inputs());
    const double a_lim = cfg.limits.acceleration_scale * panda().a_max[0];
    if (relax) {
      EXPECT_FALSE(ctl.lastStepFellBack());
      EXPECT_TRUE(ctl.lastStepRelaxed());
      EXPECT_EQ(ctl.relaxedCount(), 1);
      // joint 1 escapes as fast as its (hard) limit allows, no faster
      EXPECT_NEAR(ctl.lastQdd()[0], a_lim, 1e-6 * a_lim);
      EXPECT_NEAR(ctl.lastSlack(), 2.0 * panda().a_max[0] - a_lim, 1e-3);
    } else {
      EXPECT_TRUE(ctl.lastStepFellBack());
      EXPECT_FALSE(ctl.lastStepRelaxed());
      EXPECT_EQ(ctl.lastSlack(), 0.0);
    }
  }
}

namespace {
// A soft row asking joint 1 to speed up by `qdd` (rad/s^2): a collision row
// whose person moves in faster than the slowed arm may move.
class SpeedUpJointOne : public Constraint {
 public:
  explicit SpeedUpJointOne(double qdd) : qdd_(qdd) {}
  const std::string& name() const override { return name_; }
  int maxRows() const override { return 1; }
  bool soft() const override { return true; }
  int compute(const ControlContext&, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd>) override {
    C.row(0).setZero();
    C(0, VariableLayout::kQdd) = 1.0;
    lb[0] = qdd_;
    ub[0] = std::numeric_limits<double>::infinity();
    return 1;
  }

 private:
  double qdd_;
  std::string name_ = "speed_up_joint_one";
};
}  // namespace

// The slow-down near a person scales the velocity limits; a receiver's hand
// reaching at 1 m/s into the held gripper struck it while the joints crept at
// 15 % of their limit and the collision rows were relaxed. The slow-down now
// gives way: the row holds, within the full limits, and the scale stays set.
TEST(Controller, TheSlowDownGivesWayToARowItWouldMakeInfeasible) {
  ControllerConfig cfg = loadControllerConfig(defaultControllerConfigPath());
  const double a_lim = cfg.limits.acceleration_scale * panda().a_max[0];
  for (const double demand : {0.5 * a_lim, -0.5 * a_lim}) {
    Controller ctl(panda(), cfg);
    ctl.formulation().addConstraint(std::make_shared<SpeedUpJointOne>(demand));
    ctl.setSpeedScale(0.3);
    KinematicSim sim;
    sim.q = cfg.posture.target;
    sim.v[0] = ctl.velocityLimit().limit()[0];  // joint 1 at its slowed limit
    ctl.reset(sim.inputs());
    ctl.step(sim.inputs());
    ASSERT_FALSE(ctl.lastStepFellBack());
    EXPECT_FALSE(ctl.lastStepRelaxed()) << demand;
    EXPECT_GE(ctl.lastQdd()[0], demand - 1e-6);
    EXPECT_NEAR(ctl.velocityLimit().speedScale(), 0.3, 1e-12);
    if (demand > 0.0) {
      // past the slowed limit, within the full one
      EXPECT_TRUE(ctl.lastStepUnslowed());
      EXPECT_EQ(ctl.unslowedCount(), 1);
      const double next = sim.v[0] + cfg.period * ctl.lastQdd()[0];
      EXPECT_GT(next, ctl.velocityLimit().limit()[0]);
      EXPECT_LE(next, cfg.limits.velocity_scale * panda().v_max[0] + 1e-9);
    } else {
      // a row the slowed arm can meet: the slow-down holds
      EXPECT_FALSE(ctl.lastStepUnslowed());
      EXPECT_EQ(ctl.unslowedCount(), 0);
      EXPECT_LE(sim.v[0] + cfg.period * ctl.lastQdd()[0], ctl.velocityLimit().limit()[0] + 1e-9);
    }
  }
}

TEST(Controller, TaskSwitchesByName) {
  Controller ctl(panda(), ControllerConfig());
  EXPECT_TRUE(ctl.setTaskEnabled("pose", true));
  EXPECT_TRUE(ctl.formulation().taskEnabled("pose"));
  EXPECT_FALSE(ctl.setTaskEnabled("no_such_task", true));
  EXPECT_TRUE(ctl.setConstraintEnabled("joint_torque", false));
  EXPECT_FALSE(ctl.formulation().constraintEnabled("joint_torque"));
  EXPECT_FALSE(ctl.setConstraintEnabled("nope", false));
}

TEST(Controller, FreeAxisGraspLeavesRotationAboutTheAxisFree) {
  // An upright cylinder turned 1 rad about its axis, grasped from above. With
  // the free axis the gripper only aligns its approach axis and does not turn
  // to follow the object's yaw; without it, it must turn the full 1 rad.
  auto run = [](bool free_axis, Isometry& tcp_start, Isometry& tcp_end, Isometry& obj) {
    Controller ctl(panda(), loadControllerConfig(defaultControllerConfigPath()));
    KinematicSim sim;
    sim.q = ctl.config().posture.target;
    ctl.reset(sim.inputs());
    tcp_start = ctl.tcpPose();
    GraspOffset g;
    g.placement.linear() = expRotation(Vector3(M_PI, 0.0, 0.0));  // grasp z = -object z
    g.has_free_axis = free_axis;
    g.free_axis = Vector3::UnitZ();
    ctl.setGraspOffset(g);
    obj = Isometry::Identity();
    obj.translation() = Vector3(0.45, 0.15, 0.3);
    obj.linear() = expRotation(Vector3(0.0, 0.0, 1.0));
    ctl.resetObservedObject(obj);
    ctl.setObservationTarget(obj, true);
    for (int k = 0; k < 10000; ++k) {
      ctl.step(sim.inputs());
      EXPECT_FALSE(ctl.lastStepFellBack());
      sim.advance(ctl.lastQdd(), ctl.config().period);
    }
    tcp_end = ctl.tcpPose();
    EXPECT_LT((tcp_end.translation() - obj.translation()).norm(), 5e-3);
    // approach axis aligned with the grasp's in both modes
    EXPECT_LT(std::acos(std::min(1.0, -tcp_end.linear().col(2).dot(obj.linear().col(2)))), 0.02);
    return ctl.graspFrame();
  };
  Isometry s1, e1, o1, s2, e2, o2;
  const GraspFrameState g_free = run(true, s1, e1, o1);
  const GraspFrameState g_full = run(false, s2, e2, o2);
  const double turn_free = logRotation(e1.linear() * s1.linear().transpose()).norm();
  const double turn_full = logRotation(e2.linear() * s2.linear().transpose()).norm();
  EXPECT_GT(turn_full, 0.9);                 // followed the 1 rad yaw
  EXPECT_LT(turn_free, 0.5 * turn_full);     // did not need to
  EXPECT_LT(logRotation(e2.linear() * (o2.linear() * expRotation(Vector3(M_PI, 0, 0))).transpose()).norm(), 0.02);
  // the reported grasp frame is the nearest one: it coincides with the TCP
  EXPECT_LT(logRotation(e1.linear() * g_free.pose.linear().transpose()).norm(), 0.02);
  (void)g_full;
}
