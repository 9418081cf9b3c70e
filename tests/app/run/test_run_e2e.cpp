// End to end in the simulator through app::runScenario: the state machine
// takes an object from the scripted person, gives one, gives up, and
// retries. Each test copies a shipped scenario into a scratch folder (so it
// follows the shipped person and object as they are tuned), runs it, and
// checks the verdict, the states visited, the physical end state read back
// from the run's own log.csv, and the result-file contracts (every
// summary.json key of design-notes section 4; the log.csv column list).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "app/run/run_scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"
#include "tests/app/run/mini_json.hpp"
#include "tests/app/run/run_files.hpp"

namespace handover {
namespace {

using testing::CsvTable;
using testing::Json;
using testing::ScratchDir;

struct RunResult {
  scenario::Scenario scenario;
  app::RunSummary summary;
  std::string out_dir;
};

/// Copies scenes/scenarios/<name>.yaml into `dir`, parses the copy and runs it
/// with log.csv and summary.json written to dir/out (no plots: those are the
/// command line's, tested in tests/app/cli).
RunResult runShipped(const ScratchDir& dir, const std::string& name) {
  const std::string copy = dir.file(name + ".yaml");
  testing::writeText(copy, testing::readText(testing::repoPath("scenes/scenarios/" + name + ".yaml")));
  RunResult r;
  r.scenario = scenario::parseScenario(copy);
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  r.summary = app::runScenario(r.scenario, opt);
  r.out_dir = opt.out_dir;
  return r;
}

/// The last path element of a state ("Handover/HumanToRobot/Grasp" -> "Grasp").
std::string leaf(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<std::string> leaves(const std::vector<std::string>& states) {
  std::vector<std::string> out;
  for (const auto& s : states) out.push_back(leaf(s));
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : " > ") + e;
  return s;
}

/// True when `wanted` appears in `seq` in this order (other states may come between).
bool inOrder(const std::vector<std::string>& seq, const std::vector<std::string>& wanted) {
  auto it = seq.begin();
  for (const auto& w : wanted) {
    it = std::find(it, seq.end(), w);
    if (it == seq.end()) return false;
    ++it;
  }
  return true;
}

/// True when `seq` ends with `tail` exactly.
bool endsWith(const std::vector<std::string>& seq, const std::vector<std::string>& tail) {
  return seq.size() >= tail.size() && std::equal(tail.rbegin(), tail.rend(), seq.rbegin());
}

Eigen::Vector3d point(const CsvTable& t, std::size_t row, const std::string& prefix) {
  return {t.number(row, prefix + "x"), t.number(row, prefix + "y"), t.number(row, prefix + "z")};
}

// ---- result-file contracts, checked on every run ---------------------------

/// The log.csv columns (docs/outputs.md, app/run/run_log.hpp; scripts/plot_run.py reads them by name).
std::vector<std::string> documentedLogColumns() {
  std::vector<std::string> c = {"time", "state", "sensed_valid"};
  for (const char* p : {"sensed", "obs", "grasp", "tcp"})
    for (const char* a : {"x", "y", "z", "roll", "pitch", "yaw"}) c.push_back(std::string(p) + "_" + a);
  for (const char* n : {"hand_x", "hand_y", "hand_z", "hand_speed", "object_x", "object_y", "object_z"}) c.push_back(n);
  for (const char* p : {"q", "qd", "tau", "qmargin"})
    for (int i = 1; i <= 7; ++i) c.push_back(p + std::to_string(i));
  for (const char* n : {"d_human", "d_table", "d_self", "ft_fx", "ft_fy", "ft_fz", "ft_tx", "ft_ty", "ft_tz",
                        "finger_width", "gripper_cmd", "speed_scale", "qp_status", "qp_iterations"})
    c.push_back(n);
  for (const char* n : {"load_share", "load_fx", "load_fy", "load_fz", "ff_fx", "ff_fy", "ff_fz", "grip_force",
                        "qp_slack", "person_seen"})
    c.push_back(n);
  for (const char* why : {"malformed", "invalid", "time", "workspace", "jump", "speed", "acceleration"})
    c.push_back(std::string("rejected_") + why);
  c.push_back("guard_steps");
  c.push_back("person_contact");
  c.push_back("nearest_gap");
  c.push_back("nearest_pair");
  return c;
}

/// summary.json holds every key of design-notes section 4, with the right
/// types, and agrees with the summary runScenario returned.
void checkSummaryJson(const RunResult& run) {
  SCOPED_TRACE("summary.json of " + run.scenario.name);
  Json j;
  ASSERT_NO_THROW(j = testing::parseJson(testing::readText(run.out_dir + "/summary.json")));
  ASSERT_EQ(j.kind, Json::Kind::Object);
  const app::RunSummary& s = run.summary;

  for (const char* k : {"scenario", "mode", "outcome"}) {
    ASSERT_TRUE(j.has(k)) << k;
    EXPECT_EQ(j.at(k).kind, Json::Kind::String) << k;
  }
  EXPECT_EQ(j.at("scenario").text, run.scenario.name);
  EXPECT_EQ(j.at("mode").text, scenario::toString(run.scenario.mode));
  EXPECT_EQ(j.at("outcome").text, s.outcome);
  ASSERT_TRUE(j.has("success"));
  EXPECT_EQ(j.at("success").kind, Json::Kind::Bool);
  EXPECT_EQ(j.at("success").boolean, s.outcome == "success");

  const std::pair<const char*, int> counts[] = {{"handovers", s.handovers},
                                                {"aborts", s.aborts},
                                                {"retries", s.retries},
                                                {"human_contacts", s.human_contacts},
                                                {"qp_failures", s.qp_failures}};
  for (const auto& [k, v] : counts) {
    ASSERT_TRUE(j.has(k)) << k;
    ASSERT_TRUE(j.at(k).isNumber()) << k;
    EXPECT_EQ(j.at(k).number, v) << k;
  }
  // numbers, or null when the run never got there
  for (const char* k : {"time_to_grasp", "hand_still_to_grasp", "total_time"}) {
    ASSERT_TRUE(j.has(k)) << k;
    EXPECT_TRUE(j.at(k).isNumber() || j.at(k).isNull()) << k;
  }
  EXPECT_EQ(j.at("time_to_grasp").isNumber(), s.time_to_grasp.has_value());
  EXPECT_EQ(j.at("total_time").isNumber(), s.total_time.has_value());
  ASSERT_TRUE(j.has("min_human_distance"));
  if (std::isnan(s.min_human_distance)) {
    EXPECT_TRUE(j.at("min_human_distance").isNull());  // never within reach (docs/outputs.md)
  } else {
    ASSERT_TRUE(j.at("min_human_distance").isNumber());
    EXPECT_NEAR(j.at("min_human_distance").number, s.min_human_distance, 1e-6);
  }
  ASSERT_TRUE(j.has("object_dropped"));
  EXPECT_EQ(j.at("object_dropped").kind, Json::Kind::Bool);
  EXPECT_EQ(j.at("object_dropped").boolean, s.object_dropped);

  ASSERT_TRUE(j.has("limit_violations"));
  for (const char* k : {"position", "velocity", "torque"}) {
    ASSERT_TRUE(j.at("limit_violations").has(k)) << k;
    EXPECT_TRUE(j.at("limit_violations").at(k).isNumber()) << k;
  }
  ASSERT_TRUE(j.has("grasp_error"));
  if (!j.at("grasp_error").isNull()) {
    for (const char* k : {"pos", "rot_deg"}) {
      ASSERT_TRUE(j.at("grasp_error").has(k)) << k;
      EXPECT_TRUE(j.at("grasp_error").at(k).isNumber()) << k;
    }
  }
  ASSERT_TRUE(j.has("states"));
  ASSERT_EQ(j.at("states").kind, Json::Kind::Array);
  ASSERT_EQ(j.at("states").items.size(), s.states.size());
  for (std::size_t i = 0; i < s.states.size(); ++i) EXPECT_EQ(j.at("states").items[i].text, s.states[i]);
  ASSERT_TRUE(j.has("control_step_us"));
  for (const char* k : {"median", "p99", "max"}) {
    ASSERT_TRUE(j.at("control_step_us").has(k)) << k;
    ASSERT_TRUE(j.at("control_step_us").at(k).isNumber()) << k;
    EXPECT_GT(j.at("control_step_us").at(k).number, 0.0) << k;
  }
  EXPECT_LE(j.at("control_step_us").at("median").number, j.at("control_step_us").at("p99").number);
  EXPECT_LE(j.at("control_step_us").at("p99").number, j.at("control_step_us").at("max").number);
  ASSERT_TRUE(j.has("realtime_factor"));
  ASSERT_TRUE(j.at("realtime_factor").isNumber());
  EXPECT_GT(j.at("realtime_factor").number, 0.0);
}

/// log.csv: the documented header, rows as wide as it, time rising in
/// --log-every steps up to the simulated time. Returns the table.
CsvTable checkLogCsv(const RunResult& run) {
  SCOPED_TRACE("log.csv of " + run.scenario.name);
  const CsvTable t = testing::readCsv(run.out_dir + "/log.csv");
  EXPECT_EQ(t.header, documentedLogColumns());
  EXPECT_GT(t.rows.size(), 10u);
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r].size() != t.header.size()) {
      ADD_FAILURE() << "row " << r + 1 << " has " << t.rows[r].size() << " fields, header " << t.header.size();
      break;
    }
  }
  for (std::size_t r = 1; r < t.rows.size(); ++r) {
    const double dt = t.number(r, "time") - t.number(r - 1, "time");
    if (std::abs(dt - 0.005) > 1e-6) {
      ADD_FAILURE() << "time step " << dt << " s at row " << r + 1 << " (expected the default 5 ms)";
      break;
    }
  }
  // the pair nearest its safety distance: a labelled pair with a finite gap, or neither
  const int gap_col = t.column("nearest_gap"), pair_col = t.column("nearest_pair");
  int labelled = 0;
  for (std::size_t r = 0; gap_col >= 0 && pair_col >= 0 && r < t.rows.size(); ++r) {
    const std::string& pair = t.rows[r][pair_col];
    if (pair.empty()) {
      EXPECT_EQ(t.rows[r][gap_col], "nan") << "row " << r + 1;
      continue;
    }
    ++labelled;
    EXPECT_NE(pair.find(": "), std::string::npos) << "row " << r + 1 << ": " << pair;  // "rule: robot - other"
    EXPECT_NE(pair.find(" - "), std::string::npos) << "row " << r + 1 << ": " << pair;
    EXPECT_TRUE(std::isfinite(t.number(r, "nearest_gap"))) << "row " << r + 1;
  }
  EXPECT_GT(labelled, 0) << "no collision pair was ever active (the table is always near the arm)";
  // a touch of the person shows in the rows; a run without contacts shows none
  int touching_rows = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const double c = t.number(r, "person_contact");
    EXPECT_TRUE(c == 0.0 || c == 1.0) << "row " << r + 1;
    touching_rows += c > 0.5 ? 1 : 0;
  }
  if (run.summary.human_contacts == 0) EXPECT_EQ(touching_rows, 0);
  if (!t.rows.empty()) {
    EXPECT_NEAR(t.number(t.rows.size() - 1, "time"), run.summary.simulated_time, 0.01);
    EXPECT_EQ(leaf(t.rows.back()[1]), run.summary.states.empty() ? "" : leaf(run.summary.states.back()));
  }
  return t;
}

/// What every run should have: sane safety numbers and valid result files.
void checkCommon(const RunResult& run) {
  const app::RunSummary& s = run.summary;
  EXPECT_EQ(s.human_contacts, 0);
  EXPECT_FALSE(s.object_dropped);
  // null (NaN) when the robot never came within the collision pairs' reach of the person
  EXPECT_TRUE(std::isnan(s.min_human_distance) || s.min_human_distance > 0.0) << s.min_human_distance;
  EXPECT_EQ(s.qp_failures, 0);
  EXPECT_EQ(s.limit_violations.position + s.limit_violations.velocity + s.limit_violations.torque, 0);
  EXPECT_TRUE(s.error_message.empty()) << s.error_message;
  checkSummaryJson(run);
}

double graspOffset(const scenario::Scenario& sc) { return sc.object.grasp.translation().norm(); }

/// How far from the object's centre the grasp the robot closed on sits, m:
/// the tracked grasp frame (`grasp_`) against the observed object (`obs_`) in
/// the log's last WaitForRelease row (no standoff there). The planner may
/// choose any grasp the object admits, not only the declared one.
double chosenGraspOffset(const CsvTable& log) {
  double offset = -1.0;
  for (std::size_t i = 0; i < log.rows.size(); ++i)
    if (log.rows[i][log.column("state")].find("/WaitForRelease") != std::string::npos)
      offset = (point(log, i, "grasp_") - point(log, i, "obs_")).norm();
  if (offset < 0.0) throw std::runtime_error("chosenGraspOffset: no WaitForRelease row in the log");
  return offset;
}

/// The object's width between the fingers; the scenarios used here are round
/// (cylinder grasped across its axis, or a sphere): the diameter.
double objectWidth(const scenario::Scenario& sc) {
  if (sc.object.shape == scenario::Shape::Box) throw std::runtime_error("objectWidth: box not supported here");
  return 2.0 * sc.object.size.at(0);
}

// ---- the four behaviours ----------------------------------------------------

// At the end of the run the object is at the person's grip point and the
// robot's TCP is well away from it (it holds nothing).
void expectObjectWithThePerson(const RunResult& run, const CsvTable& log) {
  const std::size_t last = log.rows.size() - 1;
  const Eigen::Vector3d object = point(log, last, "object_"), tcp = point(log, last, "tcp_"),
                        hand = point(log, last, "hand_");
  EXPECT_LT((object - hand).norm(), 0.10) << "object at the person's grip point";
  EXPECT_GT((object - tcp).norm(), graspOffset(run.scenario) + 0.10) << "the robot holds nothing and is away";
}

TEST(RunEndToEnd, HumanToRobotTakesTheObject) {
  ScratchDir dir("run_h2r");
  const RunResult run = runShipped(dir, "default");
  const app::RunSummary& s = run.summary;
  ASSERT_EQ(s.mode, "human_to_robot");
  EXPECT_EQ(s.outcome, "success") << joined(s.states);
  EXPECT_EQ(s.handovers, 1);
  EXPECT_EQ(s.aborts, 0);
  EXPECT_EQ(s.retries, 0);
  EXPECT_EQ(leaves(s.states),
            (std::vector<std::string>{"WaitForOffer", "Approach", "Grasp", "WaitForRelease", "Retract", "Done"}))
      << joined(s.states);
  for (const auto& st : s.states)
    if (st != "Done") {
      EXPECT_NE(st.find("HumanToRobot/"), std::string::npos) << st;
    }
  ASSERT_TRUE(s.time_to_grasp.has_value());
  EXPECT_GT(*s.time_to_grasp, 0.0);
  ASSERT_TRUE(s.total_time.has_value());
  EXPECT_GT(*s.total_time, *s.time_to_grasp);
  EXPECT_LE(*s.total_time, run.scenario.duration);
  checkCommon(run);

  // physically: at the end the object sits in the closed gripper, away from the person
  const CsvTable log = checkLogCsv(run);
  ASSERT_FALSE(log.rows.empty());
  const std::size_t last = log.rows.size() - 1;
  const Eigen::Vector3d object = point(log, last, "object_"), tcp = point(log, last, "tcp_"),
                        hand = point(log, last, "hand_");
  EXPECT_NEAR((object - tcp).norm(), graspOffset(run.scenario), 0.03)
      << "object centre vs TCP at the end; the grasp frame sits " << graspOffset(run.scenario) << " m from the centre";
  EXPECT_GT((object - hand).norm(), 0.2) << "the object left with the robot, not with the person";
  EXPECT_NEAR(log.number(last, "finger_width"), objectWidth(run.scenario), 0.01) << "fingers closed on the object";
  EXPECT_GT(object.z(), 0.05) << "object above the table";
}

TEST(RunEndToEnd, RobotToHumanGivesTheObject) {
  ScratchDir dir("run_r2h");
  const RunResult run = runShipped(dir, "r2h_basic");
  const app::RunSummary& s = run.summary;
  ASSERT_EQ(s.mode, "robot_to_human");
  EXPECT_EQ(s.outcome, "success") << joined(s.states);
  EXPECT_EQ(s.handovers, 1);
  EXPECT_EQ(s.aborts, 0);
  const std::vector<std::string> seq = leaves(s.states);
  EXPECT_TRUE(inOrder(seq, {"HoldReady", "Present", "Release", "ConfirmGone", "BackOut", "Retract", "Done"}))
      << joined(s.states);
  EXPECT_TRUE(endsWith(seq, {"Release", "ConfirmGone", "BackOut", "Retract", "Done"})) << joined(s.states);
  for (const auto& st : s.states)
    if (st != "Done") {
      EXPECT_NE(st.find("RobotToHuman/"), std::string::npos) << st;
    }
  ASSERT_TRUE(s.total_time.has_value());
  EXPECT_LE(*s.total_time, run.scenario.duration);
  checkCommon(run);

  // physically: the object ends in the person's hand, the gripper open and away from it
  const CsvTable log = checkLogCsv(run);
  ASSERT_FALSE(log.rows.empty());
  expectObjectWithThePerson(run, log);
  EXPECT_GT(log.number(log.rows.size() - 1, "finger_width"), objectWidth(run.scenario)) << "fingers open";
}

// RetreatOpen as Retreat: whether the fingers had begun to close on the
// object before the person withdrew depends on how soon the arm got there
std::vector<std::string> retreatsAlike(std::vector<std::string> seq) {
  for (auto& st : seq)
    if (st == "RetreatOpen") st = "Retreat";
  return seq;
}

TEST(RunEndToEnd, PersonLeavesForGoodAborts) {
  ScratchDir dir("run_abort");
  const RunResult run = runShipped(dir, "h2r_abort");
  const app::RunSummary& s = run.summary;
  EXPECT_EQ(s.outcome, "aborted") << joined(s.states);
  EXPECT_EQ(s.aborts, 1);
  EXPECT_EQ(s.retries, 0);  // they never came back
  EXPECT_EQ(s.handovers, 0);
  // the run ends a few seconds after the person has gone (the end of their
  // withdraw step, the script's steps being timed), and says when
  double gone = 0.0;
  for (const scenario::ScriptStep& step : run.scenario.human.script) {
    gone += step.duration;
    if (step.kind == scenario::StepKind::Withdraw) break;
  }
  ASSERT_TRUE(s.total_time.has_value());
  EXPECT_GT(*s.total_time, gone);
  EXPECT_LT(*s.total_time, gone + 5.0);
  const std::vector<std::string> seq = retreatsAlike(leaves(s.states));
  EXPECT_TRUE(endsWith(seq, {"Retreat", "WaitAgain", "Aborted"})) << joined(s.states);
  EXPECT_TRUE(inOrder(seq, {"WaitForOffer", "Approach", "Retreat"})) << joined(s.states);
  EXPECT_EQ(std::count(seq.begin(), seq.end(), "Done"), 0) << joined(s.states);
  checkCommon(run);

  // physically: the person kept the object; the robot holds nothing
  const CsvTable log = checkLogCsv(run);
  ASSERT_FALSE(log.rows.empty());
  expectObjectWithThePerson(run, log);
}

TEST(RunEndToEnd, PersonComesBackRetryThenSuccess) {
  ScratchDir dir("run_retry");
  const RunResult run = runShipped(dir, "h2r_retry");
  const app::RunSummary& s = run.summary;
  EXPECT_EQ(s.outcome, "success") << joined(s.states);
  EXPECT_EQ(s.retries, 1);
  // the first attempt was abandoned (fsm HandoverStats: aborts = attempts abandoned)
  EXPECT_EQ(s.aborts, 1);
  EXPECT_EQ(s.handovers, 1);
  const std::vector<std::string> seq = retreatsAlike(leaves(s.states));
  EXPECT_TRUE(inOrder(seq, {"WaitForOffer", "Approach", "Retreat", "WaitAgain", "Approach", "Grasp"}))
      << joined(s.states);
  EXPECT_TRUE(endsWith(seq, {"Grasp", "WaitForRelease", "Retract", "Done"})) << joined(s.states);
  ASSERT_TRUE(s.time_to_grasp.has_value());
  checkCommon(run);

  const CsvTable log = checkLogCsv(run);
  ASSERT_FALSE(log.rows.empty());
  const std::size_t last = log.rows.size() - 1;
  const Eigen::Vector3d object = point(log, last, "object_"), tcp = point(log, last, "tcp_"),
                        hand = point(log, last, "hand_");
  // whichever grasp was chosen (the declared one from above or a family the cylinder
  // implies), the object is held where the fingers closed on it
  EXPECT_NEAR((object - tcp).norm(), chosenGraspOffset(log), 0.03);
  ASSERT_TRUE(s.grasp_error_pos.has_value());
  EXPECT_LT(*s.grasp_error_pos, 0.03) << "closed away from the chosen grasp";
  EXPECT_GT((object - hand).norm(), 0.2);
  EXPECT_NEAR(log.number(last, "finger_width"), objectWidth(run.scenario), 0.01);
}

// The grasp error is judged against the grasp the robot chose: a thin tube declared
// grasped from above, taken with the 45-degree family the cylinder implies, was
// reported 77 mm and 45 degrees off a grasp it never aimed at (g1093_00980)
TEST(RunEndToEnd, TheGraspErrorIsJudgedAgainstTheGraspTheRobotChose) {
  ScratchDir dir("grasp_error_chosen");
  app::RunOptions opt;
  opt.out_dir = dir.file("out");
  opt.plots = false;
  const scenario::Scenario sc = scenario::parseScenario(testing::repoPath("tests/app/run/data/h2r_tube_taken_at_45.yaml"));
  const app::RunSummary s = app::runScenario(sc, opt);
  ASSERT_EQ(s.outcome, "success") << joined(s.states);
  // the robot chose another family: the tracked grasp's approach axis (grasp z) at the
  // close stands well off the declared one
  const CsvTable log = testing::readCsv(dir.file("out") + "/log.csv");
  std::size_t closing = log.rows.size();
  for (std::size_t i = 0; i < log.rows.size() && closing == log.rows.size(); ++i)
    if (log.rows[i][log.column("state")].find("/WaitForRelease") != std::string::npos) closing = i;
  ASSERT_LT(closing, log.rows.size()) << "never held the tube";
  const auto rotation = [&](const std::string& prefix) {
    return (Eigen::AngleAxisd(log.number(closing, prefix + "yaw"), Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(log.number(closing, prefix + "pitch"), Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(log.number(closing, prefix + "roll"), Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  };
  const Eigen::Vector3d declared = (rotation("obs_") * sc.object.grasp.linear()).col(2);
  const double off_declared = std::acos(std::clamp(declared.dot(rotation("grasp_").col(2)), -1.0, 1.0));
  EXPECT_GT(off_declared, 0.5) << "the declared grasp was chosen: this run tests nothing";
  ASSERT_TRUE(s.grasp_error_pos.has_value());
  ASSERT_TRUE(s.grasp_error_rot_deg.has_value());
  EXPECT_LT(*s.grasp_error_pos, 0.02);
  EXPECT_LT(*s.grasp_error_rot_deg, 5.0);
}

}  // namespace
}  // namespace handover
