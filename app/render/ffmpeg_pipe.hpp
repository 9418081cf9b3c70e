// An `ffmpeg` child process that reads raw RGB24 frames on its stdin and
// writes an H.264 (yuv420p) MP4 file.
#pragma once

#include <cstddef>
#include <string>
#include <sys/types.h>

namespace handover::render {

struct FfmpegSettings {
  std::string path;                 ///< output file (.mp4), overwritten
  int width = 640;                  ///< px, even (yuv420p needs it)
  int height = 480;                 ///< px, even
  double fps = 30.0;                ///< frames per second of the video
  int crf = 23;                     ///< x264 quality, 0 (lossless) .. 51
  std::string executable = "ffmpeg";  ///< looked up on PATH when it has no '/'
};

/// Spawns ffmpeg in the constructor (posix_spawnp; the child's stderr goes to
/// an anonymous temp file so a chatty encoder never blocks us). Writes go
/// through a socket with MSG_NOSIGNAL so that an ffmpeg that died reports an
/// error instead of killing the process with SIGPIPE. Not real-time safe.
class FfmpegPipe {
 public:
  /// Throws std::runtime_error when ffmpeg cannot be started, e.g.
  /// "ffmpeg not found on PATH ...".
  explicit FfmpegPipe(const FfmpegSettings& settings);
  /// Closes without throwing (errors are lost: call close() to see them).
  ~FfmpegPipe();
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  /// Writes one frame: width*height*3 bytes, rows top to bottom. Throws
  /// std::runtime_error with ffmpeg's stderr tail if ffmpeg has exited.
  void write(const unsigned char* rgb, std::size_t bytes);

  /// Ends the input and waits for ffmpeg; throws std::runtime_error with the
  /// exit status and stderr tail when it failed. Idempotent.
  void close();

  bool isOpen() const { return pid_ > 0; }

 private:
  int finish();                       // closes input, reaps the child, returns exit code
  std::string stderrTail() const;     // last lines ffmpeg wrote on stderr

  FfmpegSettings settings_;
  pid_t pid_ = -1;
  int input_fd_ = -1;   // our end of the child's stdin
  int stderr_fd_ = -1;  // unlinked temp file holding the child's stderr
};

}  // namespace handover::render
