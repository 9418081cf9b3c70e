// The IK's lean kinematics against the model's full forwardKinematics.
#include <gtest/gtest.h>

#include "control/grasp/chain_kinematics.hpp"
#include "control/model/algorithms.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace handover::control::grasp {
namespace {

TEST(ChainKinematics, MatchesForwardKinematicsForEveryFrame) {
  const Model& model = testing::panda();
  Data data(model);
  std::mt19937 rng(7);
  ChainPoses poses;
  for (int trial = 0; trial < 50; ++trial) {
    const Vector7 q = testing::randomConfiguration(model, rng);
    forwardKinematics(model, data, q, Vector7::Zero());
    chainPoses(model, q, poses);
    for (int f = 0; f < static_cast<int>(model.frames.size()); ++f) {
      const Isometry expected = framePlacement(model, data, f);
      const Isometry got = chainFramePose(model, poses, f);
      EXPECT_LT((expected.matrix() - got.matrix()).norm(), 1e-12) << model.frames[f].name;
      Matrix6x7 J_expected, J_got;
      frameJacobian(model, data, f, J_expected);
      chainFrameJacobian(model, poses, f, J_got);
      EXPECT_LT((J_expected - J_got).norm(), 1e-12) << model.frames[f].name;
    }
  }
}

}  // namespace
}  // namespace handover::control::grasp
