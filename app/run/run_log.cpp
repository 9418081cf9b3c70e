#include "app/run/run_log.hpp"
#include "app/report/output_files.hpp"
#include "perception/reject_counts.hpp"

#include <sstream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace handover::app {

namespace {
void addPose(std::vector<std::string>& c, const std::string& p) {
  for (const char* a : {"x", "y", "z", "roll", "pitch", "yaw"}) c.push_back(p + "_" + a);
}
void addIndexed(std::vector<std::string>& c, const std::string& p, int n) {
  for (int i = 1; i <= n; ++i) c.push_back(p + std::to_string(i));
}
}  // namespace

RunLog::RunLog() {
  // the column contract (docs/outputs.md); time and state first
  columns_ = {"time", "state", "sensed_valid"};
  addPose(columns_, "sensed");
  addPose(columns_, "obs");
  addPose(columns_, "grasp");
  addPose(columns_, "tcp");
  for (const char* c : {"hand_x", "hand_y", "hand_z", "hand_speed", "object_x", "object_y", "object_z"})
    columns_.push_back(c);
  addIndexed(columns_, "q", 7);
  addIndexed(columns_, "qd", 7);
  addIndexed(columns_, "tau", 7);
  addIndexed(columns_, "qmargin", 7);
  for (const char* c : {"d_human", "d_table", "d_self", "ft_fx", "ft_fy", "ft_fz", "ft_tx", "ft_ty", "ft_tz",
                        "finger_width", "gripper_cmd", "speed_scale", "qp_status", "qp_iterations"})
    columns_.push_back(c);
  // the physical exchange (issue 13): load share, the load on the wrist in
  // world axes, the part the dynamics hold as a known wrench, the grip force
  for (const char* c : {"load_share", "load_fx", "load_fy", "load_fz", "ff_fx", "ff_fy", "ff_fz", "grip_force"})
    columns_.push_back(c);
  columns_.push_back("qp_slack");  // widening of the collision rows when relaxed (m/s^2), else 0
  // sensing (issue 16): a usable estimate of the person; samples refused so far, per reason
  columns_.push_back("person_seen");
  for (int k = 0; k < perception::kRejectReasons; ++k)
    columns_.push_back(std::string("rejected_") + perception::toString(static_cast<perception::RejectReason>(k)));
  columns_.push_back("guard_steps");  // steps so far whose command the limit guard changed
  columns_.push_back("person_contact");  // 1: the robot touches the person (the judge's contact, true geometry)
  // the collision pair nearest its safety distance (what holds a stalled arm back): its
  // distance after margins minus sDist (m), and its label (the last column, text)
  columns_.push_back("nearest_gap");
  columns_.push_back("nearest_pair");
  numeric_ = columns_.size() - 2;  // every column but the state name and the pair label
}

void RunLog::reserve(std::size_t rows) {
  buffer_.reserve(rows * numeric_);
  state_index_.reserve(rows);
  label_index_.reserve(rows);
  states_.reserve(64);
}

void RunLog::begin(double time, const std::string& state) {
  buffer_.push_back(time);
  int idx = -1;
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (states_[i] == state) {
      idx = static_cast<int>(i);
      break;
    }
  }
  if (idx < 0) {
    states_.push_back(state);
    idx = static_cast<int>(states_.size()) - 1;
  }
  state_index_.push_back(idx);
}

void RunLog::putPose(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d p = pose.translation();
  const Eigen::Vector3d r = rpyFromRotation(pose.linear());
  for (int i = 0; i < 3; ++i) buffer_.push_back(p[i]);
  for (int i = 0; i < 3; ++i) buffer_.push_back(r[i]);
}

void RunLog::end() {
  ++rows_;
  if (label_index_.size() != rows_) throw std::logic_error("RunLog: row " + std::to_string(rows_) + " has no label");
  if (buffer_.size() != rows_ * numeric_) {
    throw std::logic_error("RunLog: row " + std::to_string(rows_) + " has " +
                           std::to_string(buffer_.size() - (rows_ - 1) * numeric_) + " values, expected " +
                           std::to_string(numeric_));
  }
}

void RunLog::write(const std::string& path) const {
  std::ostringstream out;
  for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << columns_[c];
  out << "\n";
  char buf[32];
  for (std::size_t r = 0; r < rows_; ++r) {
    const double* row = &buffer_[r * numeric_];
    std::snprintf(buf, sizeof buf, "%.4f", row[0]);
    out << buf << ',' << states_[state_index_[r]];
    for (std::size_t c = 1; c < numeric_; ++c) {
      if (std::isfinite(row[c])) {
        std::snprintf(buf, sizeof buf, "%.6g", row[c]);
        out << ',' << buf;
      } else {
        out << ",nan";
      }
    }
    const int label = label_index_[r];
    out << ',' << (label >= 0 && label < static_cast<int>(labels_.size()) ? labels_[label] : "") << "\n";
  }
  writeFileChecked(path, out.str());
}

Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}

}  // namespace handover::app
