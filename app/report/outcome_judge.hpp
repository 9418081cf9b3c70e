// Judges a run from physical facts, as design-notes section 4 and the
// "outcome judgement" of the command-line issue say. It sees the simulator's
// ground truth, never the controller's beliefs (except the state machine's
// "done" and counters, which say when the robot considers itself finished).
// observe() is allocation-free except when a new state name is first seen.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "app/report/run_summary.hpp"

namespace handover::app {

/// Ground truth and controller facts of one 1 ms step.
struct StepFacts {
  double time = 0.0;                        ///< s
  // simulator ground truth
  int robot_human_contacts = 0;             ///< contact pairs robot-person this step (simulator's list)
  /// a robot geom penetrates the person's true body (hand, arms, torso, legs,
  /// head) by MuJoCo's geometry this step, whether or not the contact list has it
  bool human_penetration = false;
  bool left_finger_on_object = false;
  bool right_finger_on_object = false;
  bool object_on_table = false;
  bool object_on_floor = false;
  bool hand_holds_object = false;           ///< the person's weld is on
  Eigen::Vector3d object_pos = Eigen::Vector3d::Zero();   ///< world, m
  Eigen::Vector3d object_vel = Eigen::Vector3d::Zero();   ///< world, m/s
  Eigen::Vector3d hand_pos = Eigen::Vector3d::Zero();     ///< person's grip point, world, m
  double hand_speed = 0.0;                  ///< m/s
  double finger_width = 0.0;                ///< m, total opening
  double min_human_distance = 1e9;          ///< m, true clearance robot geoms to person (shared-object fingers excluded)
  double grasp_pos_error = 0.0;             ///< m, TCP to the true grasp frame
  double grasp_rot_error_deg = 0.0;         ///< deg, TCP to the true grasp frame
  // controller side
  bool gripper_closing = false;             ///< the controller commands the fingers closed
  bool position_violation = false;
  bool velocity_violation = false;
  bool torque_violation = false;
  bool qp_failed = false;
  bool qp_relaxed = false;  ///< solved only with the soft (collision) rows relaxed
  bool person_seen = true;  ///< perception had a usable (valid, not stale) estimate of the person
  bool limit_guarded = false;  ///< the limit guard changed the command (control/safety/limit_guard.hpp)
  const std::string* state = nullptr;       ///< full state path; pointer must stay valid for the call
  double step_us = 0.0;                     ///< wall time of the controller step
};

struct JudgeSettings {
  std::string mode = "human_to_robot";
  double hold_time = 0.1;            ///< s both fingers on the object, away from the hand
  double away_from_hand = 0.05;      ///< m between object and grip point to count as "away"
  double fall_speed = 0.5;           ///< m/s downward with nobody holding it = falling
  /// s the fall must last: an object slipping a few millimetres in the
  /// fingers, its contacts flickering as it slides, is no drop (a dropped one
  /// falls on for a few tenths of a second until it lands)
  double fall_time = 0.02;
  double hand_rest_speed = 0.05;     ///< m/s (design notes: hand at rest)
  /// A run that did not succeed, touched nobody and broke no limit, during
  /// which the person was unseen (no usable estimate) for at least this share
  /// of the time before it failed (the drop, else the end), is `no_perception`:
  /// the robot could not see the person, whatever the person then did.
  double unseen_share = 0.5;
};

class OutcomeJudge {
 public:
  explicit OutcomeJudge(JudgeSettings settings, std::size_t expected_steps = 0);

  void observe(const StepFacts& f);

  /// Ends the run. `fsm_done` = the state machine reached its final state;
  /// `fsm_outcome` its verdict ("success", "aborted", ...; "" if not done).
  RunSummary finish(bool fsm_done, const std::string& fsm_outcome, int handovers, int aborts,
                    int retries, double wall_seconds);

  /// True once the exchange physically happened (for the mode).
  bool exchanged() const { return exchanged_; }

 private:
  bool heldByRobot(const StepFacts& f) const;
  JudgeSettings s_;
  double last_time_ = 0.0;
  bool exchanged_ = false;          // physical transfer condition met for hold_time
  double transfer_since_ = -1.0;    // start of the current transfer-condition window
  bool transfer_now_ = false;
  bool dropped_ = false;
  double drop_time_ = 0.0;       // s, when the drop was first seen
  std::string drop_reason_;      // table | floor | fell
  double falling_since_ = -1.0;  // s, when the current fall began (-1: not falling)
  double unseen_at_fall_ = 0.0;  // unseen_time_ then
  int contacts_ = 0;
  int penetration_steps_ = 0;
  double step_time_ = 0.0;          // s, last step's length (for penetration_time)
  bool in_contact_ = false;
  double min_dist_ = 1e9;
  LimitViolations lim_;
  int qp_failures_ = 0;
  int qp_relaxed_ = 0;
  double unseen_time_ = 0.0;          // s without a usable estimate of the person
  double unseen_at_drop_ = 0.0;       // the same, until the drop
  int guarded_ = 0;
  // grasp timing
  std::optional<double> grasp_time_;
  std::optional<double> grasp_pos_err_, grasp_rot_err_;
  double rest_since_ = -1.0;        // when the hand last came to rest (-1: moving)
  std::optional<double> still_to_grasp_;
  bool awaiting_rest_after_grasp_ = false;
  std::optional<double> complete_time_;
  std::vector<std::string> states_;
  std::vector<double> step_us_;
};

}  // namespace handover::app
