// Keeps the latest pose sample of the person and derives the object's pose.
// Never extrapolates: when the stream stops (no sample has arrived for
// max_gap) or delivers samples too late to act on (older than max_latency
// when they arrive), the estimate is reported stale, and the consumer decides
// what to do (hold, slow down). A sensor's steady latency alone is not
// staleness: a 60 Hz tracker 90 ms behind delivers every sample ~0.1 s old,
// and judging it by that age would hide every sample from the robot. Who holds the object decides
// where its pose comes from: the person's hand (the tracked object pose when
// the sample has one, else hand pose * hand->object offset; as old as the
// hand sample) or the robot's forward kinematics (TCP
// pose * grasp offset, always fresh). Perception writes estimates, never commands.
// World frame, m, s. All methods after construction are real-time safe.
#pragma once

#include <Eigen/Geometry>

#include "perception/pose_source.hpp"

namespace handover::perception {

struct EstimatorSettings {
  double max_gap = 0.1;      ///< s without a new sample arriving: the stream stopped (stale)
  double max_latency = 0.2;  ///< s; a sample older than this when it arrives is too late to act on (stale)
  /// s, time constant of the first-order smoothing applied to each new
  /// sample (positions exponentially, rotations by slerp), 0 = none. A
  /// 60 Hz pose stream with white noise otherwise reaches the observation
  /// task (K = 1500, about 6 Hz) almost unfiltered. The weight of a sample
  /// is 1 - exp(-dt / smoothing_time), so after a dropout the estimate
  /// snaps back to the data instead of crawling.
  double smoothing_time = 0.0;
  /// s, the same for rotations (negative: use smoothing_time). Rotational
  /// noise matters more: through the lever from the object to the grasp
  /// frame it becomes position noise, and the centripetal term w x (w x r)
  /// of the grasp acceleration turns its variance into a steady pull.
  double rotation_smoothing_time = -1.0;
  /// Object pose in the person's hand frame while the person holds it.
  Eigen::Isometry3d hand_T_object = Eigen::Isometry3d::Identity();
};

enum class ObjectHolder { Nobody, Person, Robot };

struct HumanEstimate {
  bool valid = false;  ///< a sample has arrived since the start
  bool stale = true;   ///< no sample, none for max_gap, or the latest arrived older than max_latency
  double stamp = 0.0;  ///< s, measurement time of the latest sample
  double age = 0.0;    ///< s, now - stamp (0 if none)
  double silence = 0.0;  ///< s since the latest sample arrived (0 if none)
  double latency = 0.0;  ///< s, how old the latest sample was when it arrived
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();
};

struct ObjectEstimate {
  bool valid = false;  ///< the pose is known (someone holds it and, for the person, a sample exists)
  bool stale = true;   ///< derived from a stale hand sample
  ObjectHolder holder = ObjectHolder::Nobody;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< object frame in the world
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

  /// Takes a sample if it is finite and not older than the latest one;
  /// `arrival`: when it was received (s, the clock of estimate()), by
  /// default its own stamp (no latency).
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
  long rejected() const { return rejected_; }  ///< samples refused (non-finite or out of order)
  const EstimatorSettings& settings() const { return settings_; }

 private:
  EstimatorSettings settings_;
  bool have_ = false;
  PoseSample latest_;
  double arrival_ = 0.0;  ///< s, when latest_ arrived
  PerceptionEstimate est_;
  long rejected_ = 0;
};

}  // namespace handover::perception
