#include "app/import/import_recording.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "perception/csv_pose_source.hpp"
#include "perception/recording/recording_import.hpp"

namespace handover::app {

namespace {

/// "{pos: [x, y, z], rpy: [r, p, y]}" with rpy as in scenario files (Z-Y-X).
std::string posRpy(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d R = T.linear();
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  char b[160];
  std::snprintf(b, sizeof b, "{pos: [%.3f, %.3f, %.3f], rpy: [%.3f, %.3f, %.3f]}", T.translation().x(),
                T.translation().y(), T.translation().z(), roll, pitch, yaw);
  return b;
}

}  // namespace

std::string importRecordingToCsv(const ImportOptions& o) {
  perception::recording::RecordingMapping m = perception::recording::loadRecordingMapping(o.mapping);
  if (o.speed) m.speed = *o.speed;
  if (o.mirror) m.mirror = *o.mirror;
  const perception::recording::ImportedRecording rec = perception::recording::importRecording(m, o.data_dir);
  const std::filesystem::path parent = std::filesystem::path(o.out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  perception::writePoseCsv(o.out, rec.samples);

  const perception::PoseSample& a = rec.samples.front();
  const perception::PoseSample& z = rec.samples.back();
  const Eigen::Isometry3d hand0 = a.hand.isometry();
  std::ostringstream os;
  char line[200];
  std::snprintf(line, sizeof line, "imported   %zu samples (%zu recorded, %zu held), %.3f s, speed %.2f%s\n",
                rec.samples.size(), rec.recorded_rows, rec.samples.size() - rec.recorded_rows, z.stamp, m.speed,
                m.mirror ? ", mirrored" : "");
  os << line;
  os << "hand       starts " << posRpy(hand0) << "\n           ends   " << posRpy(z.hand.isometry()) << "\n";
  os << "object     " << (m.object.tracked ? "tracked" : "in the hand") << ", starts "
     << posRpy(a.object.isometry()) << "\n";
  // a person facing the robot (-x) has the right shoulder on +y
  const bool right = a.upper_arm.position.y() > 0.0;
  os << "scenario   human: {hand: " << (right ? "right" : "left") << ", start: " << posRpy(hand0)
     << ",\n                   holds_object: " << posRpy(hand0.inverse() * a.object.isometry()) << "}\n";
  if (!m.object.shape.empty()) {
    os << "           object: {shape: " << m.object.shape << ", size: [";
    for (std::size_t i = 0; i < m.object.size.size(); ++i) os << (i ? ", " : "") << m.object.size[i];
    os << "]}\n";
  }
  return os.str();
}

}  // namespace handover::app
