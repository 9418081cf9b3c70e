// Test helper: scenes/panda.xml (or another MJCF file) loaded in MuJoCo, with
// the arm set to (q, v) and both fingers to half the model's opening.
#pragma once

#include <mujoco/mujoco.h>

#include <stdexcept>
#include <string>

#include "control/model/model.hpp"

namespace handover::control::test {

inline std::string sourcePath(const std::string& rel) { return std::string(HANDOVER_SOURCE_DIR) + "/" + rel; }

class MujocoOracle {
 public:
  explicit MujocoOracle(const std::string& mjcf_path) {
    char err[1000] = "";
    m = mj_loadXML(mjcf_path.c_str(), nullptr, err, sizeof(err));
    if (m == nullptr) throw std::runtime_error("MuJoCo could not load " + mjcf_path + ": " + err);
    d = mj_makeData(m);
  }
  ~MujocoOracle() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  MujocoOracle(const MujocoOracle&) = delete;
  MujocoOracle& operator=(const MujocoOracle&) = delete;

  int id(mjtObj type, const std::string& name) const {
    const int i = mj_name2id(m, type, name.c_str());
    if (i < 0) throw std::runtime_error("MuJoCo model has no object named " + name);
    return i;
  }
  int qposOf(const std::string& joint) const { return m->jnt_qposadr[id(mjOBJ_JOINT, joint)]; }
  int dofOf(const std::string& joint) const { return m->jnt_dofadr[id(mjOBJ_JOINT, joint)]; }

  /// Arm joints (by the model's joint names) at q, v; fingers still at opening / 2.
  void set(const Model& model, const Vector7& q, const Vector7& v) {
    mj_resetData(m, d);
    for (int i = 0; i < kArmDofs; ++i) {
      d->qpos[qposOf(model.joint_names[i])] = q[i];
      d->qvel[dofOf(model.joint_names[i])] = v[i];
    }
    d->qpos[qposOf("panda_finger_joint1")] = 0.5 * model.finger_opening;
    d->qpos[qposOf("panda_finger_joint2")] = 0.5 * model.finger_opening;
    mj_forward(m, d);
  }

  Isometry bodyPose(const std::string& body) const { return pose(d->xpos + 3 * id(mjOBJ_BODY, body), d->xmat + 9 * id(mjOBJ_BODY, body)); }
  Isometry sitePose(const std::string& site) const { return pose(d->site_xpos + 3 * id(mjOBJ_SITE, site), d->site_xmat + 9 * id(mjOBJ_SITE, site)); }

  static Isometry pose(const mjtNum* p, const mjtNum* R) {
    Isometry X = Isometry::Identity();
    for (int r = 0; r < 3; ++r) {
      X.translation()[r] = p[r];
      for (int c = 0; c < 3; ++c) X.linear()(r, c) = R[3 * r + c];
    }
    return X;
  }

  mjModel* m = nullptr;
  mjData* d = nullptr;
};

}  // namespace handover::control::test
