// The simulated person: runs a scenario's script (design notes 2) against
// the physical facts of each step and outputs where the arm is and whether
// the hand holds the object (the simulator switches the hand-object weld).
//
// Model/Data: the constructor copies what it needs from the Scenario (built
// once); step() only updates preallocated state and is real-time safe.
// World frame, m, s. The hand pose is the grip-point frame (design notes 1).
#pragma once

#include <array>
#include <vector>

#include "scenes/human/hand_motion_limits.hpp"
#include "scenes/human/human_facts.hpp"
#include "scenes/human/two_link_arm.hpp"
#include "scenes/scenario/scenario.hpp"
#include "scenes/sim/sim_io.hpp"

namespace handover::human {

enum class HumanEventKind {
  StepStarted,   ///< a script step began (step = its index)
  Released,      ///< the hand let go of the object
  Grasped,       ///< the hand closed on the object
  GraspMissed,   ///< a grasp step found the object out of reach
  WaitFired,     ///< a wait's fact held for its delay
  WaitTimedOut,  ///< a wait ran out of time
  Withdrawing,   ///< a withdraw step began: the person is leaving
  ScriptDone,    ///< the last step ended
};
const char* toString(HumanEventKind k);

struct HumanEvent {
  HumanEventKind kind = HumanEventKind::StepStarted;
  double time = 0.0;  ///< s, when it happened (step boundaries are exact, not the call time)
  int step = -1;      ///< script step index
};

struct HumanOutput {
  static constexpr int kMaxEvents = 16;
  sim::HumanBodyPoses poses;                                 ///< world poses of hand, forearm, upper arm, torso
  bool holds_object = false;                                 ///< the hand-object weld should be on
  Eigen::Vector3d hand_velocity = Eigen::Vector3d::Zero();   ///< grip point, world, m/s
  double hand_speed = 0.0;                                   ///< m/s
  std::array<HumanEvent, kMaxEvents> events{};               ///< events of this step, in order
  int num_events = 0;
  int step_index = 0;   ///< current script step (== script size when done)
  bool done = false;    ///< the script has ended
};

/// A motion step (reach, withdraw, pull) the person takes longer than its
/// script says: its minimum-jerk profile over the written duration would
/// move the hand faster than HandMotionLimits (e.g. a reach of 5 ms, which
/// would teleport the person's body into the robot).
struct StretchedStep {
  int step = -1;                 ///< script index
  double written = 0.0;          ///< s, the script's duration
  double used = 0.0;             ///< s, the shortest the limits allow
  double distance = 0.0;         ///< m, how far the grip point moves
  double angle = 0.0;            ///< rad, how far the hand turns
};

class ScriptedHuman {
 public:
  explicit ScriptedHuman(const scenario::Scenario& scenario, const HandMotionLimits& limits = HandMotionLimits{});

  /// Back to t = 0 (start pose, initial holding state).
  void reset();
  /// Advances the script to time t (s, non-decreasing) given this step's facts.
  /// Real-time safe. The returned reference stays valid until the next call.
  const HumanOutput& step(double t, const HumanFacts& facts);
  const HumanOutput& output() const { return out_; }

  const scenario::BodyDimensions& body() const { return body_; }
  const Eigen::Vector3d& shoulder() const { return shoulder_; }
  /// Direction the elbow prefers (down and away from the body), unit, world.
  const Eigen::Vector3d& elbowHint() const { return elbow_hint_; }
  /// The motion steps the person takes longer than written (faster than a
  /// hand moves); found once from the script (hand positions do not depend
  /// on the run: reach and withdraw go to fixed poses, a pull moves by a
  /// fixed vector). Empty for an ordinary script.
  const std::vector<StretchedStep>& stretchedSteps() const { return stretched_; }
  const HandMotionLimits& limits() const { return limits_; }

 private:
  void emit(HumanEventKind kind, double time);
  void startStep(double t0);
  void finishStep(double t_end);
  void placeBody();

  // model (fixed)
  std::vector<scenario::ScriptStep> script_;
  scenario::BodyDimensions body_;
  Eigen::Vector3d shoulder_;
  Eigen::Vector3d elbow_hint_;
  Eigen::Isometry3d start_pose_;
  Eigen::Isometry3d torso_;
  bool starts_holding_ = false;
  HandMotionLimits limits_;
  std::vector<double> durations_;          ///< s, per script step: the duration the person takes
  std::vector<StretchedStep> stretched_;

  // data (per run)
  HumanOutput out_;
  int index_ = 0;
  bool started_ = false;
  double step_start_ = 0.0;
  double fact_since_ = -1.0;  ///< wait: when its fact became true (-1 = not true)
  Eigen::Vector3d from_pos_, to_pos_;
  Eigen::Quaterniond from_rot_, to_rot_;
  Eigen::Vector3d hand_pos_;
  Eigen::Quaterniond hand_rot_;
};

}  // namespace handover::human
