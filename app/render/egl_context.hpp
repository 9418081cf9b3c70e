// A headless desktop-OpenGL context through EGL on Mesa's surfaceless
// platform: no X server, no window, no pbuffer. MuJoCo renders into its own
// offscreen framebuffer object inside this context.
#pragma once

#include <string>

namespace handover::render {

/// Owns one EGL context on the process-wide surfaceless display. The display
/// is shared and reference-counted, so several contexts (e.g. parallel batch
/// runs, one per thread) can live at the same time.
///
/// An OpenGL context is current per thread. Call makeCurrent() before any
/// mjr_ call and release() afterwards when the same thread also drives
/// another API (GLX through GLFW): libglvnd refuses to make an EGL context
/// current while a GLX one is. Not real-time safe (driver calls).
class EglContext {
 public:
  /// Throws std::runtime_error("no EGL display: ...") when EGL, the
  /// surfaceless platform or desktop OpenGL is unavailable.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  /// Makes this context current on the calling thread (no-op if it is).
  void makeCurrent();
  /// Releases whatever EGL context is current on the calling thread.
  void release();

  /// "vendor / renderer / version" of the GL implementation, for logs.
  const std::string& description() const { return description_; }

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string description_;
};

}  // namespace handover::render
