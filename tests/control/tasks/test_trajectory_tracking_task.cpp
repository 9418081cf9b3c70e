// Trajectory-tracking task rows against numerical differentiation of the true
// kinematics: with zero gains, A chi - b must equal the error's second
// derivative (translation), the relative angular acceleration (full
// orientation), or the projected second derivative of c = b - a (free axis),
// for any qddot and any alphadot_obs (the coupling).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "control/controller.hpp"
#include "control/model/algorithms.hpp"
#include "control/so3.hpp"
#include "control/tasks/planned_turn.hpp"
#include "control/tasks/observed_object_integrator.hpp"
#include "control/tasks/trajectory_tracking_task.hpp"
#include "tests/support/panda_model.hpp"

using namespace handover::control;

namespace {

using handover::test::panda;

// A motion of the arm (constant qddot) and of the observed object (constant
// alphadot_obs), evaluated at any time t around 0.
struct Motion {
  Vector7 q0, qd0, qdd;
  Isometry X0;
  Vector6 alpha0, alphadot;

  ObservedState object(double t) const {
    ObservedObjectIntegrator integ;
    integ.reset(X0, alpha0);
    const int n = 200;  // substeps: the integrator is second order in rotation
    for (int k = 0; k < n; ++k) integ.integrate(alphadot, t / n);
    return integ.state();
  }
  void arm(double t, Vector7& q, Vector7& v) const {
    q = q0 + qd0 * t + 0.5 * qdd * t * t;
    v = qd0 + qdd * t;
  }
};

Motion randomMotion(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Motion m;
  m.q0 << 0.1, -0.6, 0.2, -2.2, 0.3, 1.7, 0.6;
  for (int i = 0; i < 7; ++i) {
    m.q0[i] += 0.2 * u(rng);
    m.qd0[i] = 0.6 * u(rng);
    m.qdd[i] = 2.0 * u(rng);
  }
  m.X0 = Isometry::Identity();
  m.X0.translation() = Vector3(0.5 + 0.1 * u(rng), 0.1 * u(rng), 0.3 + 0.1 * u(rng));
  m.X0.linear() = expRotation(Vector3(u(rng), u(rng), u(rng)));
  for (int i = 0; i < 6; ++i) {
    m.alpha0[i] = 0.8 * u(rng);
    m.alphadot[i] = 3.0 * u(rng);
  }
  return m;
}

GraspOffset someOffset(bool free_axis) {
  GraspOffset g;
  g.placement.translation() = Vector3(0.03, -0.02, 0.08);
  g.placement.linear() = expRotation(Vector3(0.3, -0.5, 0.9));
  g.has_free_axis = free_axis;
  g.free_axis = Vector3(0.2, 0.1, 1.0).normalized();
  return g;
}

struct Rows {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, kNumVars);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(6);
};

Rows computeRows(TrajectoryTrackingTask& task, const Motion& m, Data& data) {
  computeAll(panda(), data, m.q0, m.qd0);
  ControlContext ctx;
  ctx.model = &panda();
  ctx.data = &data;
  ctx.observed = m.object(0.0);
  Rows r;
  task.compute(ctx, r.A, r.b);
  return r;
}

Eigen::VectorXd chiOf(const Motion& m) {
  Eigen::VectorXd chi(kNumVars);
  chi << m.qdd, m.alphadot;
  return chi;
}

// True quantities along the motion, from forward kinematics only.
struct Truth {
  const Motion& m;
  const GraspOffset& g;
  Matrix3 R_grasp_frozen;  // nearest-grasp choice frozen at t = 0 (free-axis mode)
  int tcp;

  Isometry tcpPose(double t, Vector6* vel = nullptr) const {
    Data d(panda());
    Vector7 q, v;
    m.arm(t, q, v);
    forwardKinematics(panda(), d, q, v);
    if (vel) *vel = frameVelocity(panda(), d, tcp);
    return framePlacement(panda(), d, tcp);
  }
  Vector3 positionError(double t) const {
    const ObservedState o = m.object(t);
    // grasp point: with a free axis, rotated about the axis as chosen at t = 0
    const Matrix3 rot_obs0 = R_grasp_frozen * g.placement.linear().transpose();  // R_obs(0) Rot(phi)
    const Matrix3 rot_phi = m.X0.linear().transpose() * rot_obs0;
    const Vector3 r = o.pose.linear() * rot_phi * g.placement.translation();
    return tcpPose(t).translation() - (o.pose.translation() + r);
  }
  Vector3 relativeOmega(double t) const {
    Vector6 v;
    tcpPose(t, &v);
    return v.tail<3>() - m.object(t).velocity.tail<3>();
  }
  Vector3 axisError(double t) const {
    const Vector3 u = g.placement.linear().transpose() * g.free_axis;
    return tcpPose(t).linear() * u - m.object(t).pose.linear() * g.free_axis;
  }
};

constexpr double kH = 1e-3;

template <class F>
Eigen::Vector3d secondDerivative(F f) {
  return (f(kH) - 2.0 * f(0.0) + f(-kH)) / (kH * kH);
}
template <class F>
Eigen::Vector3d firstDerivative(F f) {
  return (f(kH) - f(-kH)) / (2.0 * kH);
}

}  // namespace

TEST(TrajectoryTrackingTask, RowsMatchNumericalDifferentiation) {
  std::mt19937 rng(42);
  Data data(panda());
  for (int trial = 0; trial < 5; ++trial) {
    const Motion m = randomMotion(rng);
    const GraspOffset g = someOffset(false);
    TrajectoryTrackingTask task(panda(), "tracking", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
    task.setGraspOffset(g);
    const Rows rows = computeRows(task, m, data);
    const Eigen::VectorXd pred = rows.A * chiOf(m) - rows.b;

    Truth truth{m, g, m.X0.linear() * g.placement.linear(), panda().frameId("tcp")};
    const Vector3 epp = secondDerivative([&](double t) { return truth.positionError(t); });
    const Vector3 wd = firstDerivative([&](double t) { return truth.relativeOmega(t); });
    EXPECT_LT((pred.head<3>() - epp).norm(), 1e-4 * (1.0 + epp.norm())) << "trial " << trial;
    EXPECT_LT((pred.tail<3>() - wd).norm(), 1e-4 * (1.0 + wd.norm())) << "trial " << trial;
  }
}

TEST(TrajectoryTrackingTask, CouplingToObjectAccelerationIsInTheRows) {
  // Perturb only alphadot_obs: the predicted change of the error acceleration
  // must equal the finite-difference change of the true error acceleration.
  std::mt19937 rng(5);
  Data data(panda());
  Motion m = randomMotion(rng);
  const GraspOffset g = someOffset(false);
  TrajectoryTrackingTask task(panda(), "tracking", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
  task.setGraspOffset(g);
  const Rows rows = computeRows(task, m, data);
  const int tcp = panda().frameId("tcp");

  Motion m2 = m;
  m2.alphadot << 0.0, 0.0, 0.0, 4.0, -3.0, 5.0;  // angular only: the [r]x lever term
  Truth t1{m, g, m.X0.linear() * g.placement.linear(), tcp};
  Truth t2{m2, g, m2.X0.linear() * g.placement.linear(), tcp};
  const Vector3 d_true = secondDerivative([&](double t) { return t2.positionError(t); }) -
                         secondDerivative([&](double t) { return t1.positionError(t); });
  const Eigen::VectorXd d_pred = rows.A * (chiOf(m2) - chiOf(m));
  EXPECT_GT(d_true.norm(), 0.05);  // the perturbation matters
  EXPECT_LT((d_pred.head<3>() - d_true).norm(), 1e-4 * (1.0 + d_true.norm()));
}

TEST(TrajectoryTrackingTask, GainsGiveThePdLaw) {
  std::mt19937 rng(11);
  Data data(panda());
  const Motion m = randomMotion(rng);
  const GraspOffset g = someOffset(false);
  TrajectoryTrackingTask free_task(panda(), "t0", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
  TrajectoryTrackingTask task(panda(), "t1", "tcp", PdGains{3.0, 1.5}, PdGains{5.0, 2.5});
  free_task.setGraspOffset(g);
  task.setGraspOffset(g);
  const Rows r0 = computeRows(free_task, m, data);
  const Rows r1 = computeRows(task, m, data);
  EXPECT_LT((r1.A - r0.A).norm(), 1e-15);

  Truth truth{m, g, m.X0.linear() * g.placement.linear(), panda().frameId("tcp")};
  const Vector3 e = truth.positionError(0.0);
  const Vector3 ed = firstDerivative([&](double t) { return truth.positionError(t); });
  EXPECT_LT(((r1.b - r0.b).head<3>() - (-3.0 * e - 1.5 * ed)).norm(), 1e-6);
  // orientation: -K (tcp (-) grasp) - D (omega_tcp - omega_obs)
  const Matrix3 R_g = m.X0.linear() * g.placement.linear();
  const Vector3 eo = orientationError(truth.tcpPose(0.0).linear(), R_g);
  const Vector3 wrel = truth.relativeOmega(0.0);
  EXPECT_LT(((r1.b - r0.b).tail<3>() - (-5.0 * eo - 2.5 * wrel)).norm(), 1e-9);
  EXPECT_LT((task.error().head<3>() - e).norm(), 1e-12);
}

// The speed limit clips the error the PD acts on to D v_max / K (so a PD at
// rest asks at most v_max), leaves a smaller error alone and the rows' A and
// the reported error untouched.
/// The speed-limit tests' state: a random motion, an offset, the PD gains.
struct SpeedLimitCase {
  std::mt19937 rng{11};
  Data data{panda()};
  Motion m = randomMotion(rng);
  GraspOffset g = someOffset(false);
  PdGains kt{50.0, 2.0 * std::sqrt(50.0)}, ko{100.0, 20.0};
};

TEST(TrajectoryTrackingTask, SpeedLimitClipsTheErrorThePdActsOn) {
  SpeedLimitCase c;
  Data& data = c.data;
  const Motion& m = c.m;
  const GraspOffset& g = c.g;
  const PdGains &kt = c.kt, &ko = c.ko;
  TrajectoryTrackingTask free_task(panda(), "t0", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
  TrajectoryTrackingTask plain(panda(), "t1", "tcp", kt, ko);
  TrajectoryTrackingTask limited(panda(), "t2", "tcp", kt, ko);
  for (auto* t : {&free_task, &plain, &limited}) t->setGraspOffset(g);
  Truth truth{m, g, m.X0.linear() * g.placement.linear(), panda().frameId("tcp")};
  const Vector3 e = truth.positionError(0.0);
  const Vector3 ed = firstDerivative([&](double t) { return truth.positionError(t); });
  const Matrix3 R_g = m.X0.linear() * g.placement.linear();
  const Vector3 eo = orientationError(truth.tcpPose(0.0).linear(), R_g);
  const Vector3 wrel = truth.relativeOmega(0.0);
  ASSERT_GT(e.norm(), 0.05);
  ASSERT_GT(eo.norm(), 0.1);
  // limits below what the errors ask: clipped to D v / K along the error
  const double v = 0.5 * kt.stiffness * e.norm() / kt.damping, w = 0.5 * ko.stiffness * eo.norm() / ko.damping;
  limited.setSpeedLimits(v, w);
  const Rows r0 = computeRows(free_task, m, data);
  const Rows rp = computeRows(plain, m, data);
  const Rows rl = computeRows(limited, m, data);
  EXPECT_LT((rl.A - rp.A).norm(), 1e-15);
  const Vector3 e_clip = e.normalized() * (kt.damping * v / kt.stiffness);
  EXPECT_LT(((rl.b - r0.b).head<3>() - (-kt.stiffness * e_clip - kt.damping * ed)).norm(), 1e-6 * (1.0 + kt.damping));  // ed is numerical
  const Vector3 eo_clip = eo.normalized() * (ko.damping * w / ko.stiffness);
  EXPECT_LT(((rl.b - r0.b).tail<3>() - (-ko.stiffness * eo_clip - ko.damping * wrel)).norm(), 1e-9);
  EXPECT_LT((limited.error().head<3>() - e).norm(), 1e-12);
  // limits above what the errors ask: the plain PD law
  limited.setSpeedLimits(4.0 * v, 4.0 * w);
  const Rows rh = computeRows(limited, m, data);
  EXPECT_LT((rh.b - rp.b).norm(), 1e-12);
}

// A phase's gains may bring their own speed limit (the slide onto an object
// in the person's hand): it lowers the configured limit, never raises it,
// and the configured gains bring the configured limit back.
TEST(TrajectoryTrackingTask, APhasesSpeedLimitLowersTheConfiguredOneUntilTheConfiguredGainsReturn) {
  SpeedLimitCase c;
  TrajectoryTrackingTask task(panda(), "t", "tcp", c.kt, c.ko);
  TrajectoryTrackingTask reference(panda(), "r", "tcp", c.kt, c.ko);
  task.setGraspOffset(c.g);
  reference.setGraspOffset(c.g);
  Truth truth{c.m, c.g, c.m.X0.linear() * c.g.placement.linear(), panda().frameId("tcp")};
  const Vector3 e = truth.positionError(0.0);
  ASSERT_GT(e.norm(), 0.05);
  const double asked = c.kt.stiffness * e.norm() / c.kt.damping;  // m/s, what the unclipped PD asks
  task.setSpeedLimits(0.5 * asked, 0.0);

  TaskGains phase;
  phase.configured = false;
  phase.translation = c.kt;
  phase.orientation = c.ko;
  phase.max_speed = 0.25 * asked;
  ASSERT_TRUE(task.applyGains(phase));
  EXPECT_DOUBLE_EQ(task.maxSpeed(), 0.25 * asked);
  reference.setSpeedLimits(0.25 * asked, 0.0);
  EXPECT_LT((computeRows(task, c.m, c.data).b - computeRows(reference, c.m, c.data).b).norm(), 1e-12);

  phase.max_speed = 4.0 * asked;  // above the configured limit: the configured one holds
  task.applyGains(phase);
  EXPECT_DOUBLE_EQ(task.maxSpeed(), 0.5 * asked);
  phase.max_speed = 0.0;          // none of its own: the configured one
  task.applyGains(phase);
  EXPECT_DOUBLE_EQ(task.maxSpeed(), 0.5 * asked);
  phase.max_speed = 0.25 * asked;
  task.applyGains(phase);
  task.applyGains(TaskGains{});   // the configured gains again
  EXPECT_DOUBLE_EQ(task.maxSpeed(), 0.5 * asked);
  reference.setSpeedLimits(0.5 * asked, 0.0);
  EXPECT_LT((computeRows(task, c.m, c.data).b - computeRows(reference, c.m, c.data).b).norm(), 1e-12);
}

TEST(TrajectoryTrackingTask, FreeAxisRowsAreExactAndLeaveSpinFree) {
  std::mt19937 rng(9);
  Data data(panda());
  for (int trial = 0; trial < 4; ++trial) {
    const Motion m = randomMotion(rng);
    const GraspOffset g = someOffset(true);
    TrajectoryTrackingTask task(panda(), "tracking", "tcp", PdGains{0.0, 0.0}, PdGains{0.0, 0.0});
    task.setGraspOffset(g);
    const Rows rows = computeRows(task, m, data);
    const Eigen::VectorXd pred = rows.A * chiOf(m) - rows.b;

    const int tcp = panda().frameId("tcp");
    const ObservedState o0 = m.object(0.0);
    Truth probe{m, g, Matrix3::Identity(), tcp};
    const Matrix3 R_ee = probe.tcpPose(0.0).linear();
    Truth truth{m, g, graspRotation(o0, g, R_ee), tcp};

    // orientation rows: P c'' with P the projector normal to b = R_tcp u
    const Vector3 u = g.placement.linear().transpose() * g.free_axis;
    const Vector3 bvec = R_ee * u;
    const Matrix3 P = Matrix3::Identity() - bvec * bvec.transpose();
    const Vector3 cpp = secondDerivative([&](double t) { return truth.axisError(t); });
    EXPECT_LT((pred.tail<3>() - P * cpp).norm(), 1e-4 * (1.0 + cpp.norm())) << "trial " << trial;
    // translation rows toward the nearest grasp point (choice frozen over the step)
    const Vector3 epp = secondDerivative([&](double t) { return truth.positionError(t); });
    EXPECT_LT((pred.head<3>() - epp).norm(), 1e-4 * (1.0 + epp.norm())) << "trial " << trial;
    // spinning the gripper about b costs nothing: those qddot columns see no b component
    Matrix6x7 J;
    frameJacobian(panda(), data, tcp, J);
    EXPECT_LT((bvec.transpose() * rows.A.block(3, 0, 3, kArmDofs)).norm(), 1e-12);
    EXPECT_LT((rows.A.block(3, 0, 3, kArmDofs) * J.bottomRows<3>().completeOrthogonalDecomposition().pseudoInverse() *
               bvec)
                  .norm(),
              1e-9);
  }
}

TEST(GraspFrame, NearestGraspAroundTheFreeAxis) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  GraspOffset g = someOffset(true);
  for (int trial = 0; trial < 20; ++trial) {
    ObservedState o;
    o.pose.linear() = expRotation(Vector3(u(rng), u(rng), u(rng)));
    const Matrix3 R_ee = expRotation(Vector3(2 * u(rng), 2 * u(rng), 2 * u(rng)));
    const Matrix3 R_g = graspRotation(o, g, R_ee);
    // a member of the family: maps the gripper's axis onto the object's axis
    const Vector3 uax = g.placement.linear().transpose() * g.free_axis;
    EXPECT_LT((R_g * uax - o.pose.linear() * g.free_axis).norm(), 1e-9);
    const double best = logRotation(R_g * R_ee.transpose()).norm();
    for (int k = 0; k < 72; ++k) {
      const Matrix3 cand = o.pose.linear() * expRotation(g.free_axis * (k * M_PI / 36.0)) * g.placement.linear();
      EXPECT_LE(best, logRotation(cand * R_ee.transpose()).norm() + 1e-9);
    }
  }
}

TEST(GraspFrame, StateFollowsRigidBodyRelations) {
  // velocity and acceleration of the grasp point against finite differences
  std::mt19937 rng(8);
  const Motion m = randomMotion(rng);
  const GraspOffset g = someOffset(false);
  auto point = [&](double t) {
    const ObservedState o = m.object(t);
    return Vector3(graspFrameState(o, m.alphadot, g, Matrix3::Identity()).pose.translation());
  };
  const GraspFrameState s = graspFrameState(m.object(0.0), m.alphadot, g, Matrix3::Identity());
  const Vector3 v_fd = firstDerivative(point);
  const Vector3 a_fd = secondDerivative(point);
  EXPECT_LT((s.velocity.head<3>() - v_fd).norm(), 1e-5);
  EXPECT_LT((s.acceleration.head<3>() - a_fd).norm(), 1e-4 * (1.0 + a_fd.norm()));
  EXPECT_LT((s.acceleration.tail<3>() - m.alphadot.tail<3>()).norm(), 1e-15);
}

// A placement sliding along its own approach axis (a standoff shrinking
// with speed sdot and acceleration sddot) on a moving, turning object: the
// fed-forward velocity and acceleration are the derivatives of the point.
TEST(GraspFrame, ASlidingPlacementFeedsItsMotionForward) {
  std::mt19937 rng(11);
  const Motion m = randomMotion(rng);
  GraspOffset g = someOffset(false);
  const double s0 = 0.06, sdot = 0.3, sddot = -2.0;  // m, m/s, m/s^2 along the grasp z
  auto slid = [&](double t) {
    GraspOffset o = g;
    o.placement = g.placement * Eigen::Translation3d(0.0, 0.0, -s0 + sdot * t + 0.5 * sddot * t * t);
    return o;
  };
  auto point = [&](double t) {
    return Vector3(graspFrameState(m.object(t), m.alphadot, slid(t), Matrix3::Identity()).pose.translation());
  };
  GraspOffset now = slid(0.0);
  now.approach_speed = sdot;
  now.approach_acceleration = sddot;
  const GraspFrameState s = graspFrameState(m.object(0.0), m.alphadot, now, Matrix3::Identity());
  const Vector3 v_fd = firstDerivative(point);
  const Vector3 a_fd = secondDerivative(point);
  EXPECT_LT((s.velocity.head<3>() - v_fd).norm(), 1e-5);
  EXPECT_LT((s.acceleration.head<3>() - a_fd).norm(), 1e-4 * (1.0 + a_fd.norm()));
  // without the feed-forward the frame's velocity misses the slide
  const GraspFrameState still = graspFrameState(m.object(0.0), m.alphadot, slid(0.0), Matrix3::Identity());
  EXPECT_NEAR((s.velocity.head<3>() - still.velocity.head<3>()).norm(), sdot, 1e-12);
}

namespace {

// A controller tracking a resting grasp frame at the TCP pose of `q_plan`
// from `q0`, the posture task pulling toward q_plan as the grasp planner's
// redundancy resolution does, for 6 s.
struct Turn {
  double orientation_left = 0.0;  ///< rad
  double position_left = 0.0;     ///< m
  double joints_off_plan = 0.0;   ///< |q - q_plan|, rad
  double wrist_margin = 10.0;     ///< least distance of q7 to its limits, rad
};
Turn turnToward(const Vector7& q0, const Vector7& q_plan, bool with_plan) {
  ControllerConfig cfg;
  cfg.tracking.translation.gains = PdGains::critical(20.0);
  cfg.tracking.orientation.gains = PdGains::critical(20.0);
  cfg.tracking.max_speed = 0.5;
  cfg.tracking.max_angular_speed = 1.5;
  Controller ctl(panda(), cfg);
  ControlInputs in;
  in.q = q0;
  ctl.reset(in);
  Data d(panda());
  forwardKinematics(panda(), d, q_plan, Vector7::Zero());
  const Isometry target = framePlacement(panda(), d, panda().frameId("tcp"));
  GraspOffset offset;
  offset.has_joint_plan = with_plan;
  offset.joint_plan = q_plan;
  ctl.setGraspOffset(offset);
  ctl.setPostureTarget(q_plan);
  ctl.resetObservedObject(target);
  Vector7 q = q0, v = Vector7::Zero();
  Turn r;
  for (int k = 0; k < 6000; ++k) {
    in.time = k * cfg.period;
    in.q = q;
    in.qd = v;
    ctl.setObservationTarget(target, true);
    ctl.step(in);
    v += ctl.lastQdd() * cfg.period;
    q += v * cfg.period;
    r.wrist_margin = std::min({r.wrist_margin, q[6] - panda().q_min[6], panda().q_max[6] - q[6]});
  }
  r.orientation_left = orientationError(ctl.tcpPose().linear(), target.linear()).norm();
  r.position_left = (ctl.tcpPose().translation() - target.translation()).norm();
  r.joints_off_plan = (q - q_plan).norm();
  return r;
}

}  // namespace

// The wrist at 2.2 rad, the grasp a turn of 3.9 rad the other way about the
// tool axis (q7 -> -1.7): the shortest rotation, 2.4 rad the other way,
// would take q7 to 4.6, past its limit (2.9). With the plan the TCP turns
// the way the joints go and arrives at the planned configuration; without
// it the wrist winds into its limit, the other joints make up the turn and
// the arm ends contorted, 0.18 m short of the frame (measured).
TEST(TrajectoryTrackingTask, ALargeTurnGoesTheWayTheJointPlanTurns) {
  Vector7 q0;
  q0 << 0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 2.2;
  Vector7 q_plan = q0;
  q_plan[6] = 2.2 - 3.9;
  const Turn with = turnToward(q0, q_plan, true), without = turnToward(q0, q_plan, false);
  EXPECT_LT(with.orientation_left, 0.01);
  EXPECT_LT(with.position_left, 0.005);
  EXPECT_LT(with.joints_off_plan, 0.05);
  EXPECT_GT(with.wrist_margin, 0.3);
  // without: the wrist winds into its limit and the arm contorts, short of the frame
  EXPECT_LT(without.wrist_margin, 0.1);
  EXPECT_GT(without.position_left, 0.05);
  EXPECT_GT(without.joints_off_plan, 1.0);
}

// Less than a quarter turn by the shortest rotation, but the wrist is at the
// far end of its range: the plan turns q7 by -4.8 rad (2.3 -> -2.5), the
// shortest rotation (1.5 rad) would take it to 3.8, past its limit. A give's
// approach from its waiting pose (g31_00157): joint 7 stopped at
// its limit, joint 1 swung the arm 2.3 rad aside to make up the turn and the
// approach timed out. The joints' motion toward the plan turns the TCP more
// than half a turn, which no shortest rotation does: the way is the plan's.
TEST(TrajectoryTrackingTask, ASmallTurnGoesTheLongWayWhenTheJointPlanTurnsMoreThanHalfATurn) {
  Vector7 q0;
  q0 << 0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 2.3;
  Vector7 q_plan = q0;
  q_plan[6] = 2.3 - (2.0 * M_PI - 1.5);
  const Turn with = turnToward(q0, q_plan, true);
  EXPECT_LT(with.orientation_left, 0.01);
  EXPECT_LT(with.position_left, 0.005);
  EXPECT_LT(with.joints_off_plan, 0.05);
  EXPECT_GT(with.wrist_margin, 0.2);
}

// Seven joints moving at once, the TCP to turn 3.1 rad (near half a turn):
// the first-order guess of the way, J_w (q_plan - q), points the short way,
// but the joints' path turns the TCP the long way round (its lift along the
// path ends on the far quaternion sign). Going the guessed way, the wrist
// winds to its limit and the arm stops contorted, 1.1 rad and 0.11 m off
// with the joints 5 rad from the plan (measured); the path's way arrives.
TEST(TrajectoryTrackingTask, ATurnOfManyJointsGoesTheWayTheirPathTurnsNotTheLinearisedWay) {
  Vector7 q0, q_plan;
  q0 << -0.0032912, -0.57026, 0.304227, -1.8384, 0.320627, 0.971033, -1.1461;
  q_plan << 0.888007, -1.44587, -0.842883, -0.911014, 0.410358, 1.91734, 1.8262;
  const int tcp = panda().frameId("tcp");
  const Quaternion now(frameRotation(panda(), tcp, q0));
  const Quaternion target(frameRotation(panda(), tcp, q_plan));
  const Vector3 shortest = orientationError(now.toRotationMatrix(), target.toRotationMatrix());
  ASSERT_GT(shortest.norm(), 3.0);
  // the linearised guess: the short way (the PD turns by -e, the guess along -e)
  Data d(panda());
  forwardKinematics(panda(), d, q0, Vector7::Zero());
  Matrix6x7 J;
  frameJacobian(panda(), d, tcp, J);
  ASSERT_LT((J.bottomRows<3>() * (q_plan - q0)).dot(shortest), 0.0);
  // the path: the long way
  ASSERT_LT(planOrientationAlongJointPath(panda(), tcp, q0, now, q_plan).dot(now), 0.0);
  const Turn with = turnToward(q0, q_plan, true);
  EXPECT_LT(with.orientation_left, 0.01);
  EXPECT_LT(with.position_left, 0.005);
  EXPECT_LT(with.joints_off_plan, 0.05);
  EXPECT_GT(with.wrist_margin, 0.3);
}
