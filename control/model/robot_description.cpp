#include "control/model/robot_description.hpp"

#include <filesystem>

#include "config/yaml_reader.hpp"
#include "config/config_directory.hpp"

namespace handover::control {

namespace {

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string nonEmpty(const YamlReader& r, const std::string& key) {
  const YamlReader c = r.child(key);
  std::string s = c.asString();
  if (s.empty()) c.fail("expected a non-empty name");
  return s;
}

std::vector<std::string> names(const YamlReader& r, const std::string& key) {
  const YamlReader c = r.child(key);
  if (!c.isSequence()) c.fail("expected a list of names");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < c.size(); ++i) out.push_back(c.at(i).asString());
  return out;
}

}  // namespace

RobotDescription loadRobotDescription(const std::string& path) {
  const YamlReader root = YamlReader::loadFile(path);
  if (!root.isMap()) root.fail("expected a map (the robot description)");
  RobotDescription d;
  d.file = path;
  d.urdf = nonEmpty(root, "urdf");
  if (d.urdf.front() != '/') {
    // relative to this file; a copy of config/ elsewhere (--config-dir) that does not
    // hold the URDF's folder still means the shipped one, relative to the source tree's config/
    const std::string near = folderOf(path) + d.urdf;
    const std::string shipped = std::string(HANDOVER_SOURCE_DIR) + "/config/" + d.urdf;
    d.urdf = !std::filesystem::exists(near) && std::filesystem::exists(shipped) ? shipped : near;
  }
  d.base_link = nonEmpty(root, "base_link");
  const YamlReader frames = root.child("frames");
  d.hand_link = nonEmpty(frames, "hand");
  d.tcp_link = nonEmpty(frames, "tcp");
  d.ft_sensor_link = nonEmpty(frames, "ft_sensor");
  frames.finish();
  d.capsule_prefix = root.child("capsule_prefix").asString();
  const YamlReader acc = root.child("acceleration_limits");
  d.acceleration_limits = acc.asVector(kArmDofs);
  for (int i = 0; i < kArmDofs; ++i) acc.at(i).checkRange(d.acceleration_limits[i], 1e-3, 1e4);
  const YamlReader gripper = root.child("gripper");
  d.gripper_links = names(gripper, "links");
  {
    const YamlReader fingers = gripper.child("fingers");
    const std::vector<std::string> f = names(gripper, "fingers");
    if (f.size() != 2) fingers.fail("expected two finger links, left then right");
    for (std::size_t i = 0; i < 2; ++i) {
      bool listed = false;
      for (const std::string& l : d.gripper_links) listed = listed || l == f[i];
      if (f[i].empty() || !listed) fingers.at(i).fail("expected one of gripper.links, got '" + f[i] + "'");
      d.finger_links[i] = f[i];
    }
  }
  d.fingertip_capsules = names(gripper, "fingertip_capsules");
  gripper.finish();
  const YamlReader groups = root.child("link_groups");
  if (!groups.isMap()) groups.fail("expected a map of group names to lists of link names or patterns");
  for (const std::string& name : groups.keys()) {
    const YamlReader g = groups.child(name);
    LinkGroup group{name, names(groups, name)};
    if (group.patterns.empty()) g.fail("expected at least one link name or pattern");
    for (std::size_t i = 0; i < group.patterns.size(); ++i)
      if (group.patterns[i].empty()) g.at(i).fail("expected a non-empty name");
    d.link_groups.push_back(std::move(group));
  }
  root.finish();
  return d;
}

std::string defaultRobotDescriptionPath() {
  return configFile("robot.yaml");
}

RobotDescription defaultRobotDescription() { return loadRobotDescription(defaultRobotDescriptionPath()); }

}  // namespace handover::control
