// Bounds that keep the controller stable (control/controller_config_bounds.hpp):
// the PD bound is checked against the discrete loops it is derived from, and
// each configuration the issue measured failing is refused with its key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "control/controller_config.hpp"
#include "control/controller_config_bounds.hpp"
#include "control/model/model.hpp"
#include "control/model/joint_limits.hpp"
#include "tests/support/temp_path.hpp"

using namespace handover;
using namespace handover::control;

namespace {

// largest |e| over the last 100 of `steps` steps of e'' = -K e - D e', from
// e = 1, realised one period at a time by the given integrator
double residual(double k, double d, double dt, bool exact, int steps) {
  double e = 1.0, v = 0.0, worst = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double a = -k * e - d * v;
    if (exact) {
      e += dt * v + 0.5 * dt * dt * a;
      v += dt * a;
    } else {
      v += dt * a;
      e += dt * v;
    }
    if (!std::isfinite(e)) return INFINITY;  // overflowed: diverged
    if (i >= steps - 100) worst = std::max(worst, std::abs(e));
  }
  return worst;
}

std::string loadError(const std::string& text) {
  const std::string path = handover::test::uniqueTempPath("bounds.yaml");
  std::ofstream(path) << text;
  try {
    loadControllerConfig(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PdGainsBound, AcceptedGainsDecayInBothDiscreteLoops) {
  const double dt = 1e-3;
  for (double k : {1.0, 10.0, 1500.0, 1e4, 0.2 / (dt * dt)}) {
    for (double zeta : {0.2, 1.0, 3.0}) {
      const double d = 2.0 * zeta * std::sqrt(k);
      if (!pdGainsProblem(k, d, dt).empty()) continue;
      // long enough for the slowest accepted pole to decay by many e-folds
      const int steps = static_cast<int>(std::min(2e6, 40.0 / (std::min(d / 2.0, std::sqrt(k)) * dt * 0.1)));
      EXPECT_LT(residual(k, d, dt, true, steps), 1.0) << "K " << k << " D " << d;
      EXPECT_LT(residual(k, d, dt, false, steps), 1.0) << "K " << k << " D " << d;
    }
  }
}

TEST(PdGainsBound, DivergingLoopsAreRefused) {
  const double dt = 1e-3;
  // each diverges in at least one of the two loops
  const double cases[][2] = {{1e7, 2.0 * std::sqrt(1e7)}, {1500.0, 1e5}, {1500.0, 0.0}, {4e6, 0.0}};
  for (const auto& c : cases) {
    const bool diverges = residual(c[0], c[1], dt, true, 20000) > 1.0 || residual(c[0], c[1], dt, false, 20000) > 1.0;
    EXPECT_TRUE(diverges) << c[0] << " " << c[1];
    EXPECT_FALSE(pdGainsProblem(c[0], c[1], dt).empty()) << c[0] << " " << c[1];
  }
  // the paper's observation gains at the allowed maximum period
  EXPECT_FALSE(pdGainsProblem(1500.0, 2.0 * std::sqrt(1500.0), 0.1).empty());
  EXPECT_TRUE(pdGainsProblem(1500.0, 2.0 * std::sqrt(1500.0), 1e-3).empty());
}

TEST(ControllerBounds, ShippedConfigPasses) { EXPECT_NO_THROW(loadControllerConfig(defaultControllerConfigPath())); }

TEST(ControllerBounds, MeasuredFailuresAreRefusedWithTheirKey) {
  EXPECT_NE(loadError("period: 0.1\n").find("observation.stiffness"), std::string::npos);
  EXPECT_NE(loadError("observation:\n  stiffness: 1.0e7\n").find(":2:"), std::string::npos);
  EXPECT_NE(loadError("observation:\n  damping: 1.0e5\n").find("observation"), std::string::npos);
  EXPECT_NE(loadError("posture:\n  weight: 0\nqp:\n  regularisation: 0\n").find("qp.regularisation"), std::string::npos);
  EXPECT_NE(loadError("posture:\n  target: [3.0, 0, 0, -1.5, 0, 1.5, 0]\n").find("posture.target"), std::string::npos);
  EXPECT_NE(loadError("posture:\n  weight: 1.0e6\n").find("posture.weight"), std::string::npos);
  EXPECT_NE(loadError("observation:\n  weight: 10\n").find("observation.weight"), std::string::npos);
  EXPECT_NE(loadError("fallback:\n  damping: 1000\nperiod: 0.002\n").find("fallback.damping"), std::string::npos);
}

TEST(ControllerBounds, JointLimitsComeFromTheRobotDescriptionsModel) {
  const Model m = loadModel(defaultRobotDescription(), 0.08);
  const JointLimits& d = defaultJointLimits();
  for (int i = 0; i < kArmDofs; ++i) {
    EXPECT_EQ(d.q_min[i], m.q_min[i]) << i;
    EXPECT_EQ(d.q_max[i], m.q_max[i]) << i;
  }
  // a robot whose joint 1 turns less refuses the posture target the Panda accepts
  const YamlReader root = YamlReader::loadString("posture:\n  target: [2.5, -0.785, 0, -2.356, 0, 1.571, 0.785]\n", "narrow.yaml");
  EXPECT_NO_THROW(parseControllerConfig(root));
  JointLimits narrow = d;
  narrow.q_min[0] = -2.0;
  narrow.q_max[0] = 2.0;
  try {
    parseControllerConfig(root, narrow);
    ADD_FAILURE() << "a posture target beyond the narrower limit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("posture.target[0]"), std::string::npos) << e.what();
  }
}
