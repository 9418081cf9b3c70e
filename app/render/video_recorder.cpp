#include "app/render/video_recorder.hpp"

#include <cmath>
#include <cstdio>

#include "config/input_error.hpp"

namespace handover::render {
namespace {

constexpr double kTimeEps = 1e-9;  // s: float noise in accumulated sim time

}  // namespace

VideoRecorder::VideoRecorder(const mjModel* m, const VideoOptions& options) : options_(options) {
  if (options.path.empty()) throw InputError("--video: empty output file name");
  if (!(options.fps > 0.0 && options.fps <= 240.0))
    throw InputError("video fps " + std::to_string(options.fps) + " is out of range (0, 240]");
  if (options.width % 2 != 0 || options.height % 2 != 0)
    throw InputError("video size " + std::to_string(options.width) + "x" +
                     std::to_string(options.height) + " must be even (H.264 yuv420p)");
  if (options.crf < 0 || options.crf > 51)
    throw InputError("video crf " + std::to_string(options.crf) + " is out of range 0..51");

  // OpenGL first: if it fails, no empty video file is left behind.
  renderer_ = std::make_unique<OffscreenRenderer>(
      m, OffscreenOptions{options.width, options.height, options.camera, true});
  ffmpeg_ = std::make_unique<FfmpegPipe>(FfmpegSettings{options.path, options.width, options.height,
                                                        options.fps, options.crf, options.ffmpeg});
  left_.reserve(64);
  right_.reserve(128);
}

VideoRecorder::~VideoRecorder() = default;  // FfmpegPipe's destructor ends the file

bool VideoRecorder::wantsFrame(double sim_time) const {
  if (!ffmpeg_->isOpen()) return false;
  if (frames_ == 0) return true;
  return sim_time + kTimeEps >= start_time_ + static_cast<double>(frames_) / options_.fps;
}

void VideoRecorder::addFrame(const mjModel* m, mjData* d, const std::string& state) {
  if (!ffmpeg_->isOpen()) throw std::runtime_error("video " + options_.path + ": addFrame after close");
  if (frames_ == 0) start_time_ = d->time;

  // frame slots up to now; at least one frame per call
  const long due = static_cast<long>(std::floor((d->time - start_time_) * options_.fps + 1e-6)) + 1;
  const long copies = due > frames_ ? due - frames_ : 1;

  const std::vector<unsigned char>* rgb;
  if (options_.overlay) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f s", d->time);
    left_.assign("time");
    right_.assign(buf);
    if (!state.empty()) {
      left_.append("\nstate");
      right_.append("\n").append(state);
    }
    rgb = &renderer_->render(m, d, left_, right_);
  } else {
    rgb = &renderer_->render(m, d);
  }
  for (long i = 0; i < copies; ++i) ffmpeg_->write(rgb->data(), rgb->size());
  frames_ += copies;
}

void VideoRecorder::close() { ffmpeg_->close(); }

}  // namespace handover::render
