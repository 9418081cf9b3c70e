// The result of one run: every key of design-notes section 4 (summary.json).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace handover::app {

struct LimitViolations {
  int position = 0;  ///< control steps with a joint beyond its position limit
  int velocity = 0;  ///< ... beyond its velocity limit
  int torque = 0;    ///< ... with a commanded torque beyond its limit
};

struct TimingStats {
  double median = 0.0, p99 = 0.0, max = 0.0;  ///< microseconds
};

struct RunSummary {
  std::string scenario;
  std::string mode;             ///< human_to_robot | robot_to_human
  /// success | aborted | hand_contact | object_drop | timeout | no_perception | unsafe | error
  std::string outcome = "error";
  std::string error_message;    ///< set when outcome == error, or why an unsafe run was stopped early
  int handovers = 0, aborts = 0, retries = 0;
  std::optional<double> time_to_grasp;        ///< s
  std::optional<double> hand_still_to_grasp;  ///< s, negative: grasped while the hand moved
  std::optional<double> total_time;           ///< s, start to handover complete and retracted
  double min_human_distance = 0.0;            ///< m, true clearance (MuJoCo geometry; shared-object fingers excluded)
  int human_contacts = 0;                     ///< touches: simulator contacts or true-geometry penetrations (onsets)
  double penetration_time = 0.0;              ///< s, time a robot geom was inside the person's true body
  bool object_dropped = false;
  std::optional<double> drop_time;            ///< s, when the drop was first seen (null if none)
  std::string drop_reason;                    ///< table | floor | fell (nobody held it and it fell), "" if none
  LimitViolations limit_violations;
  int qp_failures = 0;
  int qp_relaxed = 0;                         ///< steps solved only with the collision rows relaxed (not failures)
  int limit_guard_steps = 0;                  ///< steps whose command the limit guard changed (not violations: it kept the limits)
  std::string tracker = "simulated";          ///< simulated | csv | udp: where the person's poses came from
  long rejected_samples = 0;                  ///< tracker samples refused (malformed datagrams, the estimator's gates)
  /// the same per reason (perception/reject_counts.hpp names), in that order
  std::vector<std::pair<std::string, long>> rejected_by_reason;
  double person_unseen_time = 0.0;            ///< s without a usable (valid, fresh) estimate of the person
  /// script steps the simulated person took longer than written, because a
  /// hand cannot move that fast (human::ScriptedHuman::stretchedSteps), one
  /// sentence each; empty for an ordinary script
  std::vector<std::string> person_slowed;
  std::optional<double> grasp_error_pos;      ///< m
  std::optional<double> grasp_error_rot_deg;  ///< deg
  std::vector<std::string> states;            ///< visited, in order
  TimingStats control_step_us;
  double realtime_factor = 0.0;
  double simulated_time = 0.0;                ///< s actually simulated
  std::vector<std::string> expectation_failures;  ///< unmet `expect:` lines (exit 1)

  bool success() const { return outcome == "success"; }
  /// The run ended as its scenario expects: no `expect:` line failed, and it
  /// did not end in an error (a run that never ran meets nothing).
  bool metExpectations() const { return outcome != "error" && expectation_failures.empty(); }
  std::string toJson() const;
};

/// The `handover run` exit code (README, docs/outputs.md): 2 for outcome
/// "error", 1 for unmet expectations, and 1 for an "unsafe" or
/// "no_perception" run whose scenario does not expect an outcome
/// (`outcome_expected` false): scripts must see an unsafe run, or one that
/// could not see the person, fail even without `expect:`. Else 0.
int runExitCode(const RunSummary& r, bool outcome_expected);

}  // namespace handover::app
