// Torque limits: with a demanding pose task and reduced torque limits, every
// solved qddot gives |M qddot + h| <= tau_max (payload included), and the
// limit is actually reached (the test is not vacuous).
#include <gtest/gtest.h>

#include "control/controller.hpp"
#include "control/so3.hpp"
#include "tests/control/constraints/pose_pull.hpp"

using namespace handover::control;

TEST(JointTorqueLimit, SolvedAccelerationsRespectTorqueLimits) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  ControllerConfig cfg;
  cfg.limits.torque_scale = 0.5;
  cfg.limits.velocity_scale = 1.0;
  cfg.limit_guard.velocity_scale = 1.0;  // the QP's own rows are under test: the limit guard stays out of the way
  cfg.pose_task.translation.gains = PdGains::critical(150.0);
  cfg.pose_task.orientation.gains = PdGains::critical(150.0);
  Controller ctl(model, cfg);
  ControlInputs in = handover::test::startPosePull(ctl, cfg, [](Isometry target) {
    target.translation() += Vector3(0.25, 0.3, -0.2);
    target.linear() = expRotation(Vector3(0.0, 0.0, 1.2)) * target.linear();
    return target;
  });
  Payload payload;
  payload.mass = 1.5;
  payload.com = Vector3(0.0, 0.0, 0.05);
  ctl.setPayload(payload);

  const Vector7 limit = 0.5 * model.tau_max;
  const double dt = cfg.period;
  int saturated = 0, optimal = 0;
  Vector7 q = in.q, v = Vector7::Zero();
  for (int k = 0; k < 1500; ++k) {
    in.time = k * dt;
    in.q = q;
    in.qd = v;
    ctl.step(in);
    if (ctl.lastStatus() != QpStatus::kOptimal) continue;
    ++optimal;
    // torque from the model's M and h (payload included), as the rows say
    const Vector7 tau = ctl.data().M * ctl.lastQdd() + ctl.data().h;
    for (int i = 0; i < 7; ++i) {
      ASSERT_LE(std::abs(tau[i]), limit[i] * (1.0 + 1e-9) + 1e-9) << "joint " << i + 1 << " step " << k;
      if (std::abs(tau[i]) > 0.999 * limit[i]) ++saturated;
    }
    EXPECT_LT((ctl.lastTau() - tau).norm(), 1e-9);
    v += ctl.lastQdd() * dt;
    q += v * dt;
  }
  EXPECT_GT(optimal, 1400);
  EXPECT_GT(saturated, 0) << "the torque limit never bound: the test proves nothing";
}
