// Stow / presentation: a held object, grasped in any orientation, ends upright
// near the nominal position at a reachable configuration.
#include <gtest/gtest.h>

#include <cmath>

#include "control/grasp/chain_kinematics.hpp"
#include "control/grasp/upright_placement.hpp"
#include "tests/control/grasp/panda_fixture.hpp"
#include "tests/support/units.hpp"

namespace handover::control::grasp {
namespace {

using handover::test::kDeg;

// the held object's pose in the world at q
Isometry objectAt(const Model& model, const Vector7& q, const HeldObject& held) {
  ChainPoses poses;
  chainPoses(model, q, poses);
  return chainFramePose(model, poses, model.frameId("tcp")) * held.object_in_tcp;
}

// held by a grasp frame given in the object frame (the TCP sits on the grasp frame)
HeldObject heldBy(const Matrix3& grasp_in_object, const Vector3& grasp_point) {
  Isometry grasp = Isometry::Identity();
  grasp.linear() = grasp_in_object;
  grasp.translation() = grasp_point;
  HeldObject h;
  h.object_in_tcp = grasp.inverse();
  return h;
}

const Vector3 kStow(0.35, 0.0, 0.40);  // object position near config/fsm.yaml's stow pose

void expectUprightAt(const Model& model, const HeldObject& held, const UprightPlacement& p, const Vector3& nominal) {
  ASSERT_TRUE(p.found);
  const Isometry X_obj = objectAt(model, p.q, held);
  const Vector3 up = X_obj.linear() * held.up_axis;
  EXPECT_LT(std::acos(std::min(1.0, up.z())), 1.0 * kDeg);  // the IK reaches the upright pose itself
  EXPECT_NEAR(std::acos(std::min(1.0, up.z())), p.tilt, 1e-6);
  EXPECT_LT((X_obj.translation() - (nominal + p.offset)).norm(), 1e-3);
  EXPECT_LT((X_obj.translation() - p.object.translation()).norm(), 1e-3);
  EXPECT_GE(smallestLimitDistance(model, p.q), 0.0);
}

TEST(UprightPlacement, CommonGraspsStowUprightAtTheNominalPosition) {
  const Model& model = testing::panda();
  const GraspSelectionConfig& cfg = testing::shippedConfig();
  const struct {
    const char* name;
    Matrix3 grasp;
  } grasps[] = {
      {"top", Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix()},
      {"side", Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix()},
      {"side, fingers vertical", (Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()) * Eigen::AngleAxisd(M_PI / 2, Vector3::UnitZ())).toRotationMatrix()},
      {"45 degrees", Eigen::AngleAxisd(3 * M_PI / 4, Vector3::UnitY()).toRotationMatrix()},
      {"from below", Eigen::AngleAxisd(0.2, Vector3::UnitY()).toRotationMatrix()},
  };
  for (const auto& g : grasps) {
    SCOPED_TRACE(g.name);
    const HeldObject held = heldBy(g.grasp, Vector3(0.0, 0.0, 0.03));
    const UprightPlacement p = findUprightPlacement(model, held, kStow, testing::readyConfiguration(), cfg);
    expectUprightAt(model, held, p, kStow);
    EXPECT_EQ(p.offset, Vector3::Zero());
    EXPECT_GE(smallestLimitDistance(model, p.q), 0.1);
  }
}

TEST(UprightPlacement, AnyGraspOrientationFindsAnUprightPose) {
  const Model& model = testing::panda();
  const GraspSelectionConfig& cfg = testing::shippedConfig();
  std::mt19937 rng(4);
  std::normal_distribution<double> n01(0.0, 1.0);
  int found = 0;
  const int n = 40;
  for (int k = 0; k < n; ++k) {
    Quaternion r(n01(rng), n01(rng), n01(rng), n01(rng));  // uniform on SO(3) once normalised
    r.normalize();
    const HeldObject held = heldBy(r.toRotationMatrix(), Vector3::Zero());
    const UprightPlacement p = findUprightPlacement(model, held, kStow, testing::readyConfiguration(), cfg);
    if (!p.found) continue;
    ++found;
    expectUprightAt(model, held, p, kStow);
  }
  EXPECT_EQ(found, n);
}

TEST(UprightPlacement, PresentationFarOutMovesInOrReportsNone) {
  const Model& model = testing::panda();
  const GraspSelectionConfig& cfg = testing::shippedConfig();
  const HeldObject side = heldBy(Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix(), Vector3::Zero());
  // 1 m out is beyond a side grasp's reach; one of the offsets comes back in
  const Vector3 far(1.0, 0.0, 0.35);
  const UprightPlacement p = findUprightPlacement(model, side, far, testing::readyConfiguration(), cfg);
  expectUprightAt(model, side, p, far);
  EXPECT_NE(p.offset, Vector3::Zero());
  // 1.5 m out: nothing
  EXPECT_FALSE(findUprightPlacement(model, side, Vector3(1.5, 0.0, 0.3), testing::readyConfiguration(), cfg).found);
}

TEST(UprightPlacement, KeepsTheArmAwayFromAnObstacle) {
  // presentation to a receiver whose forearm lies where the best placement's elbow goes
  const Model& model = testing::panda();
  const GraspSelectionConfig& cfg = testing::shippedConfig();
  const HeldObject side = heldBy(Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix(), Vector3::Zero());
  const Vector3 give(0.6, 0.0, 0.35);
  const UprightPlacement free_best = findUprightPlacement(model, side, give, testing::readyConfiguration(), cfg);
  ASSERT_TRUE(free_best.found);
  ChainPoses poses;
  chainPoses(model, free_best.q, poses);
  const Vector3 elbow = poses.oMb[4].translation();
  const ObstacleCapsule forearm{elbow + Vector3(-0.1, 0.0, 0.08), elbow + Vector3(0.1, 0.0, 0.08), 0.04};
  const UprightPlacement p = findUprightPlacement(model, side, give, testing::readyConfiguration(), cfg, &forearm, 1);
  expectUprightAt(model, side, p, give);
  const double d_free = armClearance(model, poses, &forearm, 1);
  chainPoses(model, p.q, poses);
  EXPECT_GT(armClearance(model, poses, &forearm, 1), d_free + 0.02);
}

TEST(UprightPlacement, UprightPoseHasTheUpAxisAlongWorldZ) {
  for (const Vector3& up : {Vector3(0, 0, 1), Vector3(1, 0, 0), Vector3(0, -1, 0), Vector3(0, 0, -1), Vector3(1, 2, 3)}) {
    for (double yaw : {0.0, 1.0, -2.5}) {
      const Isometry X = uprightObjectPose(up, yaw, Vector3(0.1, 0.2, 0.3));
      EXPECT_LT((X.linear() * up.normalized() - Vector3::UnitZ()).norm(), 1e-9) << up.transpose();
      EXPECT_LT((X.translation() - Vector3(0.1, 0.2, 0.3)).norm(), 1e-15);
    }
  }
  // yaw turns the object about world z
  const Isometry X0 = uprightObjectPose(Vector3::UnitZ(), 0.0, Vector3::Zero());
  const Isometry X1 = uprightObjectPose(Vector3::UnitZ(), 0.7, Vector3::Zero());
  EXPECT_NEAR(std::atan2(X1.linear()(1, 0), X1.linear()(0, 0)) - std::atan2(X0.linear()(1, 0), X0.linear()(0, 0)), 0.7, 1e-12);
}

}  // namespace
}  // namespace handover::control::grasp
