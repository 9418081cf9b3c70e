// The Panda model of scenes/panda.urdf, loaded once per test process.
#pragma once

#include <string>

#include "control/model/model.hpp"

namespace handover::test {

inline const control::Model& panda() {
  static const control::Model model = control::loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return model;
}

}  // namespace handover::test
