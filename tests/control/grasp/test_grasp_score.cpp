// The score's blocked-pull term: how much of a receiver's pull the open
// gripper stands in the way of (grasp_score.hpp exitBlock).
#include <gtest/gtest.h>

#include <cmath>

#include "control/grasp/grasp_score.hpp"

namespace handover::control::grasp {
namespace {

// a gripper pointing down (approach -z world) with its fingers closing along world y
Isometry gripperDown() {
  Isometry g = Isometry::Identity();
  g.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();  // x, -y, -z
  return g;
}

TEST(ExitBlock, APullAcrossTheFingersFacesOrOutPastTheTipsIsFree) {
  const Isometry g = gripperDown();
  EXPECT_NEAR(exitBlock(g, Vector3::UnitX()), 0.0, 1e-12);   // across the pads' faces
  EXPECT_NEAR(exitBlock(g, -Vector3::UnitX()), 0.0, 1e-12);
  EXPECT_NEAR(exitBlock(g, -Vector3::UnitZ()), 0.0, 1e-12);  // out past the fingertips
}

TEST(ExitBlock, APullAlongTheClosingAxisOrIntoThePalmIsBlocked) {
  const Isometry g = gripperDown();
  EXPECT_NEAR(exitBlock(g, Vector3::UnitY()), 1.0, 1e-12);   // into one finger pad
  EXPECT_NEAR(exitBlock(g, -Vector3::UnitY()), 1.0, 1e-12);  // into the other
  EXPECT_NEAR(exitBlock(g, Vector3::UnitZ()), 1.0, 1e-12);   // into the palm
  // half way between a free direction and a finger: the blocked share
  const Vector3 diagonal = Vector3(1.0, 1.0, 0.0).normalized();
  EXPECT_NEAR(exitBlock(g, diagonal), std::sqrt(0.5), 1e-12);
  // the palm in full from 30 degrees into it, half at 15 (sin 15 = 0.26)
  const auto tilted = [](double deg) {
    return Vector3(std::cos(deg * M_PI / 180.0), 0.0, std::sin(deg * M_PI / 180.0));
  };
  EXPECT_NEAR(exitBlock(g, tilted(30.0)), 1.0, 1e-12);
  EXPECT_NEAR(exitBlock(g, tilted(15.0)), 2.0 * std::sin(15.0 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(exitBlock(g, tilted(-30.0)), 0.0, 1e-12);  // out past the fingertips
}

TEST(ExitBlock, NoPullBlocksNothing) { EXPECT_EQ(exitBlock(gripperDown(), Vector3::Zero()), 0.0); }

}  // namespace
}  // namespace handover::control::grasp
