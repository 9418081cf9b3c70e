// `--view`: a GLFW window showing the simulation, in which the user can
// orbit the camera and drag the person's hand (a mocap body) with the mouse.
#pragma once

#include <mujoco/mujoco.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "app/render/body_drag.hpp"

struct GLFWwindow;

namespace handover::render {

struct ViewerOptions {
  std::string title = "Handover";
  int width = 1280;                    ///< window size, screen px
  int height = 800;
  std::string camera = "overview";     ///< start camera, see cameraByName()
  double max_fps = 60.0;               ///< frames drawn per wall-clock second at most
  bool realtime = true;                ///< frame() sleeps so simulated time does not outrun the wall clock
  double speed = 1.0;                  ///< with realtime: simulated s per wall s ('[' / ']' halve / double it)
  bool fast = true;                    ///< shadows and reflections off (software GL under Xvfb)
  bool help = true;                    ///< show the mouse/key help at start (F1 toggles)
};

/// Mouse and keys (also shown in the window, F1):
///   left drag: orbit, right drag: pan, scroll / middle drag: zoom
///   (shift: the horizontal plane); double-click: select a body;
///   ctrl + right drag: move the selected body; ctrl + left drag: rotate it;
///   backspace: give a dragged mocap body back to its script; esc: deselect;
///   space: pause; [ / ]: slower / faster; tab: next camera; F1: help.
///
/// Runs inside the caller's simulation loop; call frame() every step (it only
/// draws when a frame is due). One viewer per process; not thread safe and
/// not real-time safe. After frame() returns no GL context is current, so an
/// EGL VideoRecorder can render on the same thread.
class ViewerWindow {
 public:
  /// Throws std::runtime_error("--view needs a display; use --video for
  /// headless runs ...") without a display, handover::InputError for an
  /// unknown camera name.
  ViewerWindow(const mjModel* m, const ViewerOptions& options = {});
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  /// Polls events and, at most max_fps times per second, draws the state in
  /// `d` with an overlay (time, `state`, help). Applies the user's drag to d
  /// (mocap pose / perturbation force). Blocks while paused. With realtime,
  /// sleeps until wall time catches up with d->time. Returns false once the
  /// window is closed. m must be the model given at construction.
  bool frame(const mjModel* m, mjData* d, const std::string& state = {});

  /// The pose the user dragged a mocap body to (held after the mouse is
  /// released, until backspace): while set, the caller should drive that
  /// body with it instead of its script. See BodyDrag::held().
  const std::optional<DraggedPose>& draggedPose() const { return drag_.held(); }
  /// Called whenever the user moves a mocap body (from inside frame()).
  void onDrag(std::function<void(const DraggedPose&)> callback) { on_drag_ = std::move(callback); }

  /// Asks the window to close, as the user's close button does.
  void requestClose();

  bool paused() const { return paused_; }
  double speed() const { return speed_; }
  void setSpeed(double speed);
  void setPaused(bool paused) { paused_ = paused; }

  // Programmatic access to what the mouse does (scripts, tests).
  /// Selects the body under the window point (relx, rely in [0, 1], origin
  /// bottom left) with mjv_select; returns its id or -1.
  int selectAt(const mjModel* m, mjData* d, double relx, double rely);
  /// Feeds a mouse event as the window reports it: x, y in window
  /// coordinates (origin top left), `mods` GLFW_MOD_* bits, `time` in s (for
  /// double-clicks). The GLFW callbacks call these; tests and demos may too.
  /// Acts on the model/data of the last frame() call (no-op before it).
  void mouseButton(int button, bool pressed, int mods, double x, double y, double time);
  void mouseMove(double x, double y);
  BodyDrag& drag() { return drag_; }
  const mjvScene& scene() const { return scene_; }
  mjvCamera& camera() { return camera_; }

 private:
  void onScroll(double yoffset);
  void onKey(int key, int action, int mods);
  void draw(const mjModel* m, mjData* d, const std::string& state);
  void nextCamera(const mjModel* m);
  void toFreeCamera();
  void notifyDrag();

  ViewerOptions options_;
  GLFWwindow* window_ = nullptr;
  int nbody_ = 0;
  mjvCamera camera_;
  mjvOption option_;
  mjvScene scene_;
  mjrContext context_;
  BodyDrag drag_;
  std::function<void(const DraggedPose&)> on_drag_;

  // the model/data of the current frame() call, for the event callbacks
  const mjModel* m_ = nullptr;
  mjData* d_ = nullptr;

  // mouse state
  bool left_ = false, right_ = false, middle_ = false;
  bool shift_ = false, ctrl_ = false;
  double last_x_ = 0, last_y_ = 0;
  double last_click_time_ = -1;
  int last_click_button_ = -1;

  bool paused_ = false;
  double speed_ = 1.0;
  bool show_help_ = true;
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_draw_{};
  bool have_anchor_ = false;          // realtime pacing: wall time <-> sim time
  Clock::time_point wall_anchor_{};
  double sim_anchor_ = 0.0;
  double fps_estimate_ = 0.0;
};

}  // namespace handover::render
