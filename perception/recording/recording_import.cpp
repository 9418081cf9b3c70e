#include "perception/recording/recording_import.hpp"

#include <cmath>
#include <filesystem>
#include <map>

#include "config/input_error.hpp"
#include "perception/recording/recorded_table.hpp"
#include "perception/recording/recording_axes.hpp"

namespace handover::perception::recording {

namespace {

/// One body's poses in the recording's world, positions in metres.
struct Track {
  std::vector<Eigen::Vector3d> position;
  std::vector<Eigen::Matrix3d> rotation;  ///< body to recording world
};

class Files {
 public:
  explicit Files(std::string dir) : dir_(std::move(dir)) {}
  const RecordedTable& get(const std::string& file) {
    auto it = tables_.find(file);
    if (it == tables_.end()) {
      const std::filesystem::path p(file);
      it = tables_.emplace(file, readRecordedTable((p.is_absolute() ? p : dir_ / p).string())).first;
    }
    return it->second;
  }

 private:
  std::filesystem::path dir_;
  std::map<std::string, RecordedTable> tables_;
};

Track readTrack(Files& files, const RecordingMapping& m, const BodyColumns& c, const std::string& key) {
  const RecordedTable& t = files.get(c.file);
  const std::string ctx = m.file + ": " + key;
  const std::vector<double>* p[3];
  const std::vector<double>* q[4];
  for (int i = 0; i < 3; ++i) p[i] = &t.column(c.position[i], ctx + ".columns.position");
  for (int i = 0; i < 4; ++i) q[i] = &t.column(c.quaternion[i], ctx + ".columns.quaternion");
  Track tr;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    tr.position.emplace_back(m.units * (*p[0])[r], m.units * (*p[1])[r], m.units * (*p[2])[r]);
    const double a = (*q[0])[r], b = (*q[1])[r], cc = (*q[2])[r], d = (*q[3])[r];
    Eigen::Quaterniond quat = m.scalar_first ? Eigen::Quaterniond(a, b, cc, d) : Eigen::Quaterniond(d, a, b, cc);
    if (std::abs(quat.norm() - 1.0) > 0.01) {
      throw InputError(t.path + ": data row " + std::to_string(r + 1) + ": the quaternion of " + key +
                       " has norm " + std::to_string(quat.norm()) + " (check `quaternion:` order and columns)");
    }
    tr.rotation.push_back(quat.normalized().toRotationMatrix());
  }
  return tr;
}

/// The mean horizontal position (z-up frame) of a track over rows [a, b).
Eigen::Vector2d meanHorizontal(const Track& t, const Eigen::Matrix3d& U, std::size_t a, std::size_t b) {
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  for (std::size_t r = a; r < b; ++r) s += (U * t.position[r]).head<2>();
  return s / static_cast<double>(b - a);
}

}  // namespace

ImportedRecording importRecording(const RecordingMapping& m, const std::string& data_dir) {
  const std::string dir = data_dir.empty() ? m.data_dir : data_dir;
  if (dir.empty()) throw InputError(m.file + ": no data folder (give `data:` in the mapping or --data DIR)");
  if (!std::filesystem::is_directory(dir)) throw InputError(dir + ": no such data folder");
  Files files(dir);

  const Track hand = readTrack(files, m, m.hand.columns, "hand");
  const Track forearm = readTrack(files, m, m.forearm.columns, "forearm");
  const Track upper = readTrack(files, m, m.upper_arm.columns, "upper_arm");
  const Track object = m.object.tracked ? readTrack(files, m, m.object.columns, "object") : Track{};
  const std::size_t rows = hand.position.size();
  for (auto [key, tr] : {std::pair{"forearm", &forearm}, std::pair{"upper_arm", &upper}, std::pair{"object", &object}}) {
    if (tr->position.empty() || tr->position.size() == rows) continue;
    throw InputError(m.file + ": " + key + " has " + std::to_string(tr->position.size()) + " rows, the hand " +
                     std::to_string(rows) + " (the bodies must be sampled together)");
  }

  // recorded time of each row
  std::vector<double> t_rec(rows);
  if (!m.time_column.empty()) {
    const std::vector<double>& tc = files.get(m.hand.columns.file).column(m.time_column, m.file + ": time_column");
    for (std::size_t r = 0; r < rows; ++r) {
      t_rec[r] = tc[r];
      if (r > 0 && !(tc[r] > tc[r - 1])) {
        throw InputError(m.hand.columns.file + ": data row " + std::to_string(r + 1) + ": time does not increase");
      }
    }
  } else {
    for (std::size_t r = 0; r < rows; ++r) t_rec[r] = static_cast<double>(r) / m.rate_hz;
  }
  const double eps = 1e-9;
  std::size_t first = 0, last = rows;  // window rows [first, last)
  while (first < rows && t_rec[first] < m.window_start - eps) ++first;
  if (m.window_end) {
    last = first;
    while (last < rows && t_rec[last] <= *m.window_end + eps) ++last;
  }
  if (last - first < 2) throw InputError(m.file + ": window: fewer than 2 samples of the recording fall inside it");

  // the recording's world in ours: up axis onto z, then the placement
  const Eigen::Matrix3d U = upRotation(m.up);
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
  if (m.place.rigid) {
    place = m.place.transform;
  } else {
    const Track receiver = readTrack(files, m, m.place.receiver, "place.receiver");
    const Track giver = readTrack(files, m, m.place.giver, "place.giver");
    if (receiver.position.size() != rows || giver.position.size() != rows) {
      throw InputError(m.file + ": place: the receiver and giver bodies must have as many rows as the hand");
    }
    const Eigen::Vector2d r = meanHorizontal(receiver, U, first, last);
    const Eigen::Vector2d g = meanHorizontal(giver, U, first, last);
    if ((g - r).norm() < 0.1) throw InputError(m.file + ": place: the giver and receiver are less than 0.1 m apart");
    const double yaw = std::atan2(g.y() - r.y(), g.x() - r.x());
    place.linear() = Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    place.translation() = place.linear() * -Eigen::Vector3d(r.x(), r.y(), m.place.floor) +
                          Eigen::Vector3d(0.0, 0.0, kFloorHeight);
  }
  place.translation() += m.place.shift;
  Eigen::Isometry3d world_T_rec = place;
  world_T_rec.linear() = place.linear() * U;

  const Eigen::Matrix3d hand_axes = handAxes(m.hand.long_axis, m.hand.back_axis);
  const Eigen::Matrix3d forearm_axes = boneAxes(m.forearm.long_axis);
  const Eigen::Matrix3d upper_axes = boneAxes(m.upper_arm.long_axis);
  const Eigen::Matrix3d object_axes = boneAxes(m.object.long_axis);
  auto ours = [&](const Track& tr, std::size_t r, const Eigen::Matrix3d& axes, const Eigen::Vector3d& offset) {
    Eigen::Isometry3d rec = Eigen::Isometry3d::Identity();
    rec.linear() = tr.rotation[r] * axes;
    rec.translation() = tr.position[r] + tr.rotation[r] * offset;
    const Eigen::Isometry3d w = world_T_rec * rec;
    return Pose::fromIsometry(m.mirror ? mirrored(w) : w);
  };

  ImportedRecording out;
  out.world_T_recording = world_T_rec;
  out.recorded_rows = last - first;
  const Eigen::Vector3d grip = m.hand.grip * m.hand.long_axis.vector();
  for (std::size_t r = first; r < last; ++r) {
    PoseSample s;
    s.stamp = (t_rec[r] - m.window_start) / m.speed;
    s.hand = ours(hand, r, hand_axes, grip);
    s.forearm = ours(forearm, r, forearm_axes, Eigen::Vector3d::Zero());
    s.upper_arm = ours(upper, r, upper_axes, Eigen::Vector3d::Zero());
    s.has_object = true;
    if (m.object.tracked) {
      s.object = ours(object, r, object_axes, Eigen::Vector3d::Zero());
    } else {
      s.object = Pose::fromIsometry(s.hand.isometry() * m.object.in_hand);
    }
    out.samples.push_back(s);
  }
  // the person holds still at the last pose for hold_end
  const double dt = out.samples.back().stamp - out.samples[out.samples.size() - 2].stamp;
  const PoseSample end = out.samples.back();
  for (int k = 1; k * dt <= m.hold_end + eps; ++k) {
    PoseSample s = end;
    s.stamp = end.stamp + k * dt;
    out.samples.push_back(s);
  }
  return out;
}

}  // namespace handover::perception::recording
