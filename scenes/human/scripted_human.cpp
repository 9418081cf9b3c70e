#include "scenes/human/scripted_human.hpp"

#include <algorithm>
#include <cmath>

#include "interfaces/minimum_jerk.hpp"

namespace handover::human {

using scenario::StepKind;

const char* toString(HumanEventKind k) {
  switch (k) {
    case HumanEventKind::StepStarted: return "step_started";
    case HumanEventKind::Released: return "released";
    case HumanEventKind::Grasped: return "grasped";
    case HumanEventKind::GraspMissed: return "grasp_missed";
    case HumanEventKind::WaitFired: return "wait_fired";
    case HumanEventKind::WaitTimedOut: return "wait_timed_out";
    case HumanEventKind::Withdrawing: return "withdrawing";
    case HumanEventKind::ScriptDone: return "script_done";
  }
  return "?";
}

ScriptedHuman::ScriptedHuman(const scenario::Scenario& s, const HandMotionLimits& limits)
    : script_(s.human.script),
      body_(scenario::bodyDimensionsFromHeight(s.human.height)),
      shoulder_(scenario::shoulderPosition(body_, s.human.stand_pos, s.human.stand_yaw, s.human.hand)),
      start_pose_(s.human.start),
      starts_holding_(s.human.holds_object.has_value()),
      limits_(limits) {
  // the elbow hangs down and a little away from the body, on the hand's side
  const double yaw = s.human.stand_yaw;
  const Eigen::Vector3d right(std::sin(yaw), -std::cos(yaw), 0.0);
  const Eigen::Vector3d outward = s.human.hand == scenario::HandSide::Right ? right : Eigen::Vector3d(-right);
  elbow_hint_ = (Eigen::Vector3d(0, 0, -1) + 0.5 * outward).normalized();
  torso_ = Eigen::Isometry3d::Identity();
  torso_.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  torso_.translation() = Eigen::Vector3d(s.human.stand_pos.x(), s.human.stand_pos.y(), scenario::kFloorZ);
  // the hand's path is fixed by the script: walk it once for the durations a hand can keep
  Eigen::Vector3d pos = start_pose_.translation();
  Eigen::Quaterniond rot = Eigen::Quaterniond(start_pose_.rotation()).normalized();
  durations_.assign(script_.size(), 0.0);
  for (std::size_t i = 0; i < script_.size(); ++i) {
    const scenario::ScriptStep& st = script_[i];
    durations_[i] = st.duration;
    if (st.kind != StepKind::Reach && st.kind != StepKind::Withdraw && st.kind != StepKind::Pull) continue;
    Eigen::Vector3d to = st.kind == StepKind::Pull ? Eigen::Vector3d(pos + st.dir * st.distance) : st.pos;
    Eigen::Quaterniond to_rot = rot;
    if (st.kind != StepKind::Pull && st.rpy) to_rot = Eigen::Quaterniond(scenario::rotationFromRpy(*st.rpy)).normalized();
    const double distance = (to - pos).norm();
    const double angle = rot.angularDistance(to_rot);
    durations_[i] = plausibleDuration(st.duration, distance, angle, limits);
    if (durations_[i] > st.duration) {
      stretched_.push_back({static_cast<int>(i), st.duration, durations_[i], distance, angle});
    }
    pos = to;
    rot = to_rot;
  }
  reset();
}

void ScriptedHuman::reset() {
  index_ = 0;
  started_ = false;
  step_start_ = 0.0;
  fact_since_ = -1.0;
  hand_pos_ = start_pose_.translation();
  hand_rot_ = Eigen::Quaterniond(start_pose_.rotation()).normalized();
  from_pos_ = to_pos_ = hand_pos_;
  from_rot_ = to_rot_ = hand_rot_;
  out_ = HumanOutput{};
  out_.holds_object = starts_holding_;
  out_.done = script_.empty();
  placeBody();
}

void ScriptedHuman::emit(HumanEventKind kind, double time) {
  if (out_.num_events < HumanOutput::kMaxEvents) out_.events[out_.num_events++] = {kind, time, index_};
}

void ScriptedHuman::startStep(double t0) {
  const scenario::ScriptStep& st = script_[index_];
  started_ = true;
  step_start_ = t0;
  fact_since_ = -1.0;
  from_pos_ = hand_pos_;
  from_rot_ = hand_rot_;
  to_pos_ = hand_pos_;
  to_rot_ = hand_rot_;
  if (st.kind == StepKind::Reach || st.kind == StepKind::Withdraw) {
    to_pos_ = st.pos;
    if (st.rpy) to_rot_ = Eigen::Quaterniond(scenario::rotationFromRpy(*st.rpy)).normalized();
  } else if (st.kind == StepKind::Pull) {
    to_pos_ = hand_pos_ + st.dir * st.distance;
  }
  emit(HumanEventKind::StepStarted, t0);
  if (st.kind == StepKind::Withdraw) emit(HumanEventKind::Withdrawing, t0);
}

void ScriptedHuman::finishStep(double t_end) {
  ++index_;
  started_ = false;
  step_start_ = t_end;
  if (index_ >= static_cast<int>(script_.size())) {
    out_.done = true;
    emit(HumanEventKind::ScriptDone, t_end);
  }
}

const HumanOutput& ScriptedHuman::step(double t, const HumanFacts& facts) {
  out_.num_events = 0;
  out_.hand_velocity.setZero();
  // instantaneous steps (release, grasp, fired waits) chain within one call
  for (int guard = 0; guard < 4 * HumanOutput::kMaxEvents && !out_.done; ++guard) {
    if (!started_) startStep(step_start_);
    const scenario::ScriptStep& st = script_[index_];
    const double elapsed = t - step_start_;
    bool finished = false;
    double t_end = t;
    switch (st.kind) {
      case StepKind::Reach:
      case StepKind::Withdraw:
      case StepKind::Pull: {
        // the duration a hand can keep (stretchedSteps(): longer than written when that is too fast)
        const double duration = durations_[index_];
        const double s = elapsed / duration;
        if (s >= 1.0) {
          hand_pos_ = to_pos_;
          hand_rot_ = to_rot_;
          finished = true;
          t_end = step_start_ + duration;
        } else {
          const double phase = minimumJerkPhase(s);
          hand_pos_ = from_pos_ + phase * (to_pos_ - from_pos_);
          hand_rot_ = from_rot_.slerp(phase, to_rot_);
          out_.hand_velocity = (minimumJerkRate(s) / duration) * (to_pos_ - from_pos_);
        }
        break;
      }
      case StepKind::Hold:
        if (elapsed >= st.duration) {
          finished = true;
          t_end = step_start_ + st.duration;
        }
        break;
      case StepKind::Wait: {
        const bool fact = st.until == scenario::WaitUntil::FingersOnObject ? facts.fingers_on_object
                          : st.until == scenario::WaitUntil::ObjectFree    ? facts.object_free
                                                                          : facts.object_in_reach;
        if (fact) {
          if (fact_since_ < 0.0) fact_since_ = t;
          if (t - fact_since_ >= st.delay) {
            emit(HumanEventKind::WaitFired, t);
            finished = true;
          }
        } else {
          fact_since_ = -1.0;
        }
        if (!finished && st.timeout && elapsed >= *st.timeout) {
          t_end = step_start_ + *st.timeout;
          emit(HumanEventKind::WaitTimedOut, t_end);
          finished = true;
        }
        break;
      }
      case StepKind::Release:
        if (out_.holds_object) emit(HumanEventKind::Released, step_start_);
        out_.holds_object = false;
        finished = true;
        t_end = step_start_;
        break;
      case StepKind::Grasp:
        if (facts.object_in_reach) {
          out_.holds_object = true;
          emit(HumanEventKind::Grasped, step_start_);
        } else {
          emit(HumanEventKind::GraspMissed, step_start_);
        }
        finished = true;
        t_end = step_start_;
        break;
    }
    if (!finished) break;
    finishStep(t_end);
  }
  out_.step_index = index_;
  out_.hand_speed = out_.hand_velocity.norm();
  placeBody();
  return out_;
}

void ScriptedHuman::placeBody() {
  sim::HumanBodyPoses& p = out_.poses;
  p.hand = Eigen::Isometry3d::Identity();
  p.hand.linear() = hand_rot_.toRotationMatrix();
  p.hand.translation() = hand_pos_;
  const ArmPlacement arm =
      placeArm(shoulder_, hand_pos_, {body_.upper_arm, body_.forearm, body_.wrist_to_grip}, elbow_hint_);
  p.upper_arm = arm.upper_arm;
  p.forearm = arm.forearm;
  p.torso = torso_;
  p.forearm_length = body_.forearm;
  p.upper_arm_length = body_.upper_arm;
}

}  // namespace handover::human
