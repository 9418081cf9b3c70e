// log.csv of a paper-experiment run, in the column names of docs/outputs.md
// that scripts/plot_run.py reads (sensed_*, obs_*, grasp_*, tcp_* as x, y, z,
// roll, pitch, yaw; q*, qd*, tau*, qmargin*), plus the ground truth
// (object_true_*, grasp_true_*) and hand_speed. No `state` column: the
// experiment has no state machine. World frame, m, rad, s.
// Rows go into a buffer reserved up front; the file is written once.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "app/experiment/experiment_metrics.hpp"

namespace handover::app {

/// Roll, pitch, yaw (rad) with R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& R);

/// Arm quantities logged beside an ExperimentSample.
struct ExperimentArmRow {
  Eigen::Matrix<double, 7, 1> q, qd, tau;  ///< rad, rad/s, N m
  Eigen::Matrix<double, 7, 1> q_margin;    ///< rad, distance to the nearest position limit
};

class ExperimentLog {
 public:
  ExperimentLog();
  void reserve(std::size_t rows);
  void add(const ExperimentSample& s, const ExperimentArmRow& arm);
  std::size_t rows() const { return rows_; }
  const std::vector<std::string>& columns() const { return columns_; }
  /// Writes the CSV; throws InputError naming the file if it cannot be written.
  void write(const std::string& path) const;

 private:
  void putPose(const Eigen::Isometry3d& pose);
  std::vector<std::string> columns_;
  std::vector<double> buffer_;
  std::size_t rows_ = 0;
};

}  // namespace handover::app
