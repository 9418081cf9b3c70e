// Closed loop in MuJoCo: the paper experiment's reach (method: observation
// task coupled to the tracking task; baseline: set point) on
// scenes/scenarios/paper, against the TRUE pre-grasp frame (grasp backed off
// 8 cm along its z axis, as the handover's Approach state).
#include <gtest/gtest.h>

#include <cmath>

#include "app/experiment/paper_experiment.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {
namespace {

scenario::Scenario paperScenario() {
  return scenario::parseScenario(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/paper/paper_experiment.yaml");
}

ExperimentRun run(const scenario::Scenario& sc, ReachController c, GainSet gains, double duration) {
  ExperimentOptions opt;  // no files: out_dir empty
  opt.execution = Execution::kTorque;
  opt.gains = gains;
  opt.duration = duration;
  return runPaperExperiment(sc, c, opt);
}

void expectSafe(const ExperimentMetrics& m) {
  EXPECT_EQ(m.position_violations, 0);
  EXPECT_EQ(m.velocity_violations, 0);
  EXPECT_EQ(m.torque_violations, 0);
  EXPECT_EQ(m.qp_failures, 0);
}

TEST(PreGraspOffset, BacksTheGraspOffAlongItsOwnApproachAxis) {
  scenario::ObjectSpec object = paperScenario().object;
  const control::GraspOffset g = preGraspOffset(object, 0.08);
  // the grasp frame's z (approach axis) points from the pre-grasp to the grasp, 8 cm long
  const Eigen::Vector3d grasp_to_pre = g.placement.translation() - object.grasp.translation();
  EXPECT_NEAR(grasp_to_pre.norm(), 0.08, 1e-12);
  EXPECT_NEAR(grasp_to_pre.dot(object.grasp.linear().col(2)), -0.08, 1e-12);
  EXPECT_TRUE(g.placement.linear().isApprox(object.grasp.linear(), 1e-12));
  EXPECT_TRUE(g.approach_from_base && g.parallel_gripper);
  EXPECT_EQ(g.has_free_axis, object.free_axis >= 0);
  object.free_axis = 2;
  const control::GraspOffset sym = preGraspOffset(object, 0.0);
  EXPECT_TRUE(sym.has_free_axis);
  EXPECT_TRUE(sym.free_axis.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(sym.placement.isApprox(object.grasp, 1e-12));
  EXPECT_ANY_THROW(preGraspOffset(object, -0.01));
}

TEST(PaperExperiment, MethodNeverExceedsAJointLimitAndTheObserverFollowsTheObject) {
  const ExperimentRun r = run(paperScenario(), ReachController::kMethod, GainSet::kPaper, 8.0);
  const ExperimentMetrics& m = r.metrics;
  expectSafe(m);
  EXPECT_EQ(m.finger_object_contact_steps, 0) << "the fingers swept over the object on the way to the pre-grasp";
  ASSERT_TRUE(m.hand_rest_time.has_value());
  // once the hand rests, the observed object sits on the true one (noise only)
  for (const ExperimentSample& s : r.samples) {
    if (s.time < *m.hand_rest_time + 0.5) continue;
    ASSERT_LT((s.observed.translation() - s.object_true.translation()).norm(), 0.01) << "t = " << s.time;
    ASSERT_LT(rotationErrorDeg(s.observed, s.object_true), 5.0) << "t = " << s.time;
  }
}

// The reach requirement: after the hand stops, the TCP comes within 1 cm and
// 5 deg of the true pre-grasp frame and stays there, safely.
//
// Run with the handover's phase gains (config/fsm.yaml params.tracking,
// K = 6 / 12) and an exact ORIENTATION sensor (position noise 2 mm kept):
// - the paper's K = 1 / 2 needs ~12 s after the hand stops even without
//   orientation noise (docs/method.md), too long for this test;
// - with the scenario's 1 deg orientation noise the method does not converge
//   (final error 2.6 cm at K = 6, 12 cm at K = 1): the noisy observed angular
//   velocity is rectified by the centripetal feed-forward w x (w x r) over
//   the 14 cm lever to the pre-grasp frame (docs/method.md, open defect);
//   see the disabled test below.
TEST(PaperExperiment, MethodReachesTheTrueGraspFrameAfterTheHandStops) {
  scenario::Scenario sc = paperScenario();
  sc.sensor.noise_rot_deg = 0.0;
  const ExperimentMetrics m = run(sc, ReachController::kMethod, GainSet::kHandoverPhase, 10.0).metrics;
  expectSafe(m);
  EXPECT_EQ(m.finger_object_contact_steps, 0);
  ASSERT_TRUE(m.hand_rest_time.has_value());
  ASSERT_TRUE(m.reached_time.has_value()) << "final error " << m.final_pos_error << " m, " << m.final_rot_error_deg
                                          << " deg";
  EXPECT_GE(*m.reached_time, *m.hand_rest_time - 1.0);  // not a lucky pass while the object still moves
  EXPECT_LT(m.final_pos_error, 0.01);
  EXPECT_LT(m.final_rot_error_deg, 5.0);
}

// The baseline meets the same requirement on the unmodified scenario (noise
// included) with the same phase gains: the target and metrics are reachable.
// Its velocity-limit overshoot while the 60 Hz set point jumps (~57 steps at
// K = 6) is reported by paper_experiment, not asserted here.
TEST(PaperExperiment, BaselineReachesThePreGraspFrameWithTheScenariosNoise) {
  const ExperimentMetrics m = run(paperScenario(), ReachController::kBaseline, GainSet::kHandoverPhase, 10.0).metrics;
  EXPECT_EQ(m.position_violations + m.torque_violations + m.qp_failures, 0);
  ASSERT_TRUE(m.reached_time.has_value()) << "final error " << m.final_pos_error << " m, " << m.final_rot_error_deg
                                          << " deg";
}

// KNOWN DEFECT (docs/method.md): with the scenario's 1 deg orientation noise
// the method stops 2-12 cm short of the pre-grasp frame (see above). Enable
// when the feed-forward no longer rectifies the noise.
TEST(PaperExperiment, MethodReachesThePreGraspFrameWithTheScenariosNoise) {
  const ExperimentMetrics m = run(paperScenario(), ReachController::kMethod, GainSet::kHandoverPhase, 10.0).metrics;
  expectSafe(m);
  ASSERT_TRUE(m.reached_time.has_value()) << "final error " << m.final_pos_error << " m, " << m.final_rot_error_deg
                                          << " deg";
}

}  // namespace
}  // namespace handover::app
