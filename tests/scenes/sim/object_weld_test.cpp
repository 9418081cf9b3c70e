// The person's grip (weld human_hand -> object): switching on keeps the
// current relative pose (no jump, the MuJoCo 2.2.2 eq_data convention is
// verified through the constraint residual), the object then follows the
// moving hand, and switching off lets it fall.
#include <iostream>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

// hand moving with constant linear and angular velocity (world axes)
struct MovingHand {
  Eigen::Isometry3d start = test::pose(0.70, 0.10, 0.40, 0.3, -0.2, 0.8);
  Eigen::Vector3d v = Eigen::Vector3d(-0.30, 0.10, 0.05);  // m/s
  Eigen::Vector3d w = Eigen::Vector3d(0.0, 0.2, 0.5);      // rad/s
  Eigen::Isometry3d at(double t) const {
    Eigen::Isometry3d x = start;
    x.translation() += v * t;
    x.linear() = Eigen::AngleAxisd(w.norm() * t, w.normalized()).toRotationMatrix() * start.linear();
    return x;
  }
};

void moveHand(Simulation& sim, const Eigen::Isometry3d& hand) {
  HumanBodyPoses p;
  p.hand = hand;
  p.forearm = test::pose(1.0, 0.3, 0.3);  // out of the arm's way
  p.upper_arm = test::pose(1.0, 0.3, 0.6);
  p.torso = test::pose(1.2, 0.0, -0.75, 0, 0, M_PI);
  ASSERT_TRUE(sim.setHumanPoses(p));
}

double rotationAngle(const Eigen::Matrix3d& R) { return Eigen::AngleAxisd(R).angle(); }

TEST(ObjectWeld, SwitchingOnWhileTheHandMovesKeepsThePoseAndFollows) {
  Simulation sim;
  sim.load();
  const MovingHand hand;
  // the object sits in the hand at an offset unlike the scene's compiled one
  const Eigen::Isometry3d offset = test::pose(0.02, -0.03, 0.06, 0.5, 0.1, -0.4);
  double t = 0.0;
  for (; t < 0.1; t += sim.timestep()) {
    moveHand(sim, hand.at(t));
    sim.step();
  }
  moveHand(sim, hand.at(t));
  const Eigen::Isometry3d h0 = hand.at(t);
  const Eigen::Isometry3d obj0 = h0 * offset;
  Vector6 vel;
  vel.head<3>() = hand.v + hand.w.cross(obj0.translation() - h0.translation());
  vel.tail<3>() = hand.w;
  sim.placeObject(obj0, vel);
  ASSERT_LT(test::equalityResidual(sim), 1e-12) << "weld is off: no equality rows";

  // the weld's compiled reference (the scene's start poses) is far from the
  // actual grip: switching on without rewriting it would snap the object
  const mjModel* m = sim.mujocoModel();
  const int weld = mj_name2id(m, mjOBJ_EQUALITY, "object_weld");
  const Eigen::Vector3d compiled(m->eq_data[mjNEQDATA * weld + 3], m->eq_data[mjNEQDATA * weld + 4],
                                 m->eq_data[mjNEQDATA * weld + 5]);
  ASSERT_GT((compiled - offset.translation()).norm(), 0.1);

  sim.setObjectWeld(true);
  ASSERT_TRUE(sim.objectWelded());
  ASSERT_TRUE(sim.contacts().object_welded_to_hand);
  // the switch itself moves nothing and leaves the weld satisfied (this checks
  // the eq_data layout: anchor 0..2, relpos 3..5, relquat 6..9)
  EXPECT_LT((sim.object().pose.matrix() - obj0.matrix()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(test::equalityResidual(sim), 1e-6);

  // 1 s later the hand has travelled ~0.3 m and turned ~0.5 rad; the object kept its grip pose
  double worst_pos = 0.0, worst_rot = 0.0;
  for (int i = 0; i < 1000; ++i) {
    sim.step();
    t += sim.timestep();
    moveHand(sim, hand.at(t));
    const Eigen::Isometry3d rel = hand.at(t).inverse() * sim.object().pose;
    worst_pos = std::max(worst_pos, (rel.translation() - offset.translation()).norm());
    worst_rot = std::max(worst_rot, rotationAngle(rel.linear().transpose() * offset.linear()));
  }
  EXPECT_GT((hand.at(t).translation() - h0.translation()).norm(), 0.25);
  // the weld is a stiff spring to a mocap body (which has no velocity in
  // MuJoCo), so the object trails the moving hand slightly (docs/simulation.md)
  EXPECT_LT(worst_pos, 1e-3);
  EXPECT_LT(worst_rot, 0.01);
  std::cout << "weld lag at 0.32 m/s: " << worst_pos * 1e3 << " mm, " << worst_rot << " rad\n";

  // release: the object falls away from the hand
  sim.setObjectWeld(false);
  EXPECT_FALSE(sim.contacts().object_welded_to_hand);
  const double dz0 = sim.object().pose.translation().z() - hand.at(t).translation().z();
  for (int i = 0; i < 200; ++i) {
    sim.step();
    t += sim.timestep();
    moveHand(sim, hand.at(t));
  }
  const double dz1 = sim.object().pose.translation().z() - hand.at(t).translation().z();
  // free fall for 0.2 s drops it ~0.2 m relative to the hand (which rises 1 cm)
  EXPECT_LT(dz1 - dz0, -0.15);
  EXPECT_LT(sim.object().velocity[2], -1.5);
}

TEST(ObjectWeld, SwitchingOnTwiceOrAfterResetStillMatchesTheCurrentPose) {
  Simulation sim;
  sim.load();
  moveHand(sim, test::pose(0.6, -0.2, 0.3, 0, 0, 1.0));
  sim.placeObject(test::pose(0.62, -0.18, 0.35, 0.2, 0, 0));
  sim.setObjectWeld(true);
  EXPECT_LT(test::equalityResidual(sim), 1e-6);
  for (int i = 0; i < 100; ++i) sim.step();
  sim.setObjectWeld(false);
  sim.placeObject(test::pose(0.5, -0.25, 0.25, 0, 0.7, 0));
  sim.setObjectWeld(true);
  EXPECT_LT(test::equalityResidual(sim), 1e-6);
  // placing while welded re-takes the grip where the object was put
  const Eigen::Isometry3d moved = test::pose(0.55, -0.22, 0.28, 0.1, 0.2, 0.3);
  sim.placeObject(moved);
  EXPECT_LT(test::equalityResidual(sim), 1e-6);
  for (int i = 0; i < 200; ++i) sim.step();
  EXPECT_LT((sim.object().pose.translation() - moved.translation()).norm(), 1e-3);
  sim.reset(test::readyPosture(), 0.08);
  EXPECT_FALSE(sim.objectWelded());
}

}  // namespace
}  // namespace handover::sim
