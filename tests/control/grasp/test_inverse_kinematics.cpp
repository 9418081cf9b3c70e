// IK on our own model: reaches FK of random configurations within the limits,
// and says so when a target is out of reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "control/grasp/chain_kinematics.hpp"
#include "control/grasp/grasp_score.hpp"
#include "control/grasp/inverse_kinematics.hpp"
#include "tests/control/grasp/panda_fixture.hpp"
#include "tests/support/units.hpp"

namespace handover::control::grasp {
namespace {

using handover::test::kDeg;

using testing::tcpPose;

bool withinLimits(const Model& model, const Vector7& q) {
  return (q.array() >= model.q_min.array()).all() && (q.array() <= model.q_max.array()).all();
}

// the seeds a caller would give: "ready" and a few spread over the workspace
std::vector<Vector7> fixedSeeds() {
  std::vector<Vector7> seeds(4);
  seeds[0] = testing::readyConfiguration();
  seeds[1] << 0.8, -0.3, 0.0, -1.8, 0.0, 1.5, 0.8;
  seeds[2] << -0.8, -0.3, 0.0, -1.8, 0.0, 1.5, 0.8;
  seeds[3] << 0.0, 0.3, 0.0, -1.5, 1.5, 1.5, 0.0;
  return seeds;
}

TEST(InverseKinematics, ReachesRandomReachablePosesFromFixedSeeds) {
  const Model& model = testing::panda();
  const int tcp = model.frameId("tcp");
  const std::vector<Vector7> seeds = fixedSeeds();
  IkOptions options;
  std::mt19937 rng(11);
  const int n = 200;
  int converged = 0;
  for (int trial = 0; trial < n; ++trial) {
    const Vector7 q_true = testing::randomConfiguration(model, rng, 0.05);
    const Isometry target = tcpPose(model, q_true);
    const IkResult r = solveIkMultiStart(model, tcp, target, seeds.data(), static_cast<int>(seeds.size()), options);
    EXPECT_TRUE(withinLimits(model, r.q));
    if (!r.converged) continue;
    ++converged;
    // the residuals it reports are the true ones, and meet the brief's accuracy
    double dp = 0.0, dr = 0.0;
    poseError(model, tcp, r.q, target, dp, dr);
    EXPECT_NEAR(dp, r.position_error, 1e-12);
    EXPECT_NEAR(dr, r.orientation_error, 1e-12);
    EXPECT_LT(dp, 1e-3);
    EXPECT_LT(dr, 0.5 * kDeg);
  }
  std::printf("IK from 4 fixed seeds: %d of %d random reachable poses\n", converged, n);
  // random configurations include folded ones whose pose few seeds lead to
  EXPECT_GE(converged, 0.9 * n) << converged << " of " << n;
}

TEST(InverseKinematics, ConvergesFromANearbySeedEveryTime) {
  const Model& model = testing::panda();
  const int tcp = model.frameId("tcp");
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.15);
  IkOptions options;
  for (int trial = 0; trial < 100; ++trial) {
    const Vector7 q_true = testing::randomConfiguration(model, rng, 0.2);
    Vector7 seed = q_true;
    for (int i = 0; i < kArmDofs; ++i) seed[i] += noise(rng);
    const IkResult r = solveIk(model, tcp, tcpPose(model, q_true), seed, options);
    EXPECT_TRUE(r.converged) << "trial " << trial << ": " << r.position_error << " m, " << r.orientation_error
                             << " rad after " << r.iterations;
    EXPECT_LT(r.position_error, options.position_tolerance);
    EXPECT_LT(r.orientation_error, options.orientation_tolerance);
    EXPECT_TRUE(withinLimits(model, r.q));
  }
}

TEST(InverseKinematics, ReportsAnUnreachableTargetWithItsResidual) {
  const Model& model = testing::panda();
  const int tcp = model.frameId("tcp");
  const std::vector<Vector7> seeds = fixedSeeds();
  Isometry target = Isometry::Identity();
  target.translation() = Vector3(1.4, 0.2, 0.3);  // the Panda reaches about 0.85 m from joint 2
  const IkResult r = solveIkMultiStart(model, tcp, target, seeds.data(), static_cast<int>(seeds.size()), IkOptions());
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.position_error, 0.3);
  EXPECT_TRUE(withinLimits(model, r.q));
  EXPECT_LE(r.iterations, IkOptions().max_iterations);
}

TEST(InverseKinematics, KeepsTheClearanceFromTheLimits) {
  const Model& model = testing::panda();
  const int tcp = model.frameId("tcp");
  IkOptions options;
  options.limit_clearance = 0.05;
  std::mt19937 rng(3);
  for (int trial = 0; trial < 30; ++trial) {
    const Vector7 q_true = testing::randomConfiguration(model, rng);
    const IkResult r = solveIk(model, tcp, tcpPose(model, q_true), testing::readyConfiguration(), options);
    EXPECT_GE(smallestLimitDistance(model, r.q), options.limit_clearance - 1e-12);
  }
}

}  // namespace
}  // namespace handover::control::grasp
