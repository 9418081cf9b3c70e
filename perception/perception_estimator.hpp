// Estimates the person's tracked bodies (hand, forearm, upper arm, and the
// object when the tracker follows it) from pose samples, and derives the
// object's pose.
//
// Every sample passes the plausibility gates first (plausibility_gate.hpp):
// a non-finite or non-unit value, a stamp out of order or from the future, a
// body outside the workspace, a jump, a speed or an acceleration no person
// makes: refused and counted per reason (rejects()), the estimate unchanged.
// Accepted samples feed the motion model (EstimatorSettings::model):
//   kalman     a constant-velocity Kalman filter per body on position and
//              rotation (pose_filter.hpp); the estimate at `now` is predicted
//              forward by the sample's age, at most prediction_horizon s, so
//              a steady sensor latency is compensated instead of followed;
//   smoothing  first-order smoothing of each new sample (the estimator
//              before the filter; kept to compare), never extrapolated.
// Stale: no accepted sample for max_gap (the stream stopped, or every sample
// is refused: a failing source is silence, never motion), or the latest one
// arrived older than max_latency (too late to act on). A steady latency
// below max_latency is not staleness. The consumer decides what to do with
// stale data (hold, slow down, treat the person as lost).
//
// Who holds the object decides where its pose comes from: the person's hand
// (the tracked object pose when the sample has one, else hand pose * hand->
// object offset; as old as the hand sample) or the robot's forward
// kinematics (TCP pose * grasp offset, always fresh). Perception writes
// estimates, never commands.
// World frame, m, s. All methods after construction are real-time safe.
#pragma once

#include <Eigen/Geometry>

#include "perception/plausibility_gate.hpp"
#include "perception/pose_filter.hpp"
#include "perception/pose_source.hpp"
#include "perception/reject_counts.hpp"

namespace handover::perception {

enum class MotionModel { kKalman, kSmoothing };

struct EstimatorSettings {
  double max_gap = 0.1;      ///< s without an accepted sample arriving: the stream stopped (stale)
  double max_latency = 1.0;  ///< s; a sample older than this when it arrives is too late to act on (stale)
  MotionModel model = MotionModel::kKalman;
  /// kalman: s, the estimate is predicted forward by the sample's age up to
  /// this (a sample older than that is predicted this far: beyond, a
  /// constant-velocity guess overshoots more than it helps). 0 = the
  /// filtered pose at the sample's own stamp.
  double prediction_horizon = 0.3;
  /// kalman: s, the same for rotations (hands turn in short, quick
  /// motions: a turn rate held longer than ~50 ms overshoots).
  double rotation_prediction_horizon = 0.0;
  /// kalman: the prediction uses each velocity scaled by its significance
  /// (PoseFilter::predict with this k): at rest, the velocity's noise times
  /// the horizon would make the estimate jitter. 0 = plain prediction.
  double prediction_significance = 2.0;
  /// kalman: true = rotations from the first-order smoothing
  /// (rotation_smoothing_time) instead of the filter (positions stay filtered
  /// and predicted).
  bool smooth_rotations = true;
  PoseFilterSettings filter;  ///< kalman: noise and motion model
  /// smoothing: s, time constant of the first-order smoothing applied to
  /// each new sample (positions exponentially, rotations by slerp), 0 =
  /// none. The weight of a sample is 1 - exp(-dt / smoothing_time), so after
  /// a dropout the estimate snaps back to the data instead of crawling.
  double smoothing_time = 0.0;
  /// smoothing: s, the same for rotations (negative: use smoothing_time).
  /// Rotational noise matters more: through the lever from the object to
  /// the grasp frame it becomes position noise, and the centripetal term
  /// w x (w x r) of the grasp acceleration turns its variance into a pull.
  double rotation_smoothing_time = -1.0;
  GateSettings gate;  ///< plausibility gates
  /// Object pose in the person's hand frame while the person holds it.
  Eigen::Isometry3d hand_T_object = Eigen::Isometry3d::Identity();
};

enum class ObjectHolder { Nobody, Person, Robot };

struct HumanEstimate {
  bool valid = false;  ///< a sample has been accepted since the start
  bool stale = true;   ///< no sample, none accepted for max_gap, or the latest arrived older than max_latency
  double stamp = 0.0;  ///< s, measurement time of the latest accepted sample
  double age = 0.0;    ///< s, now - stamp (0 if none)
  double silence = 0.0;  ///< s since the latest accepted sample arrived (0 if none)
  double latency = 0.0;  ///< s, how old the latest accepted sample was when it arrived
  double predicted = 0.0;  ///< s the positions below were predicted forward from `stamp` (kalman)
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();
  /// kalman: the motion model's hand velocity, [linear (m/s); angular
  /// (rad/s)], world axes (a derivative the model estimates, steadier than
  /// differences of noisy samples); `has_velocity` false otherwise.
  bool has_velocity = false;
  Eigen::Matrix<double, 6, 1> hand_velocity = Eigen::Matrix<double, 6, 1>::Zero();
  /// m/s, the motion model's standard deviation of each component of the
  /// hand's linear velocity (its covariance; large while a track is young:
  /// two samples of a hand at rest differ by the sensor's noise); 0 without one.
  double hand_speed_std = 0.0;
};

struct ObjectEstimate {
  bool valid = false;  ///< the pose is known (someone holds it and, for the person, a sample exists)
  bool stale = true;   ///< derived from a stale hand sample
  ObjectHolder holder = ObjectHolder::Nobody;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< object frame in the world
  /// kalman, while the person holds it: its velocity, [linear; angular],
  /// world axes (the tracked object's own, or the hand's carried rigidly to
  /// the object's origin); `has_velocity` false otherwise.
  bool has_velocity = false;
  Eigen::Matrix<double, 6, 1> velocity = Eigen::Matrix<double, 6, 1>::Zero();
  /// m/s, as HumanEstimate::hand_speed_std, for `velocity`; carried by the
  /// hand, with the hand's angular velocity's at the lever arm (hand to object)
  double speed_std = 0.0;
};

struct PerceptionEstimate {
  double time = 0.0;
  HumanEstimate human;
  ObjectEstimate object;
};

class PerceptionEstimator {
 public:
  explicit PerceptionEstimator(const EstimatorSettings& settings = {});
  void reset();

  /// Takes a sample if it passes the gates; `arrival`: when it was received
  /// (s, the clock of estimate()), by default its own stamp (no latency).
  /// False when refused (counted in rejects()).
  bool addSample(const PoseSample& s, double arrival);
  bool addSample(const PoseSample& s) { return addSample(s, s.stamp); }
  /// Drains `source` of everything that arrived by `now`; returns how many were taken.
  int update(double now, PoseSource& source);
  /// Changes where the object sits in the hand (e.g. after the person re-grasps).
  void setHandObjectOffset(const Eigen::Isometry3d& hand_T_object) { settings_.hand_T_object = hand_T_object; }

  /// The estimate at `now`. `tcp_pose` (world) and `tcp_T_object` are used only
  /// when the robot holds the object.
  const PerceptionEstimate& estimate(double now, ObjectHolder holder,
                                     const Eigen::Isometry3d& tcp_pose = Eigen::Isometry3d::Identity(),
                                     const Eigen::Isometry3d& tcp_T_object = Eigen::Isometry3d::Identity());

  /// True when the latest sample measured the object as its own body.
  bool objectTracked() const { return have_ && latest_.has_object; }
  long rejected() const { return rejects_.total(); }  ///< samples refused, all reasons
  const RejectCounts& rejects() const { return rejects_; }  ///< samples refused, per reason
  long reseeds() const { return reseeds_; }  ///< tracks started afresh after a gap (the first included)
  const EstimatorSettings& settings() const { return settings_; }

 private:
  void smooth(const PoseSample& s) { smoothInto(latest_, s, have_); }
  void smoothInto(PoseSample& into, const PoseSample& s, bool have) const;
  void filter(const PoseSample& s, bool reseed);

  EstimatorSettings settings_;
  PlausibilityGate gate_;
  bool have_ = false;
  PoseSample latest_;  ///< smoothing: the smoothed sample; kalman: the latest accepted (raw)
  PoseSample smoothed_;  ///< kalman with rotation_smoothing: the first-order smoothed sample (its rotations)
  PoseFilter hand_f_, forearm_f_, upper_arm_f_, object_f_;
  double arrival_ = 0.0;  ///< s, when latest_ arrived
  PerceptionEstimate est_;
  RejectCounts rejects_;
  long reseeds_ = 0;
};

}  // namespace handover::perception
