// Gripper and wrist sensor: a 0.5 kg object pinched between the fingers does
// not slip while the arm holds still; the F/T sensor reads the hand's weight,
// plus the object's when it is held; torque commands are clamped.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

constexpr double kG = 9.81;

// F/T force in world axes (the sensor frame's rotation is the hand's)
Eigen::Vector3d worldForce(const Simulation& sim, const ArmState& s) {
  const mjModel* m = sim.mujocoModel();
  const mjData* d = sim.mujocoData();
  const int site = mj_name2id(m, mjOBJ_SITE, "ft_sensor");
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R(r, c) = d->site_xmat[9 * site + 3 * r + c];
  return R * s.wrench.head<3>();
}

TEST(FtSensor, ReadsTheHandWeightAtRest) {
  Simulation sim;
  sim.load();
  for (int i = 0; i < 500; ++i) test::holdStep(sim, test::readyPosture());
  const ArmState s = sim.armState();
  const double m_hand = sim.handMass();
  EXPECT_GT(m_hand, 0.5);  // the hand and fingers, not a massless site
  const Eigen::Vector3d f = worldForce(sim, s);
  EXPECT_NEAR(f.z(), -m_hand * kG, 0.02 * m_hand * kG) << f.transpose();
  EXPECT_LT(f.head<2>().norm(), 0.02 * m_hand * kG) << f.transpose();

  // torque about the sensor origin = lever arm to the hand's centre of mass x weight
  const mjModel* m = sim.mujocoModel();
  const mjData* d = sim.mujocoData();
  const int hand = mj_name2id(m, mjOBJ_BODY, "panda_hand");
  const int site = mj_name2id(m, mjOBJ_SITE, "ft_sensor");
  Eigen::Vector3d com, origin;
  Eigen::Matrix3d R;
  for (int i = 0; i < 3; ++i) {
    com[i] = d->subtree_com[3 * hand + i];
    origin[i] = d->site_xpos[3 * site + i];
    for (int c = 0; c < 3; ++c) R(i, c) = d->site_xmat[9 * site + 3 * i + c];
  }
  const Eigen::Vector3d expected = (com - origin).cross(Eigen::Vector3d(0, 0, -m_hand * kG));
  EXPECT_LT((R * s.wrench.tail<3>() - expected).norm(), 0.01) << (R * s.wrench.tail<3>()).transpose() << " vs "
                                                              << expected.transpose();
}

TEST(Gripper, HalfKiloObjectDoesNotSlipAndTheSensorFeelsIt) {
  SimOptions o;
  o.object.shape = ObjectShape::Cylinder;
  o.object.size = {0.025, 0.12};
  o.object.mass = 0.5;
  Simulation sim;
  sim.load(o);
  // cylinder axis along the tcp x axis, pinched along the hand's y
  const Eigen::Isometry3d in_tcp = test::pose(0, 0, 0, 0, M_PI / 2, 0);
  sim.reset(test::readyPosture(), 0.05, in_tcp);
  for (int i = 0; i < 300; ++i) test::holdStep(sim, test::readyPosture(), 0.0, 70.0);  // close and settle

  const ContactReport r = sim.contacts();
  EXPECT_TRUE(r.left_finger_on_object);
  EXPECT_TRUE(r.right_finger_on_object);
  EXPECT_FALSE(r.object_on_table);
  EXPECT_NEAR(sim.armState().finger_width, 0.05, 2e-3);

  const Eigen::Vector3d start = (sim.tcpPose().inverse() * sim.object().pose).translation();
  double slip = 0.0;
  for (int i = 0; i < 2000; ++i) {
    test::holdStep(sim, test::readyPosture(), 0.0, 70.0);
    const Eigen::Vector3d now = (sim.tcpPose().inverse() * sim.object().pose).translation();
    slip = std::max(slip, (now - start).norm());
  }
  EXPECT_LT(slip, 5e-3);
  EXPECT_GT(sim.object().pose.translation().z(), 0.3) << "still up in the gripper";

  // the wrist sensor carries hand + object
  const Eigen::Vector3d f = worldForce(sim, sim.armState());
  EXPECT_NEAR(f.z(), -(sim.handMass() + 0.5) * kG, 0.03 * (sim.handMass() + 0.5) * kG) << f.transpose();
}

TEST(Gripper, OpenReleasesTheObject) {
  SimOptions o;
  o.object.size = {0.025, 0.12};
  Simulation sim;
  sim.load(o);
  sim.reset(test::readyPosture(), 0.05, test::pose(0, 0, 0, 0, M_PI / 2, 0));
  for (int i = 0; i < 300; ++i) test::holdStep(sim, test::readyPosture(), 0.0, 70.0);
  const double z_held = sim.object().pose.translation().z();
  for (int i = 0; i < 800; ++i) test::holdStep(sim, test::readyPosture(), 0.08, 70.0);
  EXPECT_GT(sim.armState().finger_width, 0.07);
  EXPECT_LT(sim.object().pose.translation().z(), z_held - 0.2);
  EXPECT_TRUE(sim.contacts().object_on_table);
}

TEST(Commands, TorquesAreClampedAndNonFiniteEntriesZeroed) {
  Simulation sim;
  sim.load();
  ArmCommand c;
  c.tau << 500, -500, 10, std::nan(""), 50, -50, 1;
  sim.applyCommand(c);
  sim.step();
  const ArmState s = sim.armState();
  EXPECT_DOUBLE_EQ(s.tau_measured[0], 87.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[1], -87.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[2], 10.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[3], 0.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[4], 12.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[5], -12.0);
  EXPECT_DOUBLE_EQ(s.tau_measured[6], 1.0);
}

}  // namespace
}  // namespace handover::sim
