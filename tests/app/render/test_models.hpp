// Small MJCF models for the render tests: no dependency on the real scene.
#pragma once

#include <mujoco/mujoco.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

namespace handover::render::test {

// A red box 1 m in front of camera "front", a green mocap sphere "hand" to
// its right, a grey floor. offwidth/offheight are deliberately smaller than
// the test videos: the renderer must enlarge its offscreen buffer itself.
inline const char* kBoxSceneXml = R"(
<mujoco>
  <visual><global offwidth="64" offheight="64"/></visual>
  <worldbody>
    <light pos="0 -1 3" dir="0 0.3 -1" directional="true"/>
    <geom name="floor" type="plane" size="3 3 0.1" rgba="0.3 0.3 0.3 1"/>
    <camera name="front" pos="0 -1 0.3" xyaxes="1 0 0 0 0 1" fovy="45"/>
    <body name="box" pos="0 0 0.3">
      <geom type="box" size="0.15 0.15 0.15" rgba="1 0 0 1"/>
    </body>
    <body name="hand" mocap="true" pos="0.35 0 0.3">
      <geom type="sphere" size="0.05" pos="0.02 0 0" rgba="0 1 0 1" contype="0" conaffinity="0"/>
    </body>
    <body name="ball" pos="-0.4 0 0.3">
      <freejoint/>
      <geom type="sphere" size="0.05" rgba="0 0 1 1"/>
    </body>
  </worldbody>
</mujoco>
)";

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

inline ModelPtr loadXmlString(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();  // large struct: keep it off the stack
  mj_defaultVFS(vfs.get());
  mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(xml.size()));
  const int i = mj_findFileVFS(vfs.get(), "model.xml");
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[i]));
  char err[1000] = "";
  mjModel* m = mj_loadXML("model.xml", vfs.get(), err, sizeof err);
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw std::runtime_error(std::string("test model: ") + err);
  return ModelPtr(m);
}

}  // namespace handover::render::test
