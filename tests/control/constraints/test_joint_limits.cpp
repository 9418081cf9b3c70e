// Joint position damper, velocity and acceleration limits: the bounds they
// put on qddot, and a kinematic simulation that always takes the most
// aggressive admissible acceleration toward a limit and must never pass it.
#include <gtest/gtest.h>

#include <memory>

#include "control/constraints/joint_acceleration_limit.hpp"
#include "control/constraints/joint_position_limit.hpp"
#include "control/constraints/joint_velocity_limit.hpp"
#include "control/formulation/formulation.hpp"

using namespace handover::control;

namespace {

const Model& panda() {
  static const Model m = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return m;
}

struct LimitRig {
  Formulation f;
  QpProblem p;
  Data data{panda()};
  std::shared_ptr<JointPositionLimit> position;
  std::shared_ptr<JointVelocityLimit> velocity;
  explicit LimitRig(const JointPositionLimitParams& params = JointPositionLimitParams(), double vscale = 0.5,
                    double braking = 0.0) {
    f.addConstraint(std::make_shared<JointAccelerationLimit>(panda(), 1.0));
    position = std::make_shared<JointPositionLimit>(panda(), params);
    velocity = std::make_shared<JointVelocityLimit>(panda(), vscale, "joint_velocity", braking, params.safety);
    f.addConstraint(position);
    f.addConstraint(velocity);
    f.reserveProblem(p);
  }
  void bounds(const Vector7& q, const Vector7& v, double dt = 1e-3) {
    data.q = q;  // the limits read only q and v
    data.v = v;
    ControlContext ctx;
    ctx.model = &panda();
    ctx.data = &data;
    ctx.dt = dt;
    f.build(ctx, p);
  }
};

// Pushes every joint toward one side as hard as the bounds allow.
void ramIntoLimits(bool lower, double start_speed_fraction, double vscale = 0.5, double braking = 0.0) {
  const Model& m = panda();
  JointPositionLimitParams params;
  LimitRig rig(params, vscale, braking);
  const double dt = 1e-3;
  const Vector7 vlim = rig.velocity->limit();
  Vector7 q, v;
  for (int i = 0; i < 7; ++i) {
    const double range = m.q_max[i] - m.q_min[i];
    // start just outside the interaction zone, already at speed toward the limit
    q[i] = lower ? m.q_min[i] + 0.15 * range : m.q_max[i] - 0.15 * range;
    v[i] = (lower ? -1.0 : 1.0) * start_speed_fraction * vlim[i];
  }
  Vector7 closest = Vector7::Constant(1e9);
  for (int k = 0; k < 4000; ++k) {
    rig.bounds(q, v, dt);
    const Vector7 a = lower ? rig.p.x_lb.head<7>() : rig.p.x_ub.head<7>();
    ASSERT_TRUE(a.allFinite()) << "step " << k;
    ASSERT_TRUE((rig.p.x_lb.head<7>().array() <= rig.p.x_ub.head<7>().array()).all());
    // exact integration over the period with constant acceleration
    q += v * dt + 0.5 * a * dt * dt;
    v += a * dt;
    for (int i = 0; i < 7; ++i) {
      const double gap = lower ? q[i] - m.q_min[i] : m.q_max[i] - q[i];
      ASSERT_GT(gap, 0.0) << "joint " << i + 1 << " passed its limit at step " << k;
      closest[i] = std::min(closest[i], gap);
    }
  }
  for (int i = 0; i < 7; ++i) {
    const double range = m.q_max[i] - m.q_min[i];
    // it kept the safety margin (half of it, by construction of the position bound)...
    EXPECT_GE(closest[i], 0.5 * params.safety * range - 1e-9) << "joint " << i + 1;
    // ...and was not stopped absurdly early: it got well into the interaction zone
    EXPECT_LT(closest[i], 0.5 * params.interaction * range) << "joint " << i + 1;
  }
}

}  // namespace

TEST(JointPositionLimit, NeverPassesLowerLimits) { ramIntoLimits(true, 1.0); }
TEST(JointPositionLimit, NeverPassesUpperLimits) { ramIntoLimits(false, 1.0); }
TEST(JointPositionLimit, NeverPassesFromRest) { ramIntoLimits(true, 0.0); }
// at the datasheet speed the damper alone cannot brake in its zone (without the cap joint 2 ends
// inside its safety distance): the braking cap slows each joint before it gets there
TEST(JointPositionLimit, NeverPassesAtFullSpeedWithTheBrakingCap) {
  ramIntoLimits(true, 1.0, 1.0, 0.5);
  ramIntoLimits(false, 1.0, 1.0, 0.5);
}

TEST(JointVelocityLimit, BrakingCapIsTheSpeedThatStillStopsBeforeTheLimit) {
  const Model& m = panda();
  const double braking = 0.5;
  LimitRig rig(JointPositionLimitParams(), 1.0, braking);
  const double ds = rig.position->params().safety;
  const double dt = 1e-3;
  for (int i = 0; i < 7; ++i) {
    const double range = m.q_max[i] - m.q_min[i];
    Vector7 q = 0.5 * (m.q_min + m.q_max), v = Vector7::Zero();
    q[i] = m.q_max[i] - ds * range - 0.05;  // 0.05 rad short of the safety distance
    rig.bounds(q, v, dt);
    const double cap = std::sqrt(2.0 * braking * m.a_max[i] * 0.05);
    ASSERT_LT(cap, m.v_max[i]);
    // reachable from rest within the acceleration limit? then the bound is the cap
    const double ub = std::min(cap / dt, m.a_max[i]);
    EXPECT_NEAR(rig.p.x_ub[i], ub, 1e-6) << "joint " << i + 1;
    // away from the limit the datasheet speed is the bound
    EXPECT_NEAR(rig.p.x_lb[i], -m.a_max[i], 1e-9) << "joint " << i + 1;
    // moving at the cap's speed the joint must not speed up
    v[i] = cap;
    rig.bounds(q, v, dt);
    EXPECT_LE(rig.p.x_ub[i], 1e-9) << "joint " << i + 1;
  }
}

TEST(JointPositionLimit, FreeOutsideInteractionZoneAndDampedInside) {
  const Model& m = panda();
  LimitRig rig;
  Vector7 mid = 0.5 * (m.q_min + m.q_max);
  rig.bounds(mid, Vector7::Zero());
  for (int i = 0; i < 7; ++i) {
    EXPECT_FALSE(rig.position->lowerActive(i));
    EXPECT_FALSE(rig.position->upperActive(i));
  }
  // joint 2 inside its lower interaction zone, moving toward the limit
  Vector7 q = mid, v = Vector7::Zero();
  const double range = m.q_max[1] - m.q_min[1];
  q[1] = m.q_min[1] + 0.05 * range;
  v[1] = -0.5;
  const double dt = 0.02;  // long period: the damper, not the acceleration limit, binds
  rig.bounds(q, v, dt);
  EXPECT_TRUE(rig.position->lowerActive(1));
  EXPECT_FALSE(rig.position->upperActive(1));
  // the bound starts at the current velocity plus the configured slack
  // offset * (d - ds), so entering the zone needs no jump in acceleration
  const JointPositionLimitParams& pp = rig.position->params();
  const double slack = pp.damper_offset * (0.05 - pp.safety) * range;
  ASSERT_LT(slack / dt, m.a_max[1]);
  EXPECT_NEAR(v[1] + rig.p.x_lb[1] * dt, v[1] - slack, 1e-9);
  // deeper in the zone the admissible speed toward the limit shrinks
  q[1] = m.q_min[1] + 0.03 * range;
  rig.bounds(q, v, dt);
  EXPECT_GT(v[1] + rig.p.x_lb[1] * dt, v[1] - slack + 1e-6);
  // leaving the zone switches it off again
  rig.bounds(mid, Vector7::Zero());
  EXPECT_FALSE(rig.position->lowerActive(1));
}

TEST(JointPositionLimit, RejectsBadParameters) {
  JointPositionLimitParams p;
  p.safety = 0.2;
  p.interaction = 0.1;
  EXPECT_THROW(JointPositionLimit(panda(), p), std::invalid_argument);
}

TEST(JointVelocityLimit, BoundsReachTheScaledLimitInOnePeriod) {
  const Model& m = panda();
  LimitRig rig(JointPositionLimitParams(), 0.5);
  const Vector7 mid = 0.5 * (m.q_min + m.q_max);
  Vector7 v;
  v << 0.3, -0.2, 0.0, 0.1, -0.1, 0.2, 0.05;
  const double dt = 1e-3;
  rig.bounds(mid, v, dt);
  for (int i = 0; i < 7; ++i) {
    const double vmax = 0.5 * m.v_max[i];
    // acceleration limits are wider than these bounds at this speed, except
    // where the acceleration limit binds first
    const double lb = std::max((-vmax - v[i]) / dt, -m.a_max[i]);
    const double ub = std::min((vmax - v[i]) / dt, m.a_max[i]);
    EXPECT_NEAR(rig.p.x_lb[i], lb, 1e-9);
    EXPECT_NEAR(rig.p.x_ub[i], ub, 1e-9);
  }
  // the speed scale tightens further
  rig.velocity->setSpeedScale(0.1);
  Vector7 fast = Vector7::Zero();
  fast[0] = 0.5 * 0.5 * m.v_max[0];  // above the scaled limit now
  rig.bounds(mid, fast, dt);
  EXPECT_LT(rig.p.x_ub[0], 0.0);  // must slow down
  EXPECT_GE(rig.p.x_ub[0], -m.a_max[0] - 1e-12);  // but within the acceleration limit
}

TEST(JointAccelerationLimit, BoundsAreScaledDatasheetValues) {
  Formulation f;
  f.addConstraint(std::make_shared<JointAccelerationLimit>(panda(), 0.4));
  QpProblem p;
  f.reserveProblem(p);
  Data data(panda());
  ControlContext ctx;
  ctx.model = &panda();
  ctx.data = &data;
  f.build(ctx, p);
  EXPECT_LT((p.x_ub.head<7>() - 0.4 * panda().a_max).norm(), 1e-12);
  EXPECT_LT((p.x_lb.head<7>() + 0.4 * panda().a_max).norm(), 1e-12);
  EXPECT_TRUE(std::isinf(p.x_ub[7]));  // the object's acceleration is not bounded
}
