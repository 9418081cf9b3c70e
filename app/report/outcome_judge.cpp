#include "app/report/outcome_judge.hpp"

#include <algorithm>
#include <cmath>

namespace handover::app {

OutcomeJudge::OutcomeJudge(JudgeSettings settings, std::size_t expected_steps) : s_(std::move(settings)) {
  step_us_.reserve(expected_steps);
  states_.reserve(64);
}

bool OutcomeJudge::heldByRobot(const StepFacts& f) const {
  return f.left_finger_on_object && f.right_finger_on_object;
}

void OutcomeJudge::observe(const StepFacts& f) {
  if (f.time > last_time_) step_time_ = f.time - last_time_;
  // time without a usable estimate of the person (the step's duration: since the last one)
  if (!f.person_seen) unseen_time_ += std::max(0.0, f.time - last_time_);
  last_time_ = f.time;
  const bool robot_holds = heldByRobot(f);

  // contacts: count onsets, so one long touch is one contact; a penetration
  // of the person's true body counts even when the simulator lists no contact
  const bool touching = f.robot_human_contacts > 0 || f.human_penetration;
  penetration_steps_ += f.human_penetration ? 1 : 0;
  if (touching && !in_contact_) ++contacts_;
  in_contact_ = touching;
  min_dist_ = std::min(min_dist_, f.min_human_distance);

  // drops: touching table/floor, or falling with nobody holding it. An object
  // the person holds may touch the table: where a person sets it down is
  // theirs to choose (a held object the robot strikes on the table counts)
  const bool nobody_holds = !f.hand_holds_object && !robot_holds;
  const bool falling = nobody_holds && f.object_vel.z() < -s_.fall_speed;
  if (!falling) {
    falling_since_ = -1.0;
  } else if (falling_since_ < 0.0) {
    falling_since_ = f.time;
    unseen_at_fall_ = unseen_time_;
  }
  const bool fell = falling && f.time - falling_since_ + 1e-9 >= s_.fall_time;
  const bool down = (f.object_on_table || f.object_on_floor) && !f.hand_holds_object;
  if (!dropped_ && (down || fell)) {
    dropped_ = true;
    const bool on_something = f.object_on_table || f.object_on_floor;
    drop_time_ = on_something || falling_since_ < 0.0 ? f.time : falling_since_;  // a fall: from its start
    drop_reason_ = f.object_on_table ? "table" : f.object_on_floor ? "floor" : "fell";
    unseen_at_drop_ = on_something || falling_since_ < 0.0 ? unseen_time_ : unseen_at_fall_;
  }

  lim_.position += f.position_violation ? 1 : 0;
  lim_.velocity += f.velocity_violation ? 1 : 0;
  lim_.torque += f.torque_violation ? 1 : 0;
  qp_failures_ += f.qp_failed ? 1 : 0;
  qp_relaxed_ += f.qp_relaxed ? 1 : 0;
  guarded_ += f.limit_guarded ? 1 : 0;

  // the person's hand at rest (for hand_still_to_grasp)
  if (f.hand_speed < s_.hand_rest_speed) {
    if (rest_since_ < 0.0) rest_since_ = f.time;
    if (awaiting_rest_after_grasp_ && grasp_time_) {
      still_to_grasp_ = *grasp_time_ - rest_since_;  // negative: grasped before the hand settled
      awaiting_rest_after_grasp_ = false;
    }
  } else {
    rest_since_ = -1.0;
  }

  // grasp: the fingers close on the object (first time both touch while closing)
  if (s_.mode == "human_to_robot" && !grasp_time_ && robot_holds && f.gripper_closing) {
    grasp_time_ = f.time;
    grasp_pos_err_ = f.grasp_pos_error;
    grasp_rot_err_ = f.grasp_rot_error_deg;
    if (rest_since_ >= 0.0) still_to_grasp_ = f.time - rest_since_;
    else awaiting_rest_after_grasp_ = true;
  }

  // physical exchange, held for hold_time
  bool transfer = false;
  if (s_.mode == "human_to_robot") {
    transfer = robot_holds && !f.hand_holds_object && (f.object_pos - f.hand_pos).norm() > s_.away_from_hand;
  } else {
    transfer = f.hand_holds_object && !f.left_finger_on_object && !f.right_finger_on_object;
  }
  if (transfer) {
    if (!transfer_now_) transfer_since_ = f.time;
    if (f.time - transfer_since_ + 1e-9 >= s_.hold_time) exchanged_ = true;
  }
  transfer_now_ = transfer;

  if (f.state && (states_.empty() || states_.back() != *f.state)) states_.push_back(*f.state);
  step_us_.push_back(f.step_us);
}

RunSummary OutcomeJudge::finish(bool fsm_done, const std::string& fsm_outcome, int handovers, int aborts,
                                int retries, double wall_seconds) {
  RunSummary r;
  r.mode = s_.mode;
  r.handovers = handovers;
  r.aborts = aborts;
  r.retries = retries;
  r.time_to_grasp = grasp_time_;
  r.hand_still_to_grasp = still_to_grasp_;
  r.min_human_distance = min_dist_ >= 1e8 ? std::nan("") : min_dist_;
  r.human_contacts = contacts_;
  r.penetration_time = penetration_steps_ * step_time_;
  r.object_dropped = dropped_;
  if (dropped_) {
    r.drop_time = drop_time_;
    r.drop_reason = drop_reason_;
  }
  r.limit_violations = lim_;
  r.qp_failures = qp_failures_;
  r.qp_relaxed = qp_relaxed_;
  r.person_unseen_time = unseen_time_;
  r.limit_guard_steps = guarded_;
  r.grasp_error_pos = grasp_pos_err_;
  r.grasp_error_rot_deg = grasp_rot_err_;
  r.states = states_;
  r.simulated_time = last_time_;
  r.realtime_factor = wall_seconds > 0.0 ? last_time_ / wall_seconds : 0.0;
  if (!step_us_.empty()) {
    std::vector<double> v = step_us_;
    std::sort(v.begin(), v.end());
    auto pct = [&](double p) { return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))]; };
    r.control_step_us = {pct(0.5), pct(0.99), v.back()};
  }

  // the robot must also have finished (retracted) for a success
  const bool robot_finished = fsm_done && fsm_outcome == "success";
  const bool exchange_done = exchanged_ && transfer_now_;
  if (robot_finished && exchange_done) r.total_time = last_time_;

  // the person unseen for most of the time the handover had (until it failed)
  const double window = dropped_ ? drop_time_ : last_time_;
  const double unseen = dropped_ ? unseen_at_drop_ : unseen_time_;
  const bool blind = window > 0.0 && unseen >= s_.unseen_share * window;

  // verdict, worst first
  if (lim_.position + lim_.velocity + lim_.torque > 0 || qp_failures_ > 0) r.outcome = "unsafe";
  else if (blind && contacts_ == 0 && !(robot_finished && exchange_done)) r.outcome = "no_perception";
  else if (dropped_) r.outcome = "object_drop";
  else if (contacts_ > 0) r.outcome = "hand_contact";
  else if (robot_finished && exchange_done) r.outcome = "success";
  else if (fsm_done && fsm_outcome == "aborted") r.outcome = "aborted";
  else r.outcome = "timeout";
  // a person who left: the run's time is until the robot, back, gave up on them
  // (an `expect: max_total_time` then bounds how long it waited for them)
  if (r.outcome == "aborted") r.total_time = last_time_;
  return r;
}

}  // namespace handover::app
