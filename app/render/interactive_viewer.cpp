#include "app/render/interactive_viewer.hpp"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "app/render/scene_camera.hpp"

namespace handover::render {
namespace {

constexpr const char* kNoDisplay = "--view needs a display; use --video for headless runs";
constexpr double kDoubleClickSeconds = 0.3;

std::string g_glfw_error;  // last GLFW error, for messages (GLFW reports through a C callback)

void recordGlfwError(int code, const char* text) {
  g_glfw_error = std::string(text ? text : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

ViewerWindow* self(GLFWwindow* w) { return static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w)); }

constexpr const char* kHelpKeys =
    "Left drag\nRight drag\nScroll\nShift\nDouble-click\nCtrl+Right drag\nCtrl+Left drag\n"
    "Backspace\nEsc\nSpace\n[  ]\nTab\nF1";
constexpr const char* kHelpActions =
    "orbit\npan\nzoom\nhorizontal plane\nselect body (right: look at)\nmove selected body\n"
    "rotate selected body\nhand back to script\ndeselect\npause\nslower / faster\nnext camera\nhelp on/off";

}  // namespace

ViewerWindow::ViewerWindow(const mjModel* m, const ViewerOptions& options)
    : options_(options), show_help_(options.help) {
  setSpeed(options.speed);
  if (m == nullptr) throw std::invalid_argument("ViewerWindow: null model");
  camera_ = cameraByName(m, options.camera);  // InputError before opening anything
  nbody_ = m->nbody;

  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0')
    throw std::runtime_error(std::string(kNoDisplay) + " (DISPLAY is not set)");
  glfwSetErrorCallback(recordGlfwError);
  g_glfw_error.clear();
  if (glfwInit() != GLFW_TRUE)
    throw std::runtime_error(std::string(kNoDisplay) + " (cannot open display '" + display +
                             "': " + g_glfw_error + ")");
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_SAMPLES, options.fast ? 0 : 4);
  window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = g_glfw_error;
    glfwTerminate();
    throw std::runtime_error(std::string(kNoDisplay) + " (cannot create an OpenGL window: " + why + ")");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // frame() paces itself; no vsync wait inside the sim loop

  mjv_defaultOption(&option_);
  mjv_defaultScene(&scene_);
  mjr_defaultContext(&context_);
  mjv_makeScene(m, &scene_, kSceneMaxGeoms);
  mjr_makeContext(m, &context_, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_WINDOW, &context_);
  if (options.fast) {
    scene_.flags[mjRND_SHADOW] = 0;
    scene_.flags[mjRND_REFLECTION] = 0;
  }

  glfwSetWindowUserPointer(window_, this);
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int b, int a, int mods) {
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    self(w)->mouseButton(b, a == GLFW_PRESS, mods, x, y, glfwGetTime());
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) { self(w)->mouseMove(x, y); });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double yoff) { self(w)->onScroll(yoff); });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    self(w)->onKey(key, action, mods);
  });
  glfwMakeContextCurrent(nullptr);  // let an EGL recorder use this thread
}

ViewerWindow::~ViewerWindow() {
  glfwMakeContextCurrent(window_);
  mjr_freeContext(&context_);
  mjv_freeScene(&scene_);
  glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool ViewerWindow::frame(const mjModel* m, mjData* d, const std::string& state) {
  if (m == nullptr || d == nullptr) throw std::invalid_argument("ViewerWindow::frame: null model or data");
  if (m->nbody != nbody_) throw std::invalid_argument("ViewerWindow::frame: not the model the viewer was built for");
  if (glfwWindowShouldClose(window_)) return false;
  m_ = m;
  d_ = d;
  drag_.apply(m, d);

  const auto frame_period = std::chrono::duration<double>(1.0 / options_.max_fps);
  auto now = Clock::now();
  if (now - last_draw_ >= frame_period) {
    glfwPollEvents();
    drag_.apply(m, d);
    draw(m, d, state);
    fps_estimate_ = 1.0 / std::max(1e-6, std::chrono::duration<double>(now - last_draw_).count());
    last_draw_ = now;
  }

  // paused: keep drawing and handling the mouse (the hand can still be
  // placed), refreshing kinematics so the dragged body is seen where it is
  if (paused_) {
    while (paused_ && !glfwWindowShouldClose(window_)) {
      glfwWaitEventsTimeout(frame_period.count());
      drag_.apply(m, d);
      mj_kinematics(m, d);
      mj_comPos(m, d);
      mj_camlight(m, d);
      draw(m, d, state);
    }
    have_anchor_ = false;
  }

  // real-time pacing: sleep while simulated time is ahead of the wall clock
  if (options_.realtime) {
    now = Clock::now();
    if (!have_anchor_) {
      have_anchor_ = true;
      wall_anchor_ = now;
      sim_anchor_ = d->time;
    }
    const double ahead = (d->time - sim_anchor_) / speed_ - std::chrono::duration<double>(now - wall_anchor_).count();
    if (ahead > 0.002) {
      std::this_thread::sleep_for(std::chrono::duration<double>(std::min(ahead, 0.5)));
    } else if (ahead < -0.25) {
      have_anchor_ = false;  // slower than real time: do not try to catch up later
    }
  }
  return !glfwWindowShouldClose(window_);
}

void ViewerWindow::draw(const mjModel* m, mjData* d, const std::string& state) {
  glfwMakeContextCurrent(window_);
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  const mjrRect viewport = {0, 0, width, height};
  mjv_updateScene(m, d, &option_, &drag_.perturb(), &camera_, mjCAT_ALL, &scene_);
  mjr_render(viewport, &scene_, &context_);

  char speed[32];
  if (options_.realtime) std::snprintf(speed, sizeof speed, "%gx", speed_);
  else std::snprintf(speed, sizeof speed, "max");
  char values[256];
  const int body = drag_.selected();
  const char* body_name = body > 0 ? mj_id2name(m, mjOBJ_BODY, body) : nullptr;
  const auto& held = drag_.held();
  std::snprintf(values, sizeof values, "%.3f s\n%s\n%s%s\n%s\n%.0f", d->time,
                state.empty() ? "-" : state.c_str(),
                body > 0 ? (body_name ? body_name : "(unnamed)") : "none",
                held ? (held->dragging ? " (dragging)" : " (held, backspace: release)") : "",
                speed, fps_estimate_);
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport, "time\nstate\nselected\nspeed\nfps", values,
              &context_);
  if (paused_) mjr_overlay(mjFONT_BIG, mjGRID_TOPRIGHT, viewport, "PAUSED", nullptr, &context_);
  if (show_help_) mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, viewport, kHelpKeys, kHelpActions, &context_);
  glfwSwapBuffers(window_);
  glfwMakeContextCurrent(nullptr);
}

void ViewerWindow::setSpeed(double speed) {
  speed_ = std::min(16.0, std::max(1.0 / 16.0, std::isfinite(speed) ? speed : 1.0));
  have_anchor_ = false;  // pace from now on at the new speed
}

void ViewerWindow::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

int ViewerWindow::selectAt(const mjModel* m, mjData* d, double relx, double rely) {
  int width = 0, height = 0;
  glfwGetWindowSize(window_, &width, &height);
  if (width <= 0 || height <= 0) return -1;
  // the scene must describe the current state for the ray test
  mjv_updateScene(m, d, &option_, &drag_.perturb(), &camera_, mjCAT_ALL, &scene_);
  mjtNum point[3];
  int geom = -1, skin = -1;
  const int body = mjv_select(m, d, &option_, static_cast<mjtNum>(width) / height, relx, rely,
                              &scene_, point, &geom, &skin);
  if (body > 0) {
    drag_.select(m, d, body, point);
    return body;
  }
  drag_.select(m, d, 0);
  return -1;
}

void ViewerWindow::mouseButton(int button, bool pressed, int mods, double x, double y, double time) {
  if (m_ == nullptr || d_ == nullptr) return;
  bool* state = button == GLFW_MOUSE_BUTTON_LEFT    ? &left_
                : button == GLFW_MOUSE_BUTTON_RIGHT ? &right_
                : button == GLFW_MOUSE_BUTTON_MIDDLE ? &middle_
                                                     : nullptr;
  if (state != nullptr) *state = pressed;
  shift_ = (mods & GLFW_MOD_SHIFT) != 0;
  ctrl_ = (mods & GLFW_MOD_CONTROL) != 0;
  last_x_ = x;
  last_y_ = y;

  if (!pressed) {
    if (!left_ && !right_ && drag_.active()) {
      drag_.end(m_, d_);
      notifyDrag();
    }
    return;
  }
  if (button == last_click_button_ && time - last_click_time_ < kDoubleClickSeconds) {
    last_click_time_ = -1;
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    const double relx = x / std::max(1, width), rely = (height - y) / std::max(1, height);
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
      selectAt(m_, d_, relx, rely);
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
      mjtNum point[3];
      int geom = -1, skin = -1;
      if (mjv_select(m_, d_, &option_, static_cast<mjtNum>(width) / std::max(1, height), relx, rely,
                     &scene_, point, &geom, &skin) >= 0) {
        toFreeCamera();
        mju_copy3(camera_.lookat, point);
      }
    }
    return;
  }
  last_click_time_ = time;
  last_click_button_ = button;
  if (ctrl_ && drag_.selected() > 0 &&
      (button == GLFW_MOUSE_BUTTON_LEFT || button == GLFW_MOUSE_BUTTON_RIGHT)) {
    drag_.begin(m_, d_, &scene_, button == GLFW_MOUSE_BUTTON_RIGHT ? mjPERT_TRANSLATE : mjPERT_ROTATE);
    notifyDrag();
  }
}

void ViewerWindow::mouseMove(double x, double y) {
  const double dx = x - last_x_, dy = y - last_y_;
  last_x_ = x;
  last_y_ = y;
  if (m_ == nullptr || d_ == nullptr || (!left_ && !right_ && !middle_)) return;
  int width = 0, height = 0;
  glfwGetWindowSize(window_, &width, &height);
  if (height <= 0) return;
  const int action = right_ ? (shift_ ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V)
                   : left_  ? (shift_ ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V)
                            : mjMOUSE_ZOOM;
  if (drag_.active()) {
    drag_.move(m_, d_, &scene_, action, dx / height, dy / height);
    notifyDrag();
    return;
  }
  toFreeCamera();
  mjv_moveCamera(m_, action, dx / height, dy / height, &scene_, &camera_);
}

void ViewerWindow::onScroll(double yoffset) {
  if (m_ == nullptr) return;
  toFreeCamera();
  mjv_moveCamera(m_, mjMOUSE_ZOOM, 0, -0.05 * yoffset, &scene_, &camera_);
}

void ViewerWindow::onKey(int key, int action, int mods) {
  shift_ = (mods & GLFW_MOD_SHIFT) != 0;
  ctrl_ = (mods & GLFW_MOD_CONTROL) != 0;
  if (action != GLFW_PRESS || m_ == nullptr || d_ == nullptr) return;
  switch (key) {
    case GLFW_KEY_SPACE: paused_ = !paused_; break;
    case GLFW_KEY_BACKSPACE: drag_.releaseHeld(); break;
    case GLFW_KEY_ESCAPE: drag_.select(m_, d_, 0); break;
    case GLFW_KEY_F1: show_help_ = !show_help_; break;
    case GLFW_KEY_TAB: nextCamera(m_); break;
    case GLFW_KEY_LEFT_BRACKET: setSpeed(speed_ / 2); break;
    case GLFW_KEY_RIGHT_BRACKET: setSpeed(speed_ * 2); break;
    default: break;
  }
}

void ViewerWindow::nextCamera(const mjModel* m) {
  if (camera_.type == mjCAMERA_FIXED && camera_.fixedcamid + 1 < m->ncam) {
    ++camera_.fixedcamid;
    return;
  }
  if (camera_.type == mjCAMERA_FREE && m->ncam > 0) {
    camera_.type = mjCAMERA_FIXED;
    camera_.fixedcamid = 0;
    return;
  }
  if (camera_.type == mjCAMERA_FIXED) toFreeCamera();
  else camera_ = workspaceCamera();
}

void ViewerWindow::toFreeCamera() {
  if (camera_.type == mjCAMERA_FREE) return;
  // a free camera that sees what the fixed one showed (its last GL pose)
  const mjvGLCamera& gl = scene_.camera[0];
  mjvCamera free_cam = workspaceCamera();
  const double distance = free_cam.distance;
  for (int i = 0; i < 3; ++i) free_cam.lookat[i] = gl.pos[i] + distance * gl.forward[i];
  free_cam.azimuth = std::atan2(gl.forward[1], gl.forward[0]) * 180.0 / M_PI;
  free_cam.elevation = std::asin(std::max(-1.0f, std::min(1.0f, gl.forward[2]))) * 180.0 / M_PI;
  camera_ = free_cam;
}

void ViewerWindow::notifyDrag() {
  if (on_drag_ && drag_.held()) on_drag_(*drag_.held());
}

}  // namespace handover::render
