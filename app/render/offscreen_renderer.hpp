// Renders a MuJoCo scene into an RGB image without a window (EGL surfaceless).
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>
#include <vector>

#include "app/render/egl_context.hpp"

namespace handover::render {

struct OffscreenOptions {
  int width = 640;                       ///< px
  int height = 480;                      ///< px
  std::string camera = "overview";       ///< see cameraByName(): "" or a missing "overview" = workspace view
  bool fast = true;                      ///< shadows, reflections and multisampling off (~5x cheaper)
};

/// Owns an EGL context, an mjrContext whose offscreen buffer is at least
/// width x height, an mjvScene and the camera. Construction and render() are
/// not real-time safe (GPU/driver work); render() does not allocate.
class OffscreenRenderer {
 public:
  /// Throws handover::InputError for a bad size or an unknown camera name,
  /// std::runtime_error("no EGL display: ...") without headless OpenGL.
  OffscreenRenderer(const mjModel* m, const OffscreenOptions& options);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  /// Renders the state in `d` (m must be the model given at construction;
  /// mjv_updateScene needs d non-const but only reads it for drawing).
  /// `overlay_left`/`overlay_right` are drawn as two text columns at the top
  /// left, lines separated by '\n'; empty = no overlay.
  /// Returns width*height*3 bytes, RGB24, rows top to bottom (video order);
  /// the buffer is reused by the next call.
  const std::vector<unsigned char>& render(const mjModel* m, mjData* d,
                                           const std::string& overlay_left = {},
                                           const std::string& overlay_right = {});

  int width() const { return width_; }
  int height() const { return height_; }
  /// Which camera is used and why (e.g. the workspace fallback).
  const std::string& cameraNote() const { return camera_note_; }
  /// GL vendor / renderer / version.
  const std::string& glDescription() const { return egl_->description(); }
  /// Mutable camera, e.g. to move a free camera between frames.
  mjvCamera& camera() { return camera_; }

 private:
  int width_, height_;
  int nbody_, ngeom_;  // to catch a different model passed to render()
  std::unique_ptr<EglContext> egl_;
  mjvCamera camera_;
  mjvOption option_;
  mjvScene scene_;
  mjrContext context_;
  std::string camera_note_;
  std::vector<unsigned char> raw_;  // bottom-up, as OpenGL reads it
  std::vector<unsigned char> rgb_;  // top-down
};

}  // namespace handover::render
