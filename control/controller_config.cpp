#include "control/controller_config.hpp"

#include <cmath>

#include "control/controller_config_bounds.hpp"

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

std::optional<YamlReader> section(const YamlReader& root, const char* key) {
  auto r = root.optionalChild(key);
  if (r && !r->isMap()) r->fail("expected a map");
  return r;
}

}  // namespace

ControllerConfig parseControllerConfig(const YamlReader& root) {
  ControllerConfig cfg;
  if (root.isNull()) return cfg;  // empty file: all defaults
  if (!root.isMap()) root.fail("expected a map of controller settings");

  if (auto c = root.optionalChild("period")) cfg.period = c->checkRange(c->asDouble(), 1e-5, 0.1);
  if (auto c = root.optionalChild("frame")) cfg.frame = c->asString();

  if (auto s = section(root, "observation")) {
    cfg.observation.gains = readGains(*s, cfg.observation.gains);
    cfg.observation.weight = readWeight(*s, cfg.observation.weight);
    s->finish();
  }
  if (auto s = section(root, "tracking")) {
    cfg.tracking.weight = readWeight(*s, cfg.tracking.weight);
    cfg.tracking.translation = readAxis(*s, "translation", cfg.tracking.translation);
    cfg.tracking.orientation = readAxis(*s, "orientation", cfg.tracking.orientation);
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
      v->finish();
    }
    if (auto a = section(*s, "acceleration")) {
      if (auto c = a->optionalChild("scale")) cfg.limits.acceleration_scale = c->checkRange(c->asDouble(), 1e-3, 1.0);
      a->finish();
    }
    if (auto t = section(*s, "torque")) {
      if (auto c = t->optionalChild("scale")) cfg.limits.torque_scale = c->checkRange(c->asDouble(), 1e-3, 1.0);
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
  checkControllerBounds(cfg, root);
  return cfg;
}

ControllerConfig loadControllerConfig(const std::string& path) {
  return parseControllerConfig(YamlReader::loadFile(path));
}

std::string defaultControllerConfigPath() { return std::string(HANDOVER_SOURCE_DIR) + "/config/controller.yaml"; }

}  // namespace handover::control
