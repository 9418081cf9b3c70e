#include "app/experiment/experiment_log.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "config/input_error.hpp"

namespace handover::app {

Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& R) {
  // R = Rz(yaw) Ry(pitch) Rx(roll); pitch in [-pi/2, pi/2]
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}

namespace {
void addPose(std::vector<std::string>& c, const std::string& p) {
  for (const char* a : {"x", "y", "z", "roll", "pitch", "yaw"}) c.push_back(p + "_" + a);
}
void addIndexed(std::vector<std::string>& c, const std::string& p) {
  for (int i = 1; i <= 7; ++i) c.push_back(p + std::to_string(i));
}
}  // namespace

ExperimentLog::ExperimentLog() {
  columns_ = {"time", "sensed_valid"};
  addPose(columns_, "sensed");
  addPose(columns_, "obs");
  addPose(columns_, "grasp");
  addPose(columns_, "tcp");
  addPose(columns_, "object_true");
  addPose(columns_, "grasp_true");
  columns_.push_back("hand_speed");
  addIndexed(columns_, "q");
  addIndexed(columns_, "qd");
  addIndexed(columns_, "tau");
  addIndexed(columns_, "qmargin");
}

void ExperimentLog::reserve(std::size_t rows) { buffer_.reserve(rows * columns_.size()); }

void ExperimentLog::putPose(const Eigen::Isometry3d& pose) {
  for (int i = 0; i < 3; ++i) buffer_.push_back(pose.translation()[i]);
  const Eigen::Vector3d rpy = rollPitchYaw(pose.linear());
  for (int i = 0; i < 3; ++i) buffer_.push_back(rpy[i]);
}

void ExperimentLog::add(const ExperimentSample& s, const ExperimentArmRow& arm) {
  buffer_.push_back(s.time);
  buffer_.push_back(s.measured_valid ? 1.0 : 0.0);
  putPose(s.object_measured);
  putPose(s.observed);
  putPose(s.reference);
  putPose(s.tcp);
  putPose(s.object_true);
  putPose(s.grasp_true);
  buffer_.push_back(s.hand_speed);
  for (const auto* v : {&arm.q, &arm.qd, &arm.tau, &arm.q_margin})
    for (int j = 0; j < 7; ++j) buffer_.push_back((*v)[j]);
  ++rows_;
}

void ExperimentLog::write(const std::string& path) const {
  std::ofstream f(path);
  if (!f) throw InputError(path + ": cannot write the experiment log");
  for (std::size_t c = 0; c < columns_.size(); ++c) f << (c ? "," : "") << columns_[c];
  f << "\n";
  char num[32];
  const std::size_t w = columns_.size();
  for (std::size_t r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < w; ++c) {
      std::snprintf(num, sizeof num, "%.6g", buffer_[r * w + c]);
      f << (c ? "," : "") << num;
    }
    f << "\n";
  }
  if (!f) throw InputError(path + ": write failed");
}

}  // namespace handover::app
