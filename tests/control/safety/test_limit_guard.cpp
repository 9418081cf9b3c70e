// The limit guard on its own: a command inside its bounds passes bit for bit;
// adversarial commands (the largest acceleration toward a limit, NaN, torques
// beyond reach) driven through the model's dynamics (semi-implicit Euler, as
// the simulator integrates) never take a joint past its position, velocity or
// torque limit; the braking law's stopping speed really stops in time; the
// settings are validated.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "config/input_error.hpp"
#include "control/controller_config.hpp"
#include "control/safety/limit_guard.hpp"
#include "tests/support/panda_model.hpp"
#include "tests/support/temp_path.hpp"

using namespace handover::control;

namespace {

using handover::test::panda;

constexpr double kDt = 1e-3;

/// The arm under the guard: each step computes M, h at (q, qd), lets the
/// guard fix `command`, and integrates what the guarded torque does.
struct GuardedArm {
  Data data{panda()};
  LimitGuard guard;
  Vector7 q, qd = Vector7::Zero();
  Vector7 tau_external = Vector7::Zero();
  Vector7 last_tau = Vector7::Zero();
  /// a torque on the plant the guard's dynamics do not hold (a person's push)
  Vector7 push = Vector7::Zero();
  /// the guard is told what acted in the last period beyond its dynamics, as
  /// the controller measures it (DisturbanceObserver::latest minus tau_external)
  bool tell_unmodelled = false;
  Vector7 unmodelled = Vector7::Zero();
  explicit GuardedArm(const LimitGuardSettings& s = LimitGuardSettings()) : guard(panda(), s, kDt) {}

  bool step(Vector7 command) {
    computeAll(panda(), data, q, qd);
    Vector7 tau;
    const bool changed = guard.apply(data, tau_external, command, tau, tell_unmodelled ? unmodelled : Vector7::Zero());
    last_tau = tau;
    // the accelerations the torque produces (model = plant here)
    const Vector7 qdd = data.M.llt().solve(tau - data.h + tau_external + push);
    // what the controller's observer reads from this period's motion: M qdd + h - tau
    unmodelled = data.M * qdd + data.h - tau - tau_external;
    qd += kDt * qdd;
    q += kDt * qd;
    return changed;
  }
};

void expectWithinLimits(const GuardedArm& arm, int k, double slack = 1e-9) {
  const Model& m = panda();
  for (int i = 0; i < kArmDofs; ++i) {
    ASSERT_GE(arm.q[i], m.q_min[i] - slack) << "joint " << i + 1 << " step " << k;
    ASSERT_LE(arm.q[i], m.q_max[i] + slack) << "joint " << i + 1 << " step " << k;
    ASSERT_LE(std::abs(arm.qd[i]), m.v_max[i] + slack) << "joint " << i + 1 << " step " << k;
    ASSERT_LE(std::abs(arm.last_tau[i]), m.tau_max[i] + slack) << "joint " << i + 1 << " step " << k;
  }
}

Vector7 ready() { return ControllerConfig().posture.target; }

}  // namespace

TEST(LimitGuard, PassesASafeCommandBitForBit) {
  GuardedArm arm;
  arm.q = ready();
  arm.qd << 0.2, -0.1, 0.1, 0.2, -0.3, 0.1, 0.4;
  arm.tau_external << 0.5, -0.2, 0.1, 0.3, 0.0, 0.05, -0.02;
  computeAll(panda(), arm.data, arm.q, arm.qd);
  Vector7 qdd;
  qdd << 1.0, -2.0, 0.5, 3.0, -1.0, 2.0, -4.0;
  const Vector7 qdd_in = qdd;
  Vector7 tau;
  EXPECT_FALSE(arm.guard.apply(arm.data, arm.tau_external, qdd, tau));
  EXPECT_EQ(qdd, qdd_in);
  Vector7 expected;
  expected.noalias() = arm.data.M * qdd_in;  // the controller's own expression
  expected += arm.data.h - arm.tau_external;
  EXPECT_EQ(tau, expected);
  EXPECT_EQ(arm.guard.changedCount(), 0);
  EXPECT_FALSE(arm.guard.lastChanged());
}

TEST(LimitGuard, StoppingSpeedStopsBeforeTheLimit) {
  // from the stopping speed at distance d, one period at that speed and then
  // braking at a_b (semi-implicit Euler) ends short of d
  const LimitGuard guard(panda(), LimitGuardSettings(), kDt);
  const double a_b = LimitGuardSettings().deceleration_scale * panda().a_max[1];
  for (double d : {1e-4, 1e-3, 0.01, 0.1, 0.5, 2.0}) {
    const double v0 = guard.stoppingSpeed(1, d);
    EXPECT_GT(v0, 0.0);
    double x = kDt * v0, v = v0;
    while (v > 0.0) {
      v = std::max(0.0, v - a_b * kDt);
      x += kDt * v;
    }
    EXPECT_LE(x, d * (1.0 + 1e-12)) << "d = " << d;
    EXPECT_GT(x, 0.5 * d) << "d = " << d << ": the law is not needlessly timid";
  }
  EXPECT_EQ(guard.stoppingSpeed(1, 0.0), 0.0);
  EXPECT_EQ(guard.stoppingSpeed(1, -0.1), 0.0);
}

TEST(LimitGuard, FullAccelerationIntoEveryLimitNeverPassesIt) {
  // every joint commanded 1000 rad/s^2 toward one side for 3 s, from the
  // ready posture and from fast motion toward the limit
  for (int side = 0; side < 2; ++side) {
    for (double v0 : {0.0, 1.0}) {
      SCOPED_TRACE("side " + std::to_string(side) + " start speed " + std::to_string(v0));
      GuardedArm arm;
      arm.q = ready();
      const double sign = side == 0 ? 1.0 : -1.0;
      arm.qd = Vector7::Constant(sign * v0);
      const Vector7 command = Vector7::Constant(sign * 1000.0);
      for (int k = 0; k < 3000; ++k) {
        arm.step(command);
        expectWithinLimits(arm, k);
      }
      // the joints ended at their guarded limits, at rest (the test is not vacuous)
      for (int i = 0; i < kArmDofs; ++i) {
        const double limit = side == 0 ? arm.guard.guardedMax()[i] : arm.guard.guardedMin()[i];
        EXPECT_NEAR(arm.q[i], limit, 2e-3) << "joint " << i + 1;
        EXPECT_NEAR(arm.qd[i], 0.0, 1e-2) << "joint " << i + 1;
      }
      EXPECT_GT(arm.guard.changedCount(), 2900);
    }
  }
}

TEST(LimitGuard, RandomAdversarialCommandsKeepEveryLimit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Model& m = panda();
  for (int trial = 0; trial < 20; ++trial) {
    GuardedArm arm;
    for (int i = 0; i < kArmDofs; ++i) {
      const double mid = 0.5 * (m.q_min[i] + m.q_max[i]), half = 0.5 * (m.q_max[i] - m.q_min[i]);
      arm.q[i] = mid + 0.8 * half * u(rng);
      arm.qd[i] = 0.3 * m.v_max[i] * u(rng);
    }
    for (int k = 0; k < 2000; ++k) {
      Vector7 command;
      for (int i = 0; i < kArmDofs; ++i) command[i] = 300.0 * u(rng);
      if (k % 97 == 0) command[k % 7] = std::nan("");
      if (k % 89 == 0) command[(k + 3) % 7] = std::numeric_limits<double>::infinity();
      arm.step(command);
      ASSERT_TRUE(arm.last_tau.allFinite()) << "trial " << trial << " step " << k;
      expectWithinLimits(arm, k);
      if (HasFatalFailure()) return;
    }
  }
}

TEST(LimitGuard, SpeedStaysBelowTheGuardedVelocity) {
  GuardedArm arm;
  arm.q = ready();
  // joint 1 from -2.9 to +2.9 rad: room to reach full speed
  arm.q[0] = panda().q_min[0] + 0.1;
  Vector7 command = Vector7::Zero();
  command[0] = 50.0;
  double top = 0.0;
  for (int k = 0; k < 2500; ++k) {
    arm.step(command);
    top = std::max(top, arm.qd[0]);
  }
  const double v_g = arm.guard.velocityLimit()[0];
  EXPECT_LE(top, v_g + 1e-9);
  EXPECT_GT(top, 0.99 * v_g);  // it did reach it
}

// Issue 16: a hand pressing on a presented bottle (0.4-1.4 N m about the
// last joint at the wrist sensor) spun joint 7 past its velocity limit while
// the QP, blind to the push, commanded almost nothing. Told the last
// period's unmodelled torque, the guard brakes against it in time; not told,
// a firm press (2 N m) takes the joint past its limit.
TEST(LimitGuard, APushTheModelMissesDoesNotSpinAJointPastItsLimit) {
  for (const bool told : {false, true}) {
    SCOPED_TRACE(told ? "told the unmodelled torque" : "not told");
    GuardedArm arm;
    arm.q = ready();
    arm.push[6] = 2.0;  // N m: a firm press on the gripper, well within what joint 7 can hold (12)
    arm.tell_unmodelled = told;
    double fastest = 0.0;
    for (int k = 0; k < 500; ++k) {
      arm.step(Vector7::Zero());  // the QP does not know: no acceleration asked
      fastest = std::max(fastest, std::abs(arm.qd[6]));
      if (told) expectWithinLimits(arm, k);
    }
    if (told)
      EXPECT_GT(fastest, 0.9 * panda().v_max[6]);  // it ran up to the guarded speed, no further
    else
      EXPECT_GT(fastest, panda().v_max[6]);  // the premise: without it the push wins
  }
}

TEST(LimitGuard, TorqueNeverExceedsItsLimit) {
  // a command that takes far more torque than the motors have, near rest
  GuardedArm arm;
  arm.q = ready();
  computeAll(panda(), arm.data, arm.q, arm.qd);
  Vector7 qdd = Vector7::Constant(-1e4), tau;
  qdd[1] = 1e4;
  EXPECT_TRUE(arm.guard.apply(arm.data, arm.tau_external, qdd, tau));
  EXPECT_TRUE((tau.cwiseAbs().array() <= panda().tau_max.array() + 1e-9).all()) << tau.transpose();
  // the acceleration read back is what that torque does
  const Vector7 back = arm.data.M * qdd + arm.data.h - arm.tau_external;
  EXPECT_LT((back - tau).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_EQ(arm.guard.changedCount(), 1);
}

TEST(LimitGuard, ReducedTorqueScaleHolds) {
  LimitGuardSettings s;
  s.torque_scale = 0.8;
  GuardedArm arm(s);
  arm.q = ready();
  arm.qd << 0.0, 1.5, 0.0, -1.5, 0.0, 0.0, 0.0;
  for (int k = 0; k < 500; ++k) {
    arm.step(Vector7::Constant(200.0));
    ASSERT_TRUE((arm.last_tau.cwiseAbs().array() <= 0.8 * panda().tau_max.array() + 1e-9).all()) << "step " << k;
  }
}

namespace {

std::string errorOf(const std::string& text) {
  try {
    loadControllerConfig(handover::test::writeTempFile("guard_cfg.yaml", text));
  } catch (const handover::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LimitGuardSettings, ReadFromTheControllerConfig) {
  const ControllerConfig c = loadControllerConfig(
      handover::test::writeTempFile("guard_ok.yaml", "limit_guard:\n  position_margin: 0.01\n  velocity_scale: 0.9\n"
                                 "  deceleration_scale: 0.4\n  torque_scale: 0.95\n"));
  EXPECT_DOUBLE_EQ(c.limit_guard.position_margin, 0.01);
  EXPECT_DOUBLE_EQ(c.limit_guard.velocity_scale, 0.9);
  EXPECT_DOUBLE_EQ(c.limit_guard.deceleration_scale, 0.4);
  EXPECT_DOUBLE_EQ(c.limit_guard.torque_scale, 0.95);
  // the shipped file holds the documented defaults
  const ControllerConfig d = loadControllerConfig(defaultControllerConfigPath());
  EXPECT_DOUBLE_EQ(d.limit_guard.position_margin, LimitGuardSettings().position_margin);
  EXPECT_DOUBLE_EQ(d.limit_guard.velocity_scale, LimitGuardSettings().velocity_scale);
  EXPECT_DOUBLE_EQ(d.limit_guard.deceleration_scale, LimitGuardSettings().deceleration_scale);
  EXPECT_DOUBLE_EQ(d.limit_guard.torque_scale, LimitGuardSettings().torque_scale);
}

TEST(LimitGuardSettings, BadValuesNameTheKey) {
  std::string e = errorOf("limit_guard:\n  velocity_scal: 0.9\n");
  EXPECT_NE(e.find("limit_guard.velocity_scal"), std::string::npos) << e;
  e = errorOf("limit_guard:\n  deceleration_scale: 0\n");
  EXPECT_NE(e.find("limit_guard.deceleration_scale"), std::string::npos) << e;
  e = errorOf("limit_guard:\n  torque_scale: 1.5\n");
  EXPECT_NE(e.find("limit_guard.torque_scale"), std::string::npos) << e;
  e = errorOf("limit_guard:\n  position_margin: -0.01\n");
  EXPECT_NE(e.find("limit_guard.position_margin"), std::string::npos) << e;
  e = errorOf("limit_guard: 3\n");
  EXPECT_NE(e.find("limit_guard"), std::string::npos) << e;
}

TEST(LimitGuardSettings, QpLimitsBeyondTheGuardStillLoad) {
  // the guard's limits are the hard ones: QP limits looser than them are no
  // error (the guard then acts, and counts), so configurations that loaded
  // before the guard existed still load
  EXPECT_EQ(errorOf("limits:\n  velocity:\n    scale: 1.0\n  position:\n    safety: 0.0\n"), "");
}
