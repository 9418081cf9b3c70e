#include "perception/csv_pose_source.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/bounded_file.hpp"
#include "config/input_error.hpp"
#include "perception/object_columns.hpp"
#include "perception/pose_codec.hpp"

namespace handover::perception {

const char* poseCsvHeader() {
  return "t,hand_x,hand_y,hand_z,hand_qw,hand_qx,hand_qy,hand_qz,"
         "forearm_x,forearm_y,forearm_z,forearm_qw,forearm_qx,forearm_qy,forearm_qz,"
         "upper_arm_x,upper_arm_y,upper_arm_z,upper_arm_qw,upper_arm_qx,upper_arm_qy,upper_arm_qz";
}

void writePoseCsv(const std::string& path, const std::vector<PoseSample>& samples) {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot open for writing");
  // the object columns are written when every sample measured the object
  bool with_object = !samples.empty();
  for (const PoseSample& s : samples) with_object &= s.has_object;
  out << (with_object ? poseCsvHeaderWithObject().c_str() : poseCsvHeader()) << "\n";
  char line[kMaxEncodedSample];
  std::string row;
  for (const PoseSample& s : samples) {
    encodeSample(s, ',', line, sizeof line);
    row = line;
    if (with_object) appendObjectColumns(s.object, ',', row);
    out << row << "\n";
  }
  if (!out) throw InputError(path + ": write failed");
}

std::vector<PoseSample> readPoseCsv(const std::string& path) {
  return parsePoseCsv(readBoundedFile(path, kMaxPoseCsvBytes, "pose recording (CSV)"), path);
}

std::vector<PoseSample> parsePoseCsv(const std::string& text, const std::string& path) {
  std::vector<PoseSample> out;
  std::string line;
  int lineno = 0;
  bool header_seen = false, with_object = false;
  std::istringstream in(text);
  // a UTF-8 byte-order mark (spreadsheet exports) is not part of the header
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) in.seekg(3);
  while (std::getline(in, line)) {
    ++lineno;
    if (line.size() > kMaxCsvSampleLine) {
      throw InputError(path + ":" + std::to_string(lineno) + ": line longer than " +
                       std::to_string(kMaxCsvSampleLine) + " bytes (not a pose sample)");
    }
    if (line.find('\0') != std::string::npos) throw InputError(path + ":" + std::to_string(lineno) + ": NUL byte");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      with_object = line == poseCsvHeaderWithObject();
      if (line != poseCsvHeader() && !with_object) {
        throw InputError(path + ":" + std::to_string(lineno) + ": expected the header '" + poseCsvHeader() +
                         "' (optionally followed by the object columns, docs/perception.md)");
      }
      header_seen = true;
      continue;
    }
    PoseSample s;
    Pose object;
    const char* err = with_object ? takeObjectColumns(line, ',', object) : nullptr;
    if (!err) err = decodeSample(line.c_str(), ',', s);
    s.has_object = with_object;
    if (with_object) s.object = object;
    if (err) throw InputError(path + ":" + std::to_string(lineno) + ": " + err);
    if (!out.empty() && s.stamp < out.back().stamp) {
      throw InputError(path + ":" + std::to_string(lineno) + ": time stamp goes back");
    }
    out.push_back(s);
  }
  if (!header_seen) throw InputError(path + ": empty file (no header)");
  return out;
}

CsvPoseSource::CsvPoseSource(const std::string& path, double time_shift)
    : samples_(readPoseCsv(path)), shift_(time_shift) {}

CsvPoseSource::CsvPoseSource(std::vector<PoseSample> samples, double time_shift)
    : samples_(std::move(samples)), shift_(time_shift) {}

bool CsvPoseSource::poll(double now, PoseSample& out) {
  if (next_ >= samples_.size() || now + 1e-12 < samples_[next_].stamp + shift_) return false;
  out = samples_[next_++];
  out.stamp += shift_;
  return true;
}

}  // namespace handover::perception
