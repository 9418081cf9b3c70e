#include "app/render/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <cstring>
#include <mutex>
#include <stdexcept>

namespace handover::render {
namespace {

// eglTerminate tears down every context on a display, so the shared
// surfaceless display is terminated only when the last context goes away.
std::mutex g_display_mutex;
EGLDisplay g_display = EGL_NO_DISPLAY;
int g_display_users = 0;

std::string eglErrorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error 0x" + std::to_string(code);
  }
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    const bool starts = (p == list || p[-1] == ' ');
    const bool ends = (p[n] == '\0' || p[n] == ' ');
    if (starts && ends) return true;
  }
  return false;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("no EGL display: " + what +
                           " (headless rendering needs Mesa's EGL: libegl-mesa0, libgl1-mesa-dri)");
}

EGLDisplay acquireDisplay() {
  std::lock_guard<std::mutex> lock(g_display_mutex);
  if (g_display_users > 0) {
    ++g_display_users;
    return g_display;
  }
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(client_ext, "EGL_MESA_platform_surfaceless"))
    fail("the EGL client does not offer EGL_MESA_platform_surfaceless");
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) fail("eglGetPlatformDisplayEXT is missing");
  EGLDisplay display =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT: " + eglErrorName(eglGetError()));
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor))
    fail("eglInitialize: " + eglErrorName(eglGetError()));
  g_display = display;
  g_display_users = 1;
  return display;
}

void releaseDisplay() {
  std::lock_guard<std::mutex> lock(g_display_mutex);
  if (g_display_users > 0 && --g_display_users == 0) {
    eglTerminate(g_display);
    g_display = EGL_NO_DISPLAY;
  }
}

}  // namespace

EglContext::EglContext() {
  EGLDisplay display = acquireDisplay();
  display_ = display;
  try {
    const char* ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(ext, "EGL_KHR_surfaceless_context"))
      fail("the display does not support EGL_KHR_surfaceless_context");

    // MuJoCo draws into its own FBO, so the config only has to allow desktop
    // GL; depth/stencil of the default framebuffer are never used.
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                                     EGL_NONE};
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLint num_configs = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &num_configs) || num_configs < 1) {
      if (!hasExtension(ext, "EGL_KHR_no_config_context"))
        fail("no EGL config with desktop OpenGL support");
      config = EGL_NO_CONFIG_KHR;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API): " + eglErrorName(eglGetError()));
    // No version attributes: a compatibility-profile context, which MuJoCo
    // 2.2's fixed-function renderer needs.
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
    if (context == EGL_NO_CONTEXT) fail("eglCreateContext: " + eglErrorName(eglGetError()));
    context_ = context;
    makeCurrent();
    auto str = [](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(glGetString(name));
      return std::string(s ? s : "?");
    };
    if (glGetString(GL_VERSION) == nullptr) fail("the EGL context has no working OpenGL");
    description_ = str(GL_VENDOR) + " / " + str(GL_RENDERER) + " / " + str(GL_VERSION);
  } catch (...) {
    if (context_ != nullptr) {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display, static_cast<EGLContext>(context_));
    }
    releaseDisplay();
    throw;
  }
}

EglContext::~EglContext() {
  auto display = static_cast<EGLDisplay>(display_);
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  releaseDisplay();
}

void EglContext::makeCurrent() {
  auto context = static_cast<EGLContext>(context_);
  if (eglGetCurrentContext() == context) return;
  eglBindAPI(EGL_OPENGL_API);
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw std::runtime_error("eglMakeCurrent failed: " + eglErrorName(eglGetError()) +
                             " (is another OpenGL context current on this thread?)");
}

void EglContext::release() {
  if (eglGetCurrentContext() != EGL_NO_CONTEXT)
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                   EGL_NO_CONTEXT);
}

}  // namespace handover::render
