// Model lookups and Data sizing.
#include "control/model/model.hpp"

#include <stdexcept>

namespace handover::control {

int Model::frameId(const std::string& name) const {
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].name == name) return static_cast<int>(i);
  }
  throw std::out_of_range("control::Model: no frame named '" + name + "' (loaded from " + urdf_path + ")");
}

bool Model::hasFrame(const std::string& name) const {
  for (const Frame& f : frames) {
    if (f.name == name) return true;
  }
  return false;
}

Data::Data(const Model& model) {
  for (auto& X : oMb) X.setIdentity();
  for (auto& J : body_jacobian) J.setZero();
  for (auto& v : body_velocity) v.setZero();
  for (auto& a : body_drift) a.setZero();
  for (auto& s : scratch_v) s.setZero();
  for (auto& s : scratch_a) s.setZero();
  for (auto& s : scratch_f) s.setZero();
  for (auto& s : scratch_I) s.setZero();
  for (auto& c : com_world) c.setZero();
  for (auto& I : inertia_world) I.setZero();
  body7_with_payload = model.inertias[kArmDofs];
  has_payload = false;
}

}  // namespace handover::control
