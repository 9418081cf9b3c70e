// Dragging a body with the mouse through MuJoCo's perturbation (mjvPerturb):
// a mocap body (the person's hand) follows the mouse exactly; any other body
// is pulled by a spring force (xfrc_applied), as in MuJoCo's own viewer.
#pragma once

#include <mujoco/mujoco.h>

#include <optional>
#include <string>

namespace handover::render {

/// A pose the user gave a mocap body (world frame).
struct DraggedPose {
  int body = -1;                     ///< body id
  int mocap = -1;                    ///< index into d->mocap_pos / mocap_quat
  std::string name;                  ///< body name ("human_hand", ...)
  mjtNum pos[3] = {0, 0, 0};         ///< m, body origin in the world
  mjtNum quat[4] = {1, 0, 0, 0};     ///< unit quaternion (w, x, y, z), body to world
  bool dragging = false;             ///< the mouse button is still down
};

/// Selection and perturbation state, independent of any window (the mjv_
/// calls are CPU-only), so it is tested without a display. Not real-time
/// safe in select()/begin() (string copy); move()/apply() do not allocate.
class BodyDrag {
 public:
  BodyDrag();

  /// Selects `body` (> 0), grabbed at world point `grab_point` (m; nullptr =
  /// the body origin). body <= 0 clears the selection. Needs d's kinematics.
  void select(const mjModel* m, mjData* d, int body, const mjtNum grab_point[3] = nullptr);
  int selected() const { return perturb_.select; }

  /// Starts a drag of the selected body: mjPERT_TRANSLATE or mjPERT_ROTATE.
  /// `scene` gives the camera that scales mouse motion. False if nothing is selected.
  bool begin(const mjModel* m, const mjData* d, const mjvScene* scene, int pert_bit);
  /// Mouse motion during a drag; `action` is an mjtMouse (MOVE_V/H, ROTATE_V/H),
  /// reldx/reldy are the motion divided by the viewport height.
  void move(const mjModel* m, const mjData* d, const mjvScene* scene, int action,
            mjtNum reldx, mjtNum reldy);
  /// Ends the drag; a mocap body keeps its last pose (see held()), a force
  /// on a dynamic body is removed.
  void end(const mjModel* m, mjData* d);
  bool active() const { return perturb_.active != 0; }

  /// Writes the current drag into d: the held mocap pose into
  /// d->mocap_pos/quat, or the spring force into d->xfrc_applied.
  void apply(const mjModel* m, mjData* d);

  /// The pose the user gave a mocap body, kept after the button is released
  /// until releaseHeld(): the caller (the scripted person) should use it
  /// instead of its script while it is set.
  const std::optional<DraggedPose>& held() const { return held_; }
  /// Gives the body back to its script.
  void releaseHeld() { held_.reset(); }

  const mjvPerturb& perturb() const { return perturb_; }

 private:
  void clearForce(const mjModel* m, mjData* d);

  mjvPerturb perturb_;
  int force_body_ = -1;           // body whose xfrc_applied we wrote
  mjtNum ref_to_body_pos_[3];     // body origin in the perturbation frame at begin()
  mjtNum ref_to_body_quat_[4];    // body orientation in the perturbation frame
  std::optional<DraggedPose> held_;
};

}  // namespace handover::render
