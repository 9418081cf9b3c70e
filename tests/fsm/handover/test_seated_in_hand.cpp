// Where a given object sits in the receiver's hand (seated_in_hand.hpp): a
// flat object is lowered until its underside is `seat` above the grip point,
// a ball or an upright bottle stays where object_in_hand puts it.
#include <gtest/gtest.h>

#include <cmath>

#include "fsm/handover/seated_in_hand.hpp"

namespace handover::fsm {
namespace {

Isometry fiveCentimetresUp() {
  Isometry p = Isometry::Identity();
  p.translation() = Vector3(0.01, -0.02, 0.05);
  return p;
}

io::ObjectShape boxShape(double x, double y, double z) { return {io::ObjectShape::Kind::kBox, Vector3(x, y, z)}; }

TEST(SeatedInHand, AFlatObjectIsLoweredOntoTheHand) {
  // a deck of cards 2 cm thick: 5 cm up left its underside 4 cm above the grip point
  const Isometry seated = seatedInHand(fiveCentimetresUp(), boxShape(0.089, 0.064, 0.02), 0.02);
  EXPECT_NEAR(seated.translation().z(), 0.01 + 0.02, 1e-12);
  EXPECT_NEAR(seated.translation().x(), 0.01, 1e-12);  // only the height changes
  EXPECT_NEAR(seated.translation().y(), -0.02, 1e-12);
  EXPECT_TRUE(seated.linear().isApprox(Eigen::Matrix3d::Identity()));
}

TEST(SeatedInHand, ABallOrAnUprightBottleIsNotRaised) {
  const io::ObjectShape ball{io::ObjectShape::Kind::kSphere, Vector3(0.035, 0.0, 0.0)};
  const io::ObjectShape bottle{io::ObjectShape::Kind::kCylinder, Vector3(0.033, 0.19, 0.0)};
  EXPECT_NEAR(seatedInHand(fiveCentimetresUp(), ball, 0.02).translation().z(), 0.05, 1e-12);
  EXPECT_NEAR(seatedInHand(fiveCentimetresUp(), bottle, 0.02).translation().z(), 0.05, 1e-12);
  // a small ball: its underside 2 cm above the grip point
  const io::ObjectShape marble{io::ObjectShape::Kind::kSphere, Vector3(0.02, 0.0, 0.0)};
  EXPECT_NEAR(seatedInHand(fiveCentimetresUp(), marble, 0.02).translation().z(), 0.04, 1e-12);
}

TEST(SeatedInHand, TheHeightIsMeasuredAlongTheHandsVerticalInTheObjectsPresentedTurn) {
  // a remote 17 x 4.5 x 2.2 cm presented on its edge (turned a quarter about x):
  // 4.5 cm tall then, 2.25 cm below its centre
  Isometry on_edge = fiveCentimetresUp();
  on_edge.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitX()).toRotationMatrix();
  EXPECT_NEAR(seatedInHand(on_edge, boxShape(0.17, 0.045, 0.022), 0.02).translation().z(), 0.0225 + 0.02, 1e-12);
}

TEST(SeatedInHand, AnUnknownShapeOrNoSeatLeavesThePlacement) {
  EXPECT_TRUE(seatedInHand(fiveCentimetresUp(), io::ObjectShape{}, 0.02).isApprox(fiveCentimetresUp()));
  EXPECT_TRUE(seatedInHand(fiveCentimetresUp(), boxShape(0.1, 0.1, 0.02), 0.0).isApprox(fiveCentimetresUp()));
}

}  // namespace
}  // namespace handover::fsm
