// log.csv of a run: named columns (docs/outputs.md), rows kept in a buffer
// reserved at start so appending a row in the loop does not allocate; the
// file is written once at the end. State names are stored once each.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace handover::app {

class RunLog {
 public:
  RunLog();
  /// Reserves room for `rows` rows.
  void reserve(std::size_t rows);

  // a row is built with begin(), the put*() calls in column order, then end()
  void begin(double time, const std::string& state);
  void put(double v) { buffer_.push_back(v); }
  void putPose(const Eigen::Isometry3d& pose);  ///< x, y, z, roll, pitch, yaw
  void putVec(const double* v, int n) {
    for (int i = 0; i < n; ++i) buffer_.push_back(v[i]);
  }
  /// The row's label column (the last one, `nearest_pair`): an index into
  /// `labels` (set once before the loop), or -1 for an empty field.
  void putLabel(int index) { label_index_.push_back(index); }
  void setLabels(std::vector<std::string> labels) { labels_ = std::move(labels); }
  void end();

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return rows_; }
  /// Writes DIR/log.csv; throws std::runtime_error naming the file on I/O failure.
  void write(const std::string& path) const;

 private:
  std::vector<std::string> columns_;
  std::vector<double> buffer_;        // numeric columns (all but state), row-major
  std::vector<int> state_index_;      // per row
  std::vector<std::string> states_;   // distinct state names
  std::vector<int> label_index_;      // per row, into labels_ (-1: empty)
  std::vector<std::string> labels_;
  std::size_t rows_ = 0;
  std::size_t numeric_ = 0;
};

/// Roll, pitch, yaw (rad) of a rotation, R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R);

}  // namespace handover::app
