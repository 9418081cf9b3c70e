#include "app/render/offscreen_renderer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "app/render/scene_camera.hpp"
#include "config/input_error.hpp"

namespace handover::render {
namespace {

constexpr int kMaxSize = 8192;    // px, far above any sensible video

}  // namespace

OffscreenRenderer::OffscreenRenderer(const mjModel* m, const OffscreenOptions& options)
    : width_(options.width), height_(options.height) {
  if (m == nullptr) throw std::invalid_argument("OffscreenRenderer: null model");
  if (width_ < 16 || height_ < 16 || width_ > kMaxSize || height_ > kMaxSize)
    throw InputError("video size " + std::to_string(width_) + "x" + std::to_string(height_) +
                     " is out of range (16..8192 px per side)");
  nbody_ = m->nbody;
  ngeom_ = m->ngeom;
  camera_ = cameraByName(m, options.camera, &camera_note_);  // before any GL work: cheap to fail

  egl_ = std::make_unique<EglContext>();
  egl_->makeCurrent();

  // mjr_makeContext sizes the offscreen buffer (and multisampling, shadow map)
  // from the model's visual settings, and the model is the caller's const one:
  // build the context from a private copy with our settings.
  mjModel* tuned = mj_copyModel(nullptr, m);
  if (tuned == nullptr) throw std::runtime_error("OffscreenRenderer: mj_copyModel failed");
  tuned->vis.global.offwidth = std::max(tuned->vis.global.offwidth, width_);
  tuned->vis.global.offheight = std::max(tuned->vis.global.offheight, height_);
  if (options.fast) {
    tuned->vis.quality.offsamples = 0;
    tuned->vis.quality.shadowsize = 256;  // unused with shadows off; keeps GPU memory small
  }
  mjv_defaultOption(&option_);
  mjv_defaultScene(&scene_);
  mjr_defaultContext(&context_);
  mjv_makeScene(m, &scene_, kSceneMaxGeoms);
  mjr_makeContext(tuned, &context_, mjFONTSCALE_100);
  mj_deleteModel(tuned);

  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  if (context_.currentBuffer != mjFB_OFFSCREEN || context_.offWidth < width_ ||
      context_.offHeight < height_) {
    const std::string got = std::to_string(context_.offWidth) + "x" + std::to_string(context_.offHeight);
    mjr_freeContext(&context_);
    mjv_freeScene(&scene_);
    egl_->release();
    throw std::runtime_error("OffscreenRenderer: no offscreen buffer of " + std::to_string(width_) +
                             "x" + std::to_string(height_) + " (got " + got + ")");
  }
  if (options.fast) {
    scene_.flags[mjRND_SHADOW] = 0;
    scene_.flags[mjRND_REFLECTION] = 0;
  }
  raw_.resize(static_cast<size_t>(width_) * height_ * 3);
  rgb_.resize(raw_.size());
  egl_->release();
}

OffscreenRenderer::~OffscreenRenderer() {
  try {
    egl_->makeCurrent();
    mjr_freeContext(&context_);
    egl_->release();
  } catch (const std::exception&) {
    // another API's context is current on this thread: the GL objects go
    // away with the EGL context itself
  }
  mjv_freeScene(&scene_);
}

const std::vector<unsigned char>& OffscreenRenderer::render(const mjModel* m, mjData* d,
                                                            const std::string& overlay_left,
                                                            const std::string& overlay_right) {
  if (m == nullptr || d == nullptr) throw std::invalid_argument("OffscreenRenderer::render: null model or data");
  if (m->nbody != nbody_ || m->ngeom != ngeom_)
    throw std::invalid_argument("OffscreenRenderer::render: not the model the renderer was built for");
  egl_->makeCurrent();
  mjr_setBuffer(mjFB_OFFSCREEN, &context_);
  const mjrRect viewport = {0, 0, width_, height_};
  mjv_updateScene(m, d, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  mjr_render(viewport, &scene_, &context_);
  if (!overlay_left.empty() || !overlay_right.empty())
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, overlay_left.c_str(),
                overlay_right.c_str(), &context_);
  mjr_readPixels(raw_.data(), nullptr, viewport, &context_);
  egl_->release();

  // OpenGL rows start at the bottom; video rows start at the top.
  const size_t row = static_cast<size_t>(width_) * 3;
  for (int y = 0; y < height_; ++y)
    std::memcpy(rgb_.data() + row * y, raw_.data() + row * (height_ - 1 - y), row);
  return rgb_;
}

}  // namespace handover::render
