#include "scenes/human/two_link_arm.hpp"

#include <gtest/gtest.h>

using namespace handover::human;

namespace {
const ArmLengths kArm{0.36, 0.28, 0.075};
const Eigen::Vector3d kShoulder(1.0, 0.175, 0.68);
const Eigen::Vector3d kDownOut = Eigen::Vector3d(0, 0.5, -1).normalized();  // right arm facing -x
}  // namespace

TEST(TwoLinkArm, WristAtTheHandAndLengthsPreserved) {
  for (const Eigen::Vector3d& target : {Eigen::Vector3d(0.55, 0.05, 0.30), Eigen::Vector3d(0.85, 0.25, 0.10),
                                       Eigen::Vector3d(0.6, 0.4, 0.6), Eigen::Vector3d(0.9, 0.3, 0.5)}) {
    const ArmPlacement a = placeArm(kShoulder, target, kArm, kDownOut);
    ASSERT_TRUE(a.reached);
    EXPECT_NEAR((a.grip - target).norm(), 0.0, 1e-9);
    EXPECT_NEAR((a.elbow - a.shoulder).norm(), kArm.upper_arm, 1e-9);
    EXPECT_NEAR((a.wrist - a.elbow).norm(), kArm.forearm, 1e-9);
    EXPECT_NEAR((a.grip - a.wrist).norm(), kArm.wrist_to_grip, 1e-9);
    // frames: origins and z axes along the links, orthonormal
    EXPECT_NEAR((a.upper_arm.translation() - a.shoulder).norm(), 0.0, 1e-12);
    EXPECT_NEAR((a.upper_arm.translation() + kArm.upper_arm * a.upper_arm.linear().col(2) - a.elbow).norm(), 0, 1e-9);
    EXPECT_NEAR((a.forearm.translation() + kArm.forearm * a.forearm.linear().col(2) - a.wrist).norm(), 0, 1e-9);
    EXPECT_TRUE((a.forearm.linear().transpose() * a.forearm.linear()).isIdentity(1e-9));
    EXPECT_NEAR(a.upper_arm.linear().determinant(), 1.0, 1e-9);
  }
}

TEST(TwoLinkArm, ElbowHangsDownAndOutward) {
  const Eigen::Vector3d target(0.55, 0.05, 0.30);
  const ArmPlacement a = placeArm(kShoulder, target, kArm, kDownOut);
  // the elbow lies below the shoulder-hand line and on the outer (+y) side of it
  const Eigen::Vector3d u = (target - kShoulder).normalized();
  const Eigen::Vector3d mid = kShoulder + (a.elbow - kShoulder).dot(u) * u;
  EXPECT_LT(a.elbow.z(), mid.z());
  EXPECT_GT(a.elbow.y(), mid.y());
  // the mirrored hint mirrors the elbow's side
  const ArmPlacement b = placeArm(kShoulder, target, kArm, Eigen::Vector3d(0, -0.5, -1).normalized());
  EXPECT_LT(b.elbow.y(), a.elbow.y());
}

TEST(TwoLinkArm, OutOfReachPointsStraightAndFallsShort) {
  const Eigen::Vector3d target = kShoulder + Eigen::Vector3d(-1.0, 0, 0);
  const ArmPlacement a = placeArm(kShoulder, target, kArm, kDownOut);
  EXPECT_FALSE(a.reached);
  EXPECT_NEAR((a.grip - kShoulder).norm(), kArm.upper_arm + kArm.forearm + kArm.wrist_to_grip, 1e-9);
  EXPECT_NEAR((a.grip - kShoulder).normalized().dot(Eigen::Vector3d(-1, 0, 0)), 1.0, 1e-9);
  EXPECT_NEAR((a.elbow - a.shoulder).norm(), kArm.upper_arm, 1e-9);
}
