// Contact report: robot-person contacts only when the person touches the arm;
// the object on the table or on the floor.
#include <gtest/gtest.h>

#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

using test::personAway;

TEST(Contacts, RobotPersonContactOnlyWhenTheHandIsOnTheArm) {
  Simulation sim;
  sim.load();
  ASSERT_TRUE(sim.setHumanPoses(personAway()));
  int worst_away = 0;
  for (int i = 0; i < 200; ++i) {
    test::holdStep(sim, test::readyPosture());
    worst_away = std::max(worst_away, sim.contacts().robot_human);
  }
  EXPECT_EQ(worst_away, 0);

  // the person's palm on the robot's hand (3 cm above the flange, where the palm capsule is)
  HumanBodyPoses onto = personAway();
  const Eigen::Isometry3d tcp = sim.tcpPose();
  onto.hand = Eigen::Isometry3d::Identity();
  onto.hand.translation() = tcp * Eigen::Vector3d(0, 0, -0.1034 + 0.03);
  ASSERT_TRUE(sim.setHumanPoses(onto));
  test::holdStep(sim, test::readyPosture());
  EXPECT_GT(sim.contacts().robot_human, 0);

  // and gone again once the hand leaves
  ASSERT_TRUE(sim.setHumanPoses(personAway()));
  for (int i = 0; i < 50; ++i) test::holdStep(sim, test::readyPosture());
  EXPECT_EQ(sim.contacts().robot_human, 0);
}

TEST(Contacts, RejectsNonFinitePosesAndLengths) {
  Simulation sim;
  sim.load();
  HumanBodyPoses p = personAway();
  p.forearm_length = -0.1;
  EXPECT_FALSE(sim.setHumanPoses(p));
  p = personAway();
  p.hand.translation().x() = std::nan("");
  EXPECT_FALSE(sim.setHumanPoses(p));
  EXPECT_TRUE(sim.humanHandPose().matrix().allFinite());
}

// The scene starts the object resting on the table; a run places it in the
// person's hand before the first step. The contacts read then must be those
// of the object in the hand (a stale table contact judged every generated
// handover a drop at t = 0).
TEST(Contacts, PlacingTheObjectRefreshesItsContacts) {
  Simulation sim;
  sim.load();
  sim.reset(test::readyPosture(), 0.08);
  sim.placeObject(test::pose(0.45, 0.3, 0.02));  // on the table top
  EXPECT_TRUE(sim.contacts().object_on_table);
  sim.placeObject(test::pose(0.84, 0.10, 0.28));  // in the air, beyond the table
  EXPECT_FALSE(sim.contacts().object_on_table);
  EXPECT_FALSE(sim.contacts().object_on_floor);
}

TEST(Contacts, ObjectDroppedOnTheTableOrTheFloor) {
  Simulation sim;
  sim.load();
  sim.placeObject(test::pose(0.45, -0.3, 0.25));
  test::holdStep(sim, test::readyPosture());
  EXPECT_FALSE(sim.contacts().object_on_table) << "still in the air";
  for (int i = 0; i < 600; ++i) test::holdStep(sim, test::readyPosture());
  ContactReport r = sim.contacts();
  EXPECT_TRUE(r.object_on_table);
  EXPECT_FALSE(r.object_on_floor);

  // beside the table (|y| > 0.5): it lands on the floor
  sim.placeObject(test::pose(0.3, -0.75, 0.1));
  for (int i = 0; i < 900; ++i) test::holdStep(sim, test::readyPosture());
  r = sim.contacts();
  EXPECT_TRUE(r.object_on_floor);
  EXPECT_FALSE(r.object_on_table);
  EXPECT_LT(sim.object().pose.translation().z(), -0.6);
}

}  // namespace
}  // namespace handover::sim
