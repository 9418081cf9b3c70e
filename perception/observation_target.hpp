// What the observation task tracks: the object or the person's hand, or a
// frame attached to one of them (e.g. the grasp frame on the object, a palm
// frame above the hand). When the selection changes, the target pose blends
// from the old source to the new one over `blend_time` (minimum-jerk phase;
// positions interpolated, rotations slerped), so the observed state (a PD
// reference model with K = 1500) sees no step and its acceleration stays
// bounded. Stale or missing data is never extrapolated: the target holds its
// last value and reports valid = false.
// World frame, m, s. select() and update() are real-time safe.
#pragma once

#include <Eigen/Geometry>

#include "perception/perception_estimator.hpp"

namespace handover::perception {

enum class TargetSource { Object, Hand };
const char* toString(TargetSource s);

struct ObservationTargetSettings {
  double blend_time = 0.5;  ///< s, duration of a switch blend (0 = jump)
};

struct TargetOutput {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< target of the observation task, world
  bool valid = false;     ///< the selected source gave fresh data this cycle
  bool blending = false;  ///< a switch blend is under way
  double blend_phase = 1.0;  ///< 0..1, minimum-jerk phase of the blend (1 = done)
  TargetSource source = TargetSource::Object;
};

class ObservationTarget {
 public:
  explicit ObservationTarget(const ObservationTargetSettings& settings = {});

  /// Tracks `source` * `attached` (attached: the frame in the source's frame)
  /// from now on, blending from what was tracked before. Re-selecting the
  /// current target is a no-op.
  void select(TargetSource source, double now,
              const Eigen::Isometry3d& attached = Eigen::Isometry3d::Identity());
  /// The target at `now` from the latest estimate.
  const TargetOutput& update(double now, const PerceptionEstimate& estimate);
  const TargetOutput& output() const { return out_; }
  void reset();

 private:
  bool sourcePose(TargetSource s, const Eigen::Isometry3d& attached, const PerceptionEstimate& e,
                  Eigen::Isometry3d& pose) const;

  ObservationTargetSettings settings_;
  TargetOutput out_;
  bool have_output_ = false;  ///< out_.pose holds a real pose
  bool selected_ = false;
  TargetSource current_ = TargetSource::Object;
  Eigen::Isometry3d attached_ = Eigen::Isometry3d::Identity();
  // blend state
  bool blending_ = false;
  double blend_start_ = 0.0;
  bool old_live_ = false;  ///< follow the old source while it still has data
  TargetSource old_source_ = TargetSource::Object;
  Eigen::Isometry3d old_attached_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d old_pose_ = Eigen::Isometry3d::Identity();  ///< last known old pose
};

}  // namespace handover::perception
