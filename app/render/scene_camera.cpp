#include "app/render/scene_camera.hpp"

#include "config/input_error.hpp"

namespace handover::render {

mjvCamera workspaceCamera() {
  mjvCamera cam;
  mjv_defaultCamera(&cam);
  cam.type = mjCAMERA_FREE;
  cam.lookat[0] = 0.5;   // between the robot base and the person
  cam.lookat[1] = 0.0;
  cam.lookat[2] = 0.25;  // about handover height above the table top
  cam.distance = 2.4;
  cam.azimuth = 90.0;    // looking along +y: world x points to the right
  cam.elevation = -20.0;
  return cam;
}

mjvCamera cameraByName(const mjModel* m, const std::string& name, std::string* note) {
  const int id = name.empty() ? -1 : mj_name2id(m, mjOBJ_CAMERA, name.c_str());
  if (id >= 0) {
    mjvCamera cam;
    mjv_defaultCamera(&cam);
    cam.type = mjCAMERA_FIXED;
    cam.fixedcamid = id;
    if (note) *note = "camera '" + name + "'";
    return cam;
  }
  if (name.empty() || name == kOverviewCamera) {
    if (note)
      *note = name.empty() ? "free workspace camera"
                           : "free workspace camera (the model has no camera '" + name + "')";
    return workspaceCamera();
  }
  std::string known;
  for (int i = 0; i < m->ncam; ++i) {
    const char* n = mj_id2name(m, mjOBJ_CAMERA, i);
    known += (known.empty() ? "" : ", ") + std::string(n ? n : "(unnamed)");
  }
  throw InputError("unknown camera '" + name + "'; the model has: " +
                   (known.empty() ? std::string("no cameras") : known));
}

}  // namespace handover::render
