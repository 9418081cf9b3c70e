// The simulated person following a tracked person (a tracker replay or a
// live stream drives the simulated bodies). A real body cannot jump: when the
// tracked poses move faster than a hand can (HandMotionLimits), each body's
// origin closes the gap at most at max_speed and max_acceleration, braking so
// as to arrive, and turns at most at max_angular_speed; poses a hand can
// follow pass through unchanged (bit for bit). Issue 16: a tracked hand that jumped into the robot used to
// teleport the simulated person into the arm (the gates refused the jump for
// the controller; after three samples the estimate followed it, and so did
// the simulated body).
//
// Model/Data: limits and period fixed at construction; step() only updates
// preallocated state and is real-time safe. World frame, m, s.
#pragma once

#include <array>

#include <Eigen/Geometry>

#include "scenes/human/hand_motion_limits.hpp"
#include "scenes/sim/sim_io.hpp"

namespace handover::human {

class PlausibleFollower {
 public:
  /// m: a body lagging its target by more than this counts as slowed (a
  /// tracker's estimate corrects itself by a few mm when a sample arrives:
  /// the body then lags by as much for a few ms, which is no jump)
  static constexpr double kReportedGap = 0.01;
  /// `dt`: s, the period step() is called at (> 0).
  PlausibleFollower(const HandMotionLimits& limits, double dt);

  /// Starts at `poses`, at rest, following nothing.
  void reset(const sim::HumanBodyPoses& poses);
  /// The poses the simulated person takes this step on its way to `target`
  /// (hand, forearm and upper arm limited; torso and segment lengths copied).
  const sim::HumanBodyPoses& step(const sim::HumanBodyPoses& target);

  /// Steps in which some body lagged its target by more than kReportedGap
  /// (the tracked person moved faster than a hand can).
  long slowedSteps() const { return slowed_steps_; }
  /// m, the largest distance by which a body lagged its target.
  double largestGap() const { return largest_gap_; }

 private:
  struct Body {
    Eigen::Vector3d pos = Eigen::Vector3d::Zero();
    Eigen::Vector3d vel = Eigen::Vector3d::Zero();
    Eigen::Vector3d target_prev = Eigen::Vector3d::Zero();
    Eigen::Quaterniond rot = Eigen::Quaterniond::Identity();
    bool following = false;  ///< lagging its target, closing the gap
  };
  /// Moves `b` toward `target`; returns whether it lags it after the step.
  bool follow(Body& b, const Eigen::Isometry3d& target, Eigen::Isometry3d& out);

  HandMotionLimits limits_;
  double dt_;
  std::array<Body, 3> bodies_{};  ///< hand, forearm, upper arm
  sim::HumanBodyPoses out_;
  long slowed_steps_ = 0;
  double largest_gap_ = 0.0;
};

}  // namespace handover::human
