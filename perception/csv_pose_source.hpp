// CSV replay of timestamped pose samples (format: docs/perception.md).
// One header line, then one sample per line, 22 comma-separated numbers:
//   t, hand_{x,y,z,qw,qx,qy,qz}, forearm_{...}, upper_arm_{...}
//   (then object_{x,y,z,qw,qx,qy,qz} on every line when the header names
//   them: a tracked object, perception/object_columns.hpp)
// t in s, positions in m (world), quaternions body-to-world. Lines starting
// with '#' and blank lines are skipped. Numbers are written with 17
// significant digits so a round trip is exact.
#pragma once

#include <string>
#include <vector>

#include "perception/pose_source.hpp"

namespace handover::perception {

/// The header line the files start with.
const char* poseCsvHeader();

/// Writes samples to `path` (with the object columns when every sample has the
/// object); throws InputError if the file cannot be written.
void writePoseCsv(const std::string& path, const std::vector<PoseSample>& samples);

/// Largest pose recording read (256 MiB: over 10 minutes at 1 kHz); larger
/// files and endless devices are refused unread.
constexpr std::size_t kMaxPoseCsvBytes = std::size_t{256} << 20;

/// Reads a pose CSV; throws InputError "file:line: ..." on a bad header, a
/// wrong column count, a non-number, a non-unit quaternion, stamps that go
/// back, a line longer than a sample can be, or a file above kMaxPoseCsvBytes.
/// A leading UTF-8 byte-order mark is skipped.
std::vector<PoseSample> readPoseCsv(const std::string& path);

/// The same from the file's text (`path` names it in messages).
std::vector<PoseSample> parsePoseCsv(const std::string& text, const std::string& path);

/// Replays a file: sample i is delivered once now >= stamp_i + time_shift.
/// Loading is start-up only; poll() is real-time safe.
class CsvPoseSource : public PoseSource {
 public:
  explicit CsvPoseSource(const std::string& path, double time_shift = 0.0);
  CsvPoseSource(std::vector<PoseSample> samples, double time_shift);
  bool poll(double now, PoseSample& out) override;
  std::size_t size() const { return samples_.size(); }
  std::size_t delivered() const { return next_; }

 private:
  std::vector<PoseSample> samples_;
  double shift_;
  std::size_t next_ = 0;
};

}  // namespace handover::perception
