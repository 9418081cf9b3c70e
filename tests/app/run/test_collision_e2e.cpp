// Collision avoidance with the person, end to end through app::runScenario:
// in h2r_forearm_in_way the person's forearm lies between the gripper and the
// object, so the arm has to go around it. The run must succeed without
// touching the person, and the run's own log.csv (d_human, ground-truth
// distance to the person's surfaces) must never go below sDist.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>

#include "app/run/run_scenario.hpp"
#include "control/collision/collision_config.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/run_files.hpp"
#include "tests/app/run/run_repo_file.hpp"

namespace handover {
namespace {

/// Runs the scenario file at `repo_file` (a path in the repository) into a scratch folder, no plots.
app::RunSummary runFile(const testing::ScratchDir& dir, const std::string& repo_file) {
  return testing::runRepoFile(dir, repo_file);
}

TEST(CollisionEndToEnd, ForearmInTheWayIsAvoided) {
  testing::ScratchDir dir("collision_e2e");
  const scenario::Scenario sc = scenario::parseScenario(testing::repoPath("scenes/scenarios/h2r_forearm_in_way.yaml"));
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  opt.log_every_ms = 5;
  const app::RunSummary s = app::runScenario(sc, opt);

  // sDist of the person pairs (the defaults of config/collision.yaml)
  const control::CollisionConfig ccfg = control::loadCollisionConfig(control::defaultCollisionConfigPath());
  const double s_dist = ccfg.defaults.s_dist;
  // d_human is measured without the margins: the dampers act below iDist + margin + sensing budget
  const double reach = ccfg.defaults.i_dist + ccfg.person.margin + ccfg.sensing_error.budget();

  const testing::CsvTable log = testing::readCsv(dir.file("out/log.csv"));
  ASSERT_GE(log.column("d_human"), 0);
  ASSERT_GT(log.rows.size(), 100u);
  double min_log = std::numeric_limits<double>::infinity();
  double min_log_time = 0.0;
  int below = 0;
  for (std::size_t r = 0; r < log.rows.size(); ++r) {
    const double d = log.number(r, "d_human");
    ASSERT_TRUE(std::isfinite(d)) << "row " << r;
    if (d < min_log) {
      min_log = d;
      min_log_time = log.number(r, "time");
    }
    if (d < s_dist) ++below;
  }
  std::printf("h2r_forearm_in_way: outcome %s, human contacts %d, min_human_distance %.4f m, "
              "log.csv min d_human %.4f m at t = %.3f s (sDist %.3f m), %zu rows\n",
              s.outcome.c_str(), s.human_contacts, s.min_human_distance, min_log, min_log_time, s_dist,
              log.rows.size());

  EXPECT_EQ(s.outcome, "success") << app::formatSummary(s);
  EXPECT_EQ(s.human_contacts, 0);
  EXPECT_GE(s.min_human_distance, s_dist);
  EXPECT_EQ(below, 0) << "log.csv rows with d_human < " << s_dist << "; min " << min_log << " at t = " << min_log_time;
  // the forearm really was in the way: the arm came within the person pairs' reach (iDist)
  EXPECT_LT(min_log, reach) << "the person never came near the arm: the scenario no longer tests avoidance";
}

// A person standing as close as the contract allows offers the object low
// and close (h2r_close_stand): the arm works next to the chest and head.
// With only hand and arm in the distance model the elbow touched the chest;
// the trunk is now a collision body, and the judge sees the true body.
TEST(CollisionEndToEnd, PersonStandingCloseIsNeverTouched) {
  testing::ScratchDir dir("collision_close_stand");
  const app::RunSummary s = runFile(dir, "scenes/scenarios/h2r_close_stand.yaml");
  std::printf("h2r_close_stand: outcome %s, human contacts %d, min_human_distance %.4f m, penetration %.3f s\n",
              s.outcome.c_str(), s.human_contacts, s.min_human_distance, s.penetration_time);
  EXPECT_EQ(s.human_contacts, 0) << app::formatSummary(s);
  EXPECT_EQ(s.penetration_time, 0.0);
  EXPECT_GT(s.min_human_distance, 0.0);
  EXPECT_EQ(s.limit_violations.position + s.limit_violations.velocity + s.limit_violations.torque, 0);
}

// A ball resting on a palm, taken from above (h2r_ball_on_palm, from the
// benchmark): the fingers close around it just above the person's fingers.
// While the gripper shares the object with the hand it still keeps off the
// hand itself (config/collision.yaml person_hand_gripper_taking); without
// that rule the fingertips pressed the fingers under the ball.
TEST(CollisionEndToEnd, FingersClosingOnABallOnAPalmDoNotPressThePalm) {
  testing::ScratchDir dir("collision_ball_on_palm");
  const app::RunSummary s = runFile(dir, "tests/app/run/data/h2r_ball_on_palm.yaml");
  EXPECT_EQ(s.human_contacts, 0) << app::formatSummary(s);
  EXPECT_EQ(s.penetration_time, 0.0);
  EXPECT_EQ(s.outcome, "success") << app::formatSummary(s);
}

// A ball put into a receiver's hand who pulls late (r2h_ball_late_pull, from the
// benchmark): after the release the object in the person's hand is a collision
// body for the gripper, and it sits where the fingers left it (HandoverCycle:
// the estimator's hand-to-object offset taken at the release); with the nominal
// grip it sat at the palm, 6 cm off, and the opened fingers backing out and
// swinging away struck the real ball (198 N, 2 velocity-limit steps).
TEST(CollisionEndToEnd, FingersLeavingABallInTheReceiversHandKeepOffIt) {
  testing::ScratchDir dir("collision_ball_late_pull");
  const app::RunSummary s = runFile(dir, "tests/app/run/data/r2h_ball_late_pull.yaml");
  EXPECT_EQ(s.limit_violations.position + s.limit_violations.velocity + s.limit_violations.torque, 0)
      << app::formatSummary(s);
  EXPECT_EQ(s.human_contacts, 0) << app::formatSummary(s);
  EXPECT_EQ(s.outcome, "success") << app::formatSummary(s);
}

// A ball put on a palm from the side with the closing axis upright
// (r2h_ball_on_palm_release, from the benchmark): one finger lies between the
// ball and the palm. A parallel gripper opens symmetrically; held where it
// was, with the pose task's soft retract gains, that finger met the palm as
// the fingers opened (3 contact steps). Release now holds the near finger
// where it was and stiffly (fsm/handover/release_ride.hpp).
TEST(CollisionEndToEnd, TheFingerBetweenABallAndThePalmOpensAwayFromThePalm) {
  testing::ScratchDir dir("collision_ball_on_palm_release");
  const app::RunSummary s = runFile(dir, "tests/app/run/data/r2h_ball_on_palm_release.yaml");
  EXPECT_EQ(s.human_contacts, 0) << app::formatSummary(s);
  EXPECT_EQ(s.penetration_time, 0.0);
  EXPECT_EQ(s.limit_violations.position + s.limit_violations.velocity + s.limit_violations.torque, 0)
      << app::formatSummary(s);
  EXPECT_EQ(s.outcome, "success") << app::formatSummary(s);
}

// Each of `files` succeeds without touching the person or violating a limit.
void expectNoRunInto(std::initializer_list<const char*> files) {
  for (const char* file : files) {
    testing::ScratchDir dir("collision_reach_ready");
    const app::RunSummary s = runFile(dir, file);
    EXPECT_EQ(s.human_contacts, 0) << file << "\n" << app::formatSummary(s);
    EXPECT_EQ(s.penetration_time, 0.0) << file;
    EXPECT_EQ(s.limit_violations.position + s.limit_violations.velocity + s.limit_violations.torque, 0) << file;
    EXPECT_EQ(s.outcome, "success") << file << "\n" << app::formatSummary(s);
  }
}

// Receivers who reach out while the arm still carries the object to the
// ready pose (from the benchmark): one past it to a point nearer the base
// (r2h_reach_past_ready, at 1 m/s), one beside it with a feint first
// (r2h_reach_beside_ready). The ball held from the side waited with the
// wrist on their side of it, across their way, and their hand ran into it;
// now the waiting place keeps the palm and the arm out of the way from their
// shoulder to the object (GraspPlanning::uprightPlacement, receiver_stop).
TEST(CollisionEndToEnd, AReceiverReachingForTheObjectDoesNotRunIntoTheWaitingArm) {
  expectNoRunInto({"tests/app/run/data/r2h_reach_past_ready.yaml", "tests/app/run/data/r2h_reach_beside_ready.yaml"});
}

// Receivers who reach fast (1.2 and 1.7 m/s) for a place the waiting wrist or
// gripper holds (from the benchmark): once the reach's end can be predicted
// (its speed has peaked) the arm keeps out of the hand's way to it as it keeps
// from the hand (human_hand_forecast); the hand used to strike link 7 or the
// palm at 1.1-1.7 m/s, too fast for any damper on the hand itself.
TEST(CollisionEndToEnd, AFastReachForWhereTheArmWaitsFindsItGone) {
  expectNoRunInto({"tests/app/run/data/r2h_reach_through_wrist.yaml", "tests/app/run/data/r2h_fast_reach_to_gripper.yaml"});
}

}  // namespace
}  // namespace handover
