#include "scenes/sim/scene_builder.hpp"

#include <cctype>
#include <cstddef>
#include <sstream>
#include <vector>

#include "config/input_error.hpp"
#include "scenes/scenario/body_dimensions.hpp"

namespace handover::sim {
namespace {

bool insideComment(const std::string& xml, std::size_t pos) {
  const std::size_t open = xml.rfind("<!--", pos);
  if (open == std::string::npos) return false;
  const std::size_t close = xml.find("-->", open);
  return close == std::string::npos || close > pos;
}

std::string joinNumbers(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(12);
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << values[i];
  return out.str();
}

}  // namespace

bool setElementAttribute(std::string& xml, const std::string& element_name,
                         const std::string& attr, const std::string& value) {
  const std::string needle = "name=\"" + element_name + "\"";
  std::size_t pos = xml.find(needle);
  // a real name attribute: preceded by whitespace and not inside a comment
  while (pos != std::string::npos &&
         (pos == 0 || !std::isspace(static_cast<unsigned char>(xml[pos - 1])) ||
          insideComment(xml, pos))) {
    pos = xml.find(needle, pos + 1);
  }
  if (pos == std::string::npos) return false;
  const std::size_t tag_begin = xml.rfind('<', pos);
  const std::size_t tag_end = xml.find('>', pos);
  if (tag_begin == std::string::npos || tag_end == std::string::npos) return false;

  // look for ` attr="` inside this tag only
  const std::string key = attr + "=\"";
  std::size_t a = xml.find(key, tag_begin);
  while (a != std::string::npos && a < tag_end &&
         !std::isspace(static_cast<unsigned char>(xml[a - 1]))) {
    a = xml.find(key, a + 1);
  }
  if (a != std::string::npos && a < tag_end) {
    const std::size_t v0 = a + key.size();
    const std::size_t v1 = xml.find('"', v0);
    xml.replace(v0, v1 - v0, value);
  } else {
    const std::size_t insert_at = (xml[tag_end - 1] == '/') ? tag_end - 1 : tag_end;
    xml.insert(insert_at, " " + attr + "=\"" + value + "\"");
  }
  return true;
}

std::string buildSceneXml(const std::string& template_text, const SimOptions& options,
                          const std::string& source_name) {
  validate(options);
  std::string xml = template_text;
  auto set = [&](const std::string& element, const std::string& attr, const std::vector<double>& v) {
    if (!setElementAttribute(xml, element, attr, joinNumbers(v))) {
      throw InputError("scene " + source_name + ": no element named '" + element +
                       "' (the simulator sizes it from the load options; see docs/simulation.md)");
    }
  };
  auto setText = [&](const std::string& element, const std::string& attr, const std::string& v) {
    if (!setElementAttribute(xml, element, attr, v)) {
      throw InputError("scene " + source_name + ": no element named '" + element + "'");
    }
  };

  // object: scenario sizes are full extents, MuJoCo wants half-sizes
  const ObjectOptions& o = options.object;
  double half_height = 0.0;
  switch (o.shape) {
    case ObjectShape::Cylinder:
      set("object_geom", "size", {o.size[0], 0.5 * o.size[1]});
      half_height = 0.5 * o.size[1];
      break;
    case ObjectShape::Box:
      set("object_geom", "size", {0.5 * o.size[0], 0.5 * o.size[1], 0.5 * o.size[2]});
      half_height = 0.5 * o.size[2];
      break;
    case ObjectShape::Sphere:
      set("object_geom", "size", {o.size[0]});
      half_height = o.size[0];
      break;
  }
  setText("object_geom", "type", toString(o.shape));
  set("object_geom", "mass", {o.mass});
  set("object_geom", "friction", {o.friction, 0.02, 0.0001});
  // at rest on the table, beside the robot, until placed
  set("object", "pos", {0.45, 0.3, half_height});

  // person: proportions of stature (scenario/body_dimensions.hpp; the
  // controller's collision model sizes the same trunk from the same numbers)
  const HumanOptions& h = options.human;
  const scenario::BodyDimensions body = scenario::bodyDimensionsFromHeight(h.height);
  const double hip = body.hip_height, shoulder = body.torso_top;
  set("human_legs_geom", "size", {0.5 * body.legs_depth, 0.5 * body.legs_width, 0.5 * hip});
  set("human_legs_geom", "pos", {0.0, 0.0, 0.5 * hip});
  set("human_torso_geom", "size", {0.5 * body.torso_depth, 0.5 * body.torso_width, 0.5 * (shoulder - hip)});
  set("human_torso_geom", "pos", {0.0, 0.0, 0.5 * (shoulder + hip)});
  set("human_head_geom", "size", {body.head_radius});
  set("human_head_geom", "pos", {0.0, 0.0, body.head_centre});
  // the other arm hangs beside the torso (body_dimensions.hpp freeArmInTorso)
  const scenario::HangingArm free_arm = scenario::freeArmInTorso(body, h.hand);
  auto vertical = [&](const std::string& geom, const Eigen::Vector3d& top, const Eigen::Vector3d& bottom, double r) {
    const Eigen::Vector3d c = 0.5 * (top + bottom);
    set(geom, "pos", {c.x(), c.y(), c.z()});
    set(geom, "size", {r, 0.5 * (top - bottom).norm()});
  };
  vertical("human_free_upper_arm_geom", free_arm.shoulder, free_arm.elbow, body.upper_arm_radius);
  vertical("human_free_forearm_geom", free_arm.elbow, free_arm.tip, body.forearm_radius);
  set("human_upper_arm_geom", "size", {0.045, 0.5 * h.upper_arm_length});
  set("human_upper_arm_geom", "pos", {0.0, 0.0, 0.5 * h.upper_arm_length});
  set("human_forearm_geom", "size", {0.035, 0.5 * h.forearm_length});
  set("human_forearm_geom", "pos", {0.0, 0.0, 0.5 * h.forearm_length});
  return xml;
}

}  // namespace handover::sim
