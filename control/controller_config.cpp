#include "control/controller_config.hpp"

#include <cmath>

#include "control/controller_config_bounds.hpp"
#include "config/config_directory.hpp"

namespace handover::control {

namespace {

// damping: a number, or "auto" for critical damping 2 sqrt(stiffness)
PdGains readGains(const YamlReader& r, const PdGains& def) {
  PdGains g = def;
  bool auto_damping = true;
  if (auto c = r.optionalChild("stiffness")) g.stiffness = c->checkRange(c->asDouble(), 1e-9, 1e7);
  if (auto c = r.optionalChild("damping")) {
    if (c->node().IsScalar() && c->node().Scalar() == "auto") {
      auto_damping = true;
    } else {
      g.damping = c->checkRange(c->asDouble(), 0.0, 1e5);
      auto_damping = false;
    }
  }
  if (auto_damping) g.damping = 2.0 * std::sqrt(g.stiffness);
  return g;
}

Vector3 readWeights(const YamlReader& r, const Vector3& def) {
  auto c = r.optionalChild("weights");
  if (!c) return def;
  const Eigen::VectorXd v = c->asVector(3);
  for (int i = 0; i < 3; ++i) c->at(i).checkRange(v[i], 0.0, 1e9);
  return v;
}

AxisGains readAxis(const YamlReader& parent, const char* key, const AxisGains& def) {
  auto r = parent.optionalChild(key);
  if (!r) return def;
  if (!r->isMap()) r->fail("expected a map with stiffness, damping, weights");
  AxisGains a;
  a.gains = readGains(*r, def.gains);
  a.weights = readWeights(*r, def.weights);
  r->finish();
  return a;
}

double readWeight(const YamlReader& r, double def) {
  auto c = r.optionalChild("weight");
  return c ? c->checkRange(c->asDouble(), 0.0, 1e12) : def;
}

// `tasks:` / `constraints:`: a list of {name, type, enabled?, parameters...}
std::vector<ElementEntry> readEntries(const YamlReader& list, const char* what) {
  if (!list.isSequence() || list.size() == 0 || list.size() > 16)
    list.fail(std::string("expected a list of 1 to 16 ") + what + " {name: ..., type: ..., enabled: true|false, <parameters>}");
  std::vector<ElementEntry> out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YamlReader r = list.at(i);
    if (!r.isMap()) r.fail(std::string("expected a map {name: ..., type: ...} (one of the ") + what + ")");
    ElementEntry e;
    const YamlReader name = r.child("name");
    e.name = name.asString();
    if (e.name.empty()) name.fail("expected a non-empty name");
    for (const ElementEntry& other : out)
      if (other.name == e.name) name.fail("duplicate name '" + e.name + "'");
    const YamlReader type = r.child("type");
    e.type = type.asString();
    if (e.type.empty()) type.fail("expected a non-empty type");
    e.enabled = r.getBool("enabled", true);
    e.node = std::make_shared<const YAML::Node>(r.node());
    e.file = r.file();
    e.path = r.path();
    out.push_back(std::move(e));  // the other keys: the type's parameters, checked when the controller is built
  }
  return out;
}

std::optional<YamlReader> section(const YamlReader& root, const char* key) {
  auto r = root.optionalChild(key);
  if (r && !r->isMap()) r->fail("expected a map");
  return r;
}

ElementEntry entry(const char* name, const char* type, bool enabled = true) {
  ElementEntry e;
  e.name = name;
  e.type = type;
  e.enabled = enabled;
  return e;
}

}  // namespace

std::vector<ElementEntry> defaultTaskEntries() {
  return {entry("observation", "observation"), entry("tracking", "trajectory_tracking"), entry("posture", "posture"),
          entry("pose", "pose", false)};
}

std::vector<ElementEntry> defaultConstraintEntries() {
  return {entry("joint_acceleration", "joint_acceleration_limit"), entry("joint_position", "joint_position_limit"),
          entry("joint_velocity", "joint_velocity_limit"), entry("gravity_hold", "gravity_hold_limit"),
          entry("joint_torque", "joint_torque_limit"), entry("collision", "collision")};
}

ControllerConfig parseControllerConfig(const YamlReader& root) { return parseControllerConfig(root, defaultJointLimits()); }

ControllerConfig parseControllerConfig(const YamlReader& root, const JointLimits& joints) {
  ControllerConfig cfg;
  if (root.isNull()) return cfg;  // empty file: all defaults
  if (!root.isMap()) root.fail("expected a map of controller settings");

  if (auto c = root.optionalChild("period")) cfg.period = c->checkRange(c->asDouble(), 1e-5, 0.1);
  if (auto c = root.optionalChild("frame")) cfg.frame = c->asString();
  if (auto c = root.optionalChild("tasks")) cfg.tasks = readEntries(*c, "tasks");
  if (auto c = root.optionalChild("constraints")) cfg.constraints = readEntries(*c, "constraints");

  if (auto s = section(root, "observation")) {
    cfg.observation.gains = readGains(*s, cfg.observation.gains);
    cfg.observation.weight = readWeight(*s, cfg.observation.weight);
    s->finish();
  }
  if (auto s = section(root, "tracking")) {
    cfg.tracking.weight = readWeight(*s, cfg.tracking.weight);
    cfg.tracking.translation = readAxis(*s, "translation", cfg.tracking.translation);
    cfg.tracking.orientation = readAxis(*s, "orientation", cfg.tracking.orientation);
    if (auto v = s->optionalChild("max_speed")) cfg.tracking.max_speed = v->checkRange(v->asDouble(), 0.0, 2.0);
    if (auto v = s->optionalChild("max_angular_speed"))
      cfg.tracking.max_angular_speed = v->checkRange(v->asDouble(), 0.0, 10.0);
    s->finish();
  }
  if (auto s = section(root, "posture")) {
    cfg.posture.gains = readGains(*s, cfg.posture.gains);
    cfg.posture.weight = readWeight(*s, cfg.posture.weight);
    if (auto t = s->optionalChild("target")) cfg.posture.target = t->asVector(kArmDofs);
    s->finish();
  }
  if (auto s = section(root, "pose_task")) {
    cfg.pose_task.weight = readWeight(*s, cfg.pose_task.weight);
    cfg.pose_task.translation = readAxis(*s, "translation", cfg.pose_task.translation);
    cfg.pose_task.orientation = readAxis(*s, "orientation", cfg.pose_task.orientation);
    s->finish();
  }
  if (auto s = section(root, "limits")) {
    if (auto p = section(*s, "position")) {
      auto& pp = cfg.limits.position;
      if (auto c = p->optionalChild("interaction")) pp.interaction = c->checkRange(c->asDouble(), 1e-6, 0.5);
      if (auto c = p->optionalChild("safety")) pp.safety = c->checkRange(c->asDouble(), 0.0, 0.5);
      if (auto c = p->optionalChild("damper_offset")) pp.damper_offset = c->checkRange(c->asDouble(), 0.0, 100.0);
      if (auto c = p->optionalChild("recovery_speed")) pp.recovery_speed = c->checkRange(c->asDouble(), 0.0, 10.0);
      if (pp.safety >= pp.interaction)
        p->fail("safety (" + std::to_string(pp.safety) + ") must be smaller than interaction (" +
                std::to_string(pp.interaction) + ")");
      p->finish();
    }
    if (auto v = section(*s, "velocity")) {
      if (auto c = v->optionalChild("scale")) cfg.limits.velocity_scale = c->checkRange(c->asDouble(), 1e-3, 1.0);
      if (auto c = v->optionalChild("braking")) cfg.limits.velocity_braking = c->checkRange(c->asDouble(), 0.0, 1.0);
      v->finish();
    }
    if (auto a = section(*s, "acceleration")) {
      if (auto c = a->optionalChild("scale")) cfg.limits.acceleration_scale = c->checkRange(c->asDouble(), 1e-3, 1.0);
      a->finish();
    }
    if (auto t = section(*s, "torque")) {
      if (auto c = t->optionalChild("scale")) cfg.limits.torque_scale = c->checkRange(c->asDouble(), 1e-3, 1.0);
      if (auto h = section(*t, "hold")) {
        auto& g = cfg.limits.gravity_hold;
        if (auto c = h->optionalChild("share")) g.share = c->checkRange(c->asDouble(), 0.05, 1.0);
        if (auto c = h->optionalChild("interaction")) g.interaction = c->checkRange(c->asDouble(), 0.01, 0.5);
        if (auto c = h->optionalChild("damper_offset")) g.damper_offset = c->checkRange(c->asDouble(), 0.0, 100.0);
        if (auto c = h->optionalChild("recovery")) g.recovery = c->checkRange(c->asDouble(), 0.0, 10.0);
        if (g.interaction >= g.share)
          h->fail("interaction (" + std::to_string(g.interaction) + ") must be smaller than share (" +
                  std::to_string(g.share) + ")");
        h->finish();
      }
      t->finish();
    }
    s->finish();
  }
  if (auto s = section(root, "qp")) {
    if (auto c = s->optionalChild("regularisation")) cfg.qp.regularisation = c->checkRange(c->asDouble(), 0.0, 1.0);
    if (auto c = s->optionalChild("max_iterations"))
      cfg.qp.max_iterations = static_cast<int>(c->checkRange(c->asInt(), 1, 100000));
    if (auto c = s->optionalChild("relax_soft_rows")) cfg.qp.relax_soft_rows = c->asBool();
    s->finish();
  }
  if (auto s = section(root, "contact_wrench")) cfg.contact_wrench = parseContactWrenchSettings(*s);
  if (auto s = section(root, "disturbance")) cfg.disturbance = parseDisturbanceSettings(*s);
  if (auto s = section(root, "fallback")) {
    if (auto c = s->optionalChild("damping")) cfg.fallback.damping = c->checkRange(c->asDouble(), 0.0, 1000.0);
    if (auto c = s->optionalChild("max_share")) cfg.fallback.max_share = c->checkRange(c->asDouble(), 0.01, 1.0);
    if (auto c = s->optionalChild("window")) cfg.fallback.window = c->checkRange(c->asDouble(), 0.01, 60.0);
    s->finish();
  }
  if (auto s = section(root, "limit_guard")) cfg.limit_guard = parseLimitGuardSettings(*s);
  root.finish();
  checkControllerBounds(cfg, root, joints);
  return cfg;
}

ControllerConfig loadControllerConfig(const std::string& path) {
  return parseControllerConfig(YamlReader::loadFile(path));
}

std::string defaultControllerConfigPath() { return configFile("controller.yaml"); }

}  // namespace handover::control
