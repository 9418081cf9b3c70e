// The gravity-hold constraint (control/constraints/gravity_hold_limit.hpp):
// under torque limits too low for a far reach, a pose task pulling the arm out
// stops where gravity takes `share` of a joint's scaled limit, and without the
// constraint the same task pulls it further; near its rest posture it adds no
// row.
#include <gtest/gtest.h>

#include <cmath>

#include "control/constraints/gravity_hold_limit.hpp"
#include "control/controller.hpp"
#include "tests/control/constraints/pose_pull.hpp"

using namespace handover::control;

namespace {

struct Reach {
  double worst_share = 0.0;  ///< largest |g_j| / (scale tau_max_j) over the run
  int optimal = 0;
};

// 3 s of a pose task pulling the TCP 0.45 m out and 0.2 m down, the arm
// integrated as a double integrator from the solved accelerations
Reach reachOut(bool with_constraint, double scale) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  ControllerConfig cfg;
  cfg.limits.torque_scale = scale;
  cfg.pose_task.translation.gains = PdGains::critical(40.0);
  cfg.pose_task.orientation.gains = PdGains::critical(40.0);
  Controller ctl(model, cfg);
  EXPECT_TRUE(ctl.setConstraintEnabled("gravity_hold", with_constraint));
  ControlInputs in = handover::test::startPosePull(ctl, cfg, [](Isometry target) {
    target.translation() += Vector3(0.45, 0.0, -0.2);
    return target;
  });

  Reach r;
  const double dt = cfg.period;
  Vector7 q = in.q, v = Vector7::Zero();
  for (int k = 0; k < 3000; ++k) {
    in.time = k * dt;
    in.q = q;
    in.qd = v;
    ctl.step(in);
    if (ctl.lastStatus() == QpStatus::kOptimal) ++r.optimal;
    for (int j = 0; j < kArmDofs; ++j)
      r.worst_share = std::max(r.worst_share, std::abs(ctl.data().g[j]) / (scale * model.tau_max[j]));
    v += ctl.lastQdd() * dt;
    q += v * dt;
  }
  return r;
}

}  // namespace

TEST(GravityHoldLimit, AnArmReachingOutStopsWhereGravityTakesItsShareOfTheLimit) {
  const double share = GravityHoldParams().share;
  const Reach held = reachOut(true, 0.5);
  EXPECT_EQ(held.optimal, 3000);
  EXPECT_LE(held.worst_share, share + 0.005);
  EXPECT_GT(held.worst_share, share - GravityHoldParams().interaction) << "never came near the share: proves nothing";
  // the same pull without the constraint takes the arm out to where gravity needs more
  const Reach free = reachOut(false, 0.5);
  EXPECT_GT(free.worst_share, share + 0.05);
}

TEST(GravityHoldLimit, AddsNoRowWhileGravityIsWellInsideItsShare) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  Data data(model);
  const ControllerConfig cfg;
  computeAll(model, data, cfg.posture.target, Vector7::Zero());
  GravityHoldLimit c(model, 1.0);
  ControlContext ctx;
  ctx.model = &model;
  ctx.data = &data;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(kArmDofs, kNumVars);
  Eigen::VectorXd lb(kArmDofs), ub(kArmDofs);
  Eigen::VectorXd xl = Eigen::VectorXd::Constant(kNumVars, -100.0), xu = Eigen::VectorXd::Constant(kNumVars, 100.0);
  EXPECT_EQ(c.compute(ctx, C, lb, ub, xl, xu), 0);
  // at a tenth of the datasheet torque the same posture is inside every zone it can be:
  // a row per joint that gravity loads, each bounding the rate of |g_j|
  GravityHoldLimit weak(model, 0.1);
  const int rows = weak.compute(ctx, C, lb, ub, xl, xu);
  EXPECT_GE(rows, 2);
  for (int r = 0; r < rows; ++r) {
    EXPECT_GT(C.row(r).norm(), 0.0);
    EXPECT_TRUE(std::isfinite(ub[r]));
  }
}

TEST(GravityHoldLimit, RefusesAnInteractionZoneWiderThanTheShare) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  GravityHoldParams p;
  p.share = 0.3;
  p.interaction = 0.4;
  EXPECT_THROW(GravityHoldLimit(model, 1.0, p), std::invalid_argument);
}
