#include "scenes/sim/sim_options.hpp"

#include <cmath>
#include <sstream>

#include "config/input_error.hpp"

namespace handover::sim {
namespace {

void requirePositive(double value, const std::string& key) {
  if (!std::isfinite(value) || value <= 0.0) {
    std::ostringstream msg;
    msg << "simulation option " << key << " = " << value << ": must be a positive number";
    throw InputError(msg.str());
  }
}

}  // namespace

ObjectShape parseObjectShape(const std::string& text, const std::string& key) {
  if (text == "cylinder") return ObjectShape::Cylinder;
  if (text == "box") return ObjectShape::Box;
  if (text == "sphere") return ObjectShape::Sphere;
  throw InputError(key + ": unknown object shape '" + text + "' (expected cylinder, box or sphere)");
}

const char* toString(ObjectShape shape) {
  switch (shape) {
    case ObjectShape::Cylinder: return "cylinder";
    case ObjectShape::Box: return "box";
    case ObjectShape::Sphere: return "sphere";
  }
  return "?";
}

std::string defaultScenePath() { return std::string(HANDOVER_SOURCE_DIR) + "/scenes/handover_scene.xml"; }

void validate(const SimOptions& options) {
  const ObjectOptions& o = options.object;
  const std::size_t expected = o.shape == ObjectShape::Cylinder ? 2 : o.shape == ObjectShape::Box ? 3 : 1;
  if (o.size.size() != expected) {
    std::ostringstream msg;
    msg << "simulation option object.size: a " << toString(o.shape) << " needs " << expected
        << " numbers (" << (expected == 2 ? "[radius, height]" : expected == 3 ? "[x, y, z] edges" : "[radius]")
        << "), got " << o.size.size();
    throw InputError(msg.str());
  }
  for (std::size_t i = 0; i < o.size.size(); ++i) requirePositive(o.size[i], "object.size[" + std::to_string(i) + "]");
  requirePositive(o.mass, "object.mass");
  requirePositive(o.friction, "object.friction");
  requirePositive(options.human.height, "human.height");
  requirePositive(options.human.upper_arm_length, "human.upper_arm_length");
  requirePositive(options.human.forearm_length, "human.forearm_length");
}

}  // namespace handover::sim
