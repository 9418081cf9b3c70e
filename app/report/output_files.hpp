// Where results go and how they are written: one sanitiser for folder names
// made from scenario names (run and batch alike), a writability check before
// a run starts, and writes that are checked to the last byte (a full disk is
// an error, never an empty summary.json). Not real-time safe.
#pragma once

#include <stdexcept>
#include <string>

namespace handover::app {

/// A write of a result file failed (the message names the file and the reason).
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

/// Longest folder name made from a scenario name, bytes (filesystems allow 255).
constexpr std::size_t kMaxSafeNameBytes = 100;

/// A single path component from any text: bytes other than ASCII letters,
/// digits, '-', '_' and '.' become '_', a leading '.' becomes '_' (no "..",
/// no hidden folders), the result is cut to kMaxSafeNameBytes; "" -> "unnamed".
std::string safeFileName(const std::string& name);

/// Creates `dir` (and its parents) and proves it writable by creating and
/// removing a probe file; throws OutputError naming the folder otherwise.
void prepareOutputDir(const std::string& dir);

/// A video path's folder must already exist and be writable (the run does not
/// create folders outside its output folder); throws OutputError otherwise.
void checkVideoPath(const std::string& path);

/// Writes `content` to `path` and checks every step through the close (where
/// a full disk shows); on failure removes the partial file and throws
/// OutputError naming the file and the system's reason.
void writeFileChecked(const std::string& path, const std::string& content);

}  // namespace handover::app
