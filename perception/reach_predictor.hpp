// Where a reaching hand will come to rest. A person's reach toward a partner
// follows a minimum-jerk profile closely (straight path, bell-shaped speed:
// p(t) = p_a + D s((t - t0) / T), s(u) = 10u^3 - 15u^4 + 6u^5); once its
// speed has peaked, the samples so far fix the end point p_a + D and the
// arrival time t0 + T. The receiver can then go where the hand will stop
// instead of chasing where it is, as a person does.
//
// add() takes the hand pose at most every sample_period (decimated); from a
// reach's onset (speed above onset_speed after a rest) every new sample refits
// t0, T (grid, then golden-section on T) and p_a, D (linear least squares) to
// the samples since the rest. The end orientation continues the rotation seen
// so far along the same phase (the slerp of a minimum-jerk reach).
// `lead` (0..1) says how far to trust the end: 0 before the fitted phase
// reaches lead_start, ramping to 1 at lead_full (before the speed peak D and
// T are not separable), and 0 when the fit's RMS residual exceeds
// max_residual, the hand moves faster than the fitted profile allows (not a
// minimum-jerk reach: wandering, a hand changing its mind), or the best
// duration lies at the edge of [min_duration, max_duration] (no minimum
// inside the durations a reach takes: the fit explains nothing).
// A gap in the samples longer than restart_gap (the estimator then restarts
// its track at rest: plausibility_gate.hpp reseed_gap) loses the reach: its
// onset and course are unknown, and the restarted track's speed is not the
// hand's for a while. No reach is fitted again until the hand has rested,
// judged from restart_settle after the gap on.
// ledPose() moves a pose the way the hand moves from now to its end, by lead.
//
// World frame, m, s. add() fits (~0.1 ms, not for the 1 ms step: call it from
// the planning stage); prediction(), ledPose() and reset() are real-time safe.
// No allocation after construction.
#pragma once

#include <vector>

#include <Eigen/Geometry>

namespace handover::perception {

struct ReachPredictorSettings {
  double sample_period = 0.02;  ///< s, decimation of the samples kept
  double window = 4.0;          ///< s of samples kept
  double rest_speed = 0.05;     ///< m/s: below, the hand rests (a new reach may start)
  double onset_speed = 0.15;    ///< m/s: above, after a rest, a reach has started
  double min_duration = 0.3;    ///< s, shortest reach fitted
  double max_duration = 3.0;    ///< s, longest reach fitted
  double lead_start = 0.45;     ///< fitted phase (0..1) from which the end point is trusted at all
  double lead_full = 0.65;      ///< fitted phase from which it is trusted fully
  double max_residual = 0.02;   ///< m, RMS of the fit beyond which the motion is no minimum-jerk reach
  double restart_gap = 0.25;    ///< s between samples beyond which the reach is lost (the estimator's reseed_gap)
  double restart_settle = 0.1;  ///< s after such a gap before the speed tells a rest
};

struct ReachPrediction {
  bool reaching = false;  ///< a reach is under way (speed rose above onset_speed after a rest)
  double lead = 0.0;      ///< 0..1, trust in `end`
  double phase = 0.0;     ///< fitted phase (t - t0) / T at the latest sample
  double start = 0.0;     ///< s, fitted t0
  double duration = 0.0;  ///< s, fitted T
  double residual = 0.0;  ///< m, RMS of the fit
  /// The latest fit of this reach trusted its end fully (lead 1), kept once the
  /// hand rests there; false before, after a new onset and after a gap that lost
  /// the reach: the end the arm may have set off toward, known or not.
  bool end_trusted = false;
  Eigen::Isometry3d end = Eigen::Isometry3d::Identity();     ///< fitted resting pose
};

class ReachPredictor {
 public:
  explicit ReachPredictor(const ReachPredictorSettings& settings = {});
  void reset();

  /// The hand's pose at `t` and its linear speed (m/s, from the estimator's
  /// motion model: the rest and onset tests). Ignored when t is closer than
  /// sample_period to the last sample kept; a gap longer than the window
  /// starts afresh.
  void add(double t, const Eigen::Isometry3d& pose, double speed);

  const ReachPrediction& prediction() const { return pred_; }
  /// `pose` (world) moved rigidly as the hand moves from `hand` (its pose
  /// now) to the fitted end, by lead (position lerp, rotation slerp); `pose`
  /// itself when not leading. ledPose(hand, hand): where the hand is led to.
  Eigen::Isometry3d ledPose(const Eigen::Isometry3d& hand, const Eigen::Isometry3d& pose) const;
  const ReachPredictorSettings& settings() const { return settings_; }

 private:
  struct Sample {
    double t;
    Eigen::Vector3d p;
    Eigen::Quaterniond q;
  };
  const Sample& at(int i) const { return buf_[(head_ + i) % buf_.size()]; }  ///< i = 0: oldest kept
  void fit(double speed);
  /// Residual sum of squares of the best p_a, D for (t0, T) over samples [first, count).
  double cost(int first, double t0, double T, Eigen::Vector3d* pa, Eigen::Vector3d* d) const;

  ReachPredictorSettings settings_;
  std::vector<Sample> buf_;  ///< ring buffer, capacity window / sample_period + 1
  int head_ = 0, count_ = 0;
  double rest_time_ = -1.0;  ///< s, latest sample at rest (-1: none yet)
  double resume_time_ = -1.0;  ///< s: after a gap, the speed tells a rest from here on
  bool awaiting_rest_ = false;  ///< a gap lost the reach: none until the hand rests
  double onset_time_ = -1.0;
  ReachPrediction pred_;
};

}  // namespace handover::perception
