#include "sim_test_support.hpp"

#include "control/controller_config.hpp"

#include <cmath>

#include <mujoco/mujoco.h>

namespace handover::sim::test {

Vector7 readyPosture() { return control::loadControllerConfig(control::defaultControllerConfigPath()).posture.target; }

void holdStep(Simulation& sim, const Vector7& q_ref, double gripper_width, double gripper_force) {
  const mjModel* m = sim.mujocoModel();
  const mjData* d = sim.mujocoData();
  const ArmState s = sim.armState();
  Vector7 kp, kd;
  kp << 600, 600, 600, 600, 250, 150, 50;
  // the PD is explicit in the 1 ms step and the wrist joints are light (no
  // armature in panda.xml): kd * dt must stay well below their inertia
  kd << 50, 50, 50, 50, 15, 8, 4;
  ArmCommand c;
  for (int j = 0; j < 7; ++j) {
    // the joint actuator act_joint<j+1> drives (the simulator contract; no robot's joint names here)
    const int joint = m->actuator_trnid[2 * mj_name2id(m, mjOBJ_ACTUATOR, ("act_joint" + std::to_string(j + 1)).c_str())];
    c.tau[j] = kp[j] * (q_ref[j] - s.q[j]) - kd[j] * s.qd[j] + d->qfrc_bias[m->jnt_dofadr[joint]];
  }
  c.gripper_width = gripper_width;
  c.gripper_force = gripper_force;
  sim.applyCommand(c);
  sim.step();
}

Eigen::Isometry3d pose(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translation() = Eigen::Vector3d(x, y, z);
  p.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return p;
}

double equalityResidual(const Simulation& sim) {
  const mjModel* m = sim.mujocoModel();
  mjData* copy = mj_makeData(m);
  mj_copyData(copy, m, sim.mujocoData());
  mj_forward(m, copy);
  double worst = 0.0;
  for (int i = 0; i < copy->nefc; ++i) {
    if (copy->efc_type[i] == mjCNSTR_EQUALITY) worst = std::max(worst, std::abs(copy->efc_pos[i]));
  }
  mj_deleteData(copy);
  return worst;
}

HumanBodyPoses personAway() {
  HumanBodyPoses p;
  p.hand = pose(0.9, 0.2, 0.2);
  p.forearm = pose(0.95, 0.2, 0.35);
  p.upper_arm = pose(0.95, 0.2, 0.68);
  p.torso = pose(1.0, 0.0, -0.75, 0, 0, M_PI);
  return p;
}

}  // namespace handover::sim::test
