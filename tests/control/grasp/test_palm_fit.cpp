// How deep the gripper can take a grasp: the palm keeps out of the object.
#include <gtest/gtest.h>

#include <cmath>

#include "control/grasp/palm_fit.hpp"

namespace handover::control::grasp {
namespace {

io::ObjectShape box(double x, double y, double z) { return {io::ObjectShape::Kind::kBox, Vector3(x, y, z)}; }
io::ObjectShape cylinder(double radius, double height) {
  return {io::ObjectShape::Kind::kCylinder, Vector3(radius, height, 0.0)};
}
io::ObjectShape sphere(double radius) { return {io::ObjectShape::Kind::kSphere, Vector3(radius, 0.0, 0.0)}; }

// grasp frame in the object frame: TCP at `pos`, turned by `pitch` about y from
// straight down (pitch 0: the approach along the object's -z, from above)
Isometry graspAt(const Vector3& pos, double pitch) {
  Isometry g = Isometry::Identity();
  g.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(pitch, Vector3::UnitY()).toRotationMatrix() *
               Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  g.translation() = pos;
  return g;
}

TEST(PalmFit, AGraspThePalmAllowsIsLeftAsItIs) {
  const PalmGeometry palm;
  // from above, 4 cm into a box 17 cm tall: the palm 4.5 cm behind the TCP stays over the top face
  EXPECT_DOUBLE_EQ(palmShift(box(0.06, 0.05, 0.17), graspAt({0, 0, 0.045}, 0.0), palm), 0.0);
  // a ball through its centre at 45 degrees, a bottle from the side or from above
  EXPECT_DOUBLE_EQ(palmShift(sphere(0.035), graspAt(Vector3::Zero(), M_PI / 4), palm), 0.0);
  EXPECT_DOUBLE_EQ(palmShift(cylinder(0.035, 0.2), graspAt({0, 0, 0.065}, M_PI / 2), palm), 0.0);
  EXPECT_DOUBLE_EQ(palmShift(cylinder(0.035, 0.2), graspAt({0, 0, 0.06}, 0.0), palm), 0.0);
}

// The benchmark's g91_00315: 45 degrees onto a box 10 cm long, the TCP on its
// axis 4.5 cm below the top face. The box's top edge lies 6.7 cm behind the
// TCP along the approach axis, under the palm: the grasp moves back until the
// palm keeps its clearance, 6.7 - 4.54 + 0.5 = 2.7 cm (to the sampling's 4 mm).
TEST(PalmFit, AnAngledGraspIntoALongBoxMovesBackUntilThePalmClearsItsEdge) {
  const PalmGeometry palm;
  const io::ObjectShape long_box = box(0.0997, 0.0647, 0.156);
  const Isometry grasp = graspAt({0, 0, 0.033}, M_PI / 4);
  const double shift = palmShift(long_box, grasp, palm);
  const double edge_behind = std::sqrt(0.5) * (0.0997 / 2 + (0.078 - 0.033));
  EXPECT_NEAR(shift, edge_behind - palm.depth + palm.clearance, 0.004);
  // moved back along its own approach axis, its orientation kept
  const Isometry fitted = fitToPalm(long_box, grasp, palm);
  EXPECT_LT((fitted.linear() - grasp.linear()).norm(), 1e-12);
  EXPECT_NEAR((grasp.translation() - fitted.translation()).dot(grasp.linear().col(2)), shift, 1e-12);
  EXPECT_NEAR((grasp.translation() - fitted.translation()).cross(grasp.linear().col(2)).norm(), 0.0, 1e-12);
  // once moved, it needs no more
  EXPECT_LT(palmShift(long_box, fitted, palm), 0.004);
}

// From the side through the middle of a box 12 cm deep: its near face is 6 cm
// behind the TCP, the palm 4.5 cm: back by the difference and the clearance.
TEST(PalmFit, ASideGraspThroughADeepBoxMovesBackToItsNearFace) {
  const PalmGeometry palm;
  const double shift = palmShift(box(0.12, 0.05, 0.18), graspAt(Vector3::Zero(), M_PI / 2), palm);
  EXPECT_NEAR(shift, 0.06 - palm.depth + palm.clearance, 0.003);
}

// Moved back past where the object begins, nothing would lie between the
// fingers: such a grasp is left as declared (it was never the palm's doing).
TEST(PalmFit, AGraspThatWouldLeaveTheObjectIsNotMoved) {
  PalmGeometry palm;
  palm.half_length = 0.3;  // a palm wide enough to cover the whole box
  // from above, 4 cm above the top face of a flat wide box: the fingers would not reach it anyway
  EXPECT_DOUBLE_EQ(palmShift(box(0.3, 0.05, 0.04), graspAt({0, 0, 0.06}, 0.0), palm), 0.0);
}

}  // namespace
}  // namespace handover::control::grasp
