// `--video FILE.mp4`: records the simulation headlessly into an H.264 MP4.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>

#include "app/render/ffmpeg_pipe.hpp"
#include "app/render/offscreen_renderer.hpp"

namespace handover::render {

struct VideoOptions {
  std::string path;                      ///< output .mp4 (overwritten)
  int width = 640;                       ///< px, even
  int height = 480;                      ///< px, even
  double fps = 30.0;                     ///< video frames per simulated second (0 < fps <= 240)
  std::string camera = "overview";       ///< see cameraByName()
  bool overlay = true;                   ///< time and state text in the top-left corner
  int crf = 23;                          ///< x264 quality (lower = better, bigger)
  std::string ffmpeg = "ffmpeg";         ///< encoder executable
};

/// Renders frames offscreen (EGL) and pipes them into ffmpeg. The video plays
/// in simulated time: one frame every 1/fps s of simulation, so a 15 s run at
/// 30 fps gives 450 frames whatever the real-time factor.
///
/// Typical loop:  if (rec.wantsFrame(d->time)) rec.addFrame(m, d, state);
/// then rec.close() to learn whether ffmpeg succeeded. Nothing here is
/// real-time safe; wantsFrame() is a cheap comparison and may be called every
/// control step. One recorder per thread.
class VideoRecorder {
 public:
  /// Throws handover::InputError for bad options (size, fps, camera name,
  /// empty path) and std::runtime_error when headless OpenGL ("no EGL
  /// display: ...") or ffmpeg ("... not found on PATH") is unavailable.
  VideoRecorder(const mjModel* m, const VideoOptions& options);
  /// Finishes the file if close() was not called; errors are swallowed there.
  ~VideoRecorder();
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;

  /// True when simulated time `sim_time` (s) has reached the next frame.
  bool wantsFrame(double sim_time) const;

  /// Renders the current state and appends it. If the simulation jumped over
  /// several frame slots since the last frame, the image is repeated so the
  /// video keeps simulated time. `state` is shown in the overlay.
  /// Throws std::runtime_error (with ffmpeg's stderr) if ffmpeg died.
  void addFrame(const mjModel* m, mjData* d, const std::string& state = {});

  /// Ends the video and waits for ffmpeg; throws std::runtime_error with the
  /// tail of ffmpeg's stderr if encoding failed. Idempotent.
  void close();

  /// Frames written so far (including repeats).
  long frames() const { return frames_; }
  const VideoOptions& options() const { return options_; }
  /// Which camera is used and why.
  const std::string& cameraNote() const { return renderer_->cameraNote(); }
  OffscreenRenderer& renderer() { return *renderer_; }

 private:
  VideoOptions options_;
  std::unique_ptr<OffscreenRenderer> renderer_;
  std::unique_ptr<FfmpegPipe> ffmpeg_;
  double start_time_ = 0.0;  // sim time of frame 0
  long frames_ = 0;
  std::string left_, right_;  // overlay text, reused
};

}  // namespace handover::render
