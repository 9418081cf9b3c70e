// Plausibility gates on tracked pose samples: a sample that no person could
// produce is refused before it reaches the estimate, so a tracker fault
// (a value of 1e300, a body 10^5 m away, a hand that teleports 0.5 m between
// two samples) never becomes motion of the person the robot reacts to. A
// refused sample leaves the estimate as it was: a source that keeps failing
// goes silent and the estimate turns stale (the robot then behaves as when
// it lost the person).
//
// Checks, in this order, on the position of every tracked body (hand,
// forearm, upper arm, and the object when the sample and the reference both
// have it):
//   workspace     inside the box [workspace_min, workspace_max] (world, m);
//   jump          at most max_jump from the last accepted sample;
//   speed         at most max_speed * dt + tolerance from it (dt: the time
//                 between the two stamps; the tolerance absorbs sensor noise);
//   acceleration  at most 0.5 * max_acceleration * dt^2 + tolerance from where
//                 the estimator's constant-velocity model expects it (only
//                 when the estimator has such a model).
// Re-seeding: when the last accepted sample is older than reseed_gap (a
// dropout, or a source that failed that long), the next sample inside the
// workspace starts the track afresh without motion checks, so a person who
// reappears elsewhere after a dropout is believed at once, and a persistent
// step in the data is believed after reseed_gap rather than never.
// Real-time safe (no allocation). World frame, m, s.
#pragma once

#include <Eigen/Core>

#include "perception/pose_sample.hpp"
#include "perception/reject_counts.hpp"

namespace handover::perception {

struct GateSettings {
  Eigen::Vector3d workspace_min{-2.0, -2.5, -0.8};  ///< m, world: a box around the robot and the person
  Eigen::Vector3d workspace_max{3.0, 2.5, 2.5};     ///< m
  double max_speed = 3.0;          ///< m/s, fastest a tracked body may move
  double max_acceleration = 40.0;  ///< m/s^2, hardest a tracked body may accelerate
  double max_jump = 0.3;           ///< m, largest displacement between two accepted samples
  double tolerance = 0.08;         ///< m, noise allowance of the speed and acceleration checks
  double reseed_gap = 0.25;        ///< s without an accepted sample after which the track restarts
};

/// Where the estimator's motion model expects each body at a sample's stamp
/// (world, m); `valid` false: no model (the acceleration check is skipped).
struct BodyPrediction {
  bool valid = false;
  bool has_object = false;
  Eigen::Vector3d hand = Eigen::Vector3d::Zero();
  Eigen::Vector3d forearm = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper_arm = Eigen::Vector3d::Zero();
  Eigen::Vector3d object = Eigen::Vector3d::Zero();
};

enum class GateVerdict {
  kAccept,  ///< plausible continuation of the track
  kReseed,  ///< no recent track: the sample starts a new one
  kReject   ///< refused for `reason`
};

struct GateResult {
  GateVerdict verdict = GateVerdict::kAccept;
  RejectReason reason = RejectReason::kCount;  ///< set when rejected
};

class PlausibilityGate {
 public:
  explicit PlausibilityGate(const GateSettings& settings = {});
  void reset() { have_ = false; }

  /// Judges `s` (finite, stamp not before the reference: the estimator checks
  /// those) against the last accepted sample and `predicted`.
  GateResult check(const PoseSample& s, const BodyPrediction& predicted) const;
  /// `s` was taken: it becomes the reference of the next checks.
  void accept(const PoseSample& s);
  /// Every body of `s` lies inside the workspace box.
  bool inWorkspace(const PoseSample& s) const;

  const GateSettings& settings() const { return settings_; }

 private:
  bool inBox(const Eigen::Vector3d& p) const;
  /// The reason a body's move from `from` to `to` in `dt` (predicted at `pred`) is implausible, or kCount.
  RejectReason judgeMove(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double dt, bool have_pred,
                         const Eigen::Vector3d& pred) const;

  GateSettings settings_;
  bool have_ = false;
  PoseSample ref_;  ///< last accepted sample (raw, as measured)
};

}  // namespace handover::perception
