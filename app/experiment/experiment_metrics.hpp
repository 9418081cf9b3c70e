// Metrics of one reaching run of the paper experiment (observation error,
// tracking error, settling after the hand comes to rest, limit violations),
// computed after the run from per-step samples. Not real-time safe (the
// sample trace grows); the runner reserves it once.
//
// Frames: every pose is in the world frame (design notes 1). Units: m, s;
// rotation errors are reported in degrees (the angle of Ra^T Rb).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace handover::app {

/// One control step of a run.
struct ExperimentSample {
  double time = 0.0;                                              ///< s since the start
  Eigen::Isometry3d object_true = Eigen::Isometry3d::Identity();  ///< simulator's object pose
  Eigen::Isometry3d object_measured = Eigen::Isometry3d::Identity();  ///< sensor + estimator
  bool measured_valid = false;                                    ///< object_measured is known
  Eigen::Isometry3d observed = Eigen::Isometry3d::Identity();     ///< observation task's X_obs
  Eigen::Isometry3d reference = Eigen::Isometry3d::Identity();    ///< what the TCP is told to reach
  Eigen::Isometry3d grasp_true = Eigen::Isometry3d::Identity();   ///< object_true * grasp offset
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();          ///< simulator's TCP pose
  double hand_speed = 0.0;                                        ///< m/s, person's grip point (true)
  bool position_violation = false;  ///< a joint beyond its position limit
  bool velocity_violation = false;  ///< a joint beyond its velocity limit
  bool torque_violation = false;    ///< a commanded torque beyond its limit
  bool qp_failed = false;           ///< the controller fell back to its damped stop
  bool finger_on_object = false;    ///< a robot finger touches the object (simulator contact)
  bool robot_touches_person = false;  ///< a robot geom touches the person's geoms
};

/// RMS and maximum of an error signal over a run.
struct ErrorStats {
  double rms = 0.0;
  double max = 0.0;
};

/// Thresholds of "at rest" and "reached" (defaults: the numbers).
struct MetricThresholds {
  double rest_speed = 0.05;  ///< m/s, hand speed below which it is at rest
  double reach_pos = 0.01;   ///< m, TCP to true grasp frame
  double reach_rot_deg = 5.0;
};

struct ExperimentMetrics {
  // observation task: |P_obs - P_obj| (m) and rotation angle (deg)
  ErrorStats obs_pos_vs_true, obs_rot_vs_true;
  ErrorStats obs_pos_vs_measured, obs_rot_vs_measured;  ///< over samples with a valid measurement
  // TCP against the controller's own reference (grasp frame or set point) and against the true grasp frame
  ErrorStats track_pos, track_rot;
  ErrorStats true_pos, true_rot;
  double final_pos_error = 0.0;      ///< m, TCP to true grasp frame at the last sample
  double final_rot_error_deg = 0.0;  ///< deg
  std::optional<double> hand_rest_time;   ///< s, start of the final stretch with hand speed < rest_speed
  std::optional<double> reached_time;     ///< s, from when on the TCP stays within both tolerances
  std::optional<double> rest_to_reached;  ///< s, reached_time - hand_rest_time (negative: reached while moving)
  std::optional<double> position_settle_time;     ///< s, from when on the position stays within tolerance
  std::optional<double> orientation_settle_time;  ///< s, same for the orientation
  std::optional<bool> orientation_first;  ///< orientation settled strictly before position
  int position_violations = 0;  ///< steps with a violation of each kind
  int velocity_violations = 0;
  int torque_violations = 0;
  int qp_failures = 0;
  int finger_object_contact_steps = 0;  ///< steps with a finger on the object (the approach bumped it)
  int person_contact_steps = 0;         ///< steps with the robot touching the person
  double duration = 0.0;  ///< s, time of the last sample
};

/// The first time t[i] >= t_from from which on every error[j] <= tol
/// (j >= i); empty if the last sample is above tolerance or no sample lies at
/// or after t_from. `time` and `error` must have the same length (else
/// std::invalid_argument).
std::optional<double> settlingTime(const std::vector<double>& time, const std::vector<double>& error, double tol,
                                   double t_from = 0.0);

/// RMS and max of `values` (zeros for an empty vector).
ErrorStats errorStats(const std::vector<double>& values);

/// Angle (deg) of the rotation between two poses.
double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

/// All metrics of a run. Throws std::invalid_argument for an empty trace.
ExperimentMetrics computeExperimentMetrics(const std::vector<ExperimentSample>& samples,
                                           const MetricThresholds& thresholds = {});

/// The metrics as a JSON object (keys as in ExperimentMetrics; null for an empty optional).
std::string metricsToJson(const ExperimentMetrics& m, const std::string& controller);

}  // namespace handover::app
