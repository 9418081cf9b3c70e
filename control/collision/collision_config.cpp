#include "control/collision/collision_config.hpp"

#include <map>
#include <set>

#include "config/yaml_reader.hpp"
#include "config/config_directory.hpp"

namespace handover::control {

bool globMatch(const std::string& pattern, const std::string& name) {
  // iterative matcher with backtracking to the last '*'
  std::size_t p = 0, n = 0, star = std::string::npos, mark = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::string defaultCollisionConfigPath() { return configFile("collision.yaml"); }

namespace {

using Groups = std::map<std::string, std::vector<std::string>>;

// A string or a list of strings.
std::vector<std::string> readNames(const YamlReader& r) {
  std::vector<std::string> out;
  if (r.isSequence()) {
    if (r.size() == 0) r.fail("expected at least one name");
    for (std::size_t i = 0; i < r.size(); ++i) {
      std::string s = r.at(i).asString();
      if (s.empty()) r.at(i).fail("empty name");
      out.push_back(s);
    }
  } else {
    std::string s = r.asString();
    if (s.empty()) r.fail("empty name");
    out.push_back(s);
  }
  return out;
}

std::vector<std::string> expandGroups(const std::vector<std::string>& names, const Groups& groups) {
  std::vector<std::string> out;
  for (const auto& n : names) {
    auto it = groups.find(n);
    if (it == groups.end()) {
      out.push_back(n);
    } else {
      out.insert(out.end(), it->second.begin(), it->second.end());
    }
  }
  return out;
}

// Reads iDist/sDist/damping/damping_offset keys present in `r` over `base`.
DamperSettings readDamper(const YamlReader& r, const DamperSettings& base) {
  DamperSettings d = base;
  if (auto c = r.optionalChild("iDist")) d.i_dist = c->checkRange(c->asDouble(), 1e-4, 1.0);
  if (auto c = r.optionalChild("sDist")) d.s_dist = c->checkRange(c->asDouble(), 0.0, 1.0);
  if (auto c = r.optionalChild("damping")) {
    if (c->node().IsScalar() && c->node().Scalar() == "auto") {
      d.automatic = true;
    } else {
      double xi = 0.0;
      try {
        xi = c->asDouble();
      } catch (const InputError&) {
        c->fail("expected 'auto' or a damping in m/s, got '" + c->node().Scalar() + "'");
      }
      if (!(xi > 0.0)) c->fail("damping must be > 0 (or 'auto'), got " + std::to_string(xi));
      d.automatic = false;
      d.damping = xi;
    }
  }
  if (auto c = r.optionalChild("damping_offset")) d.damping_offset = c->checkRange(c->asDouble(), 0.0, 10.0);
  if (d.s_dist >= d.i_dist) {
    r.fail("sDist (" + std::to_string(d.s_dist) + ") must be smaller than iDist (" + std::to_string(d.i_dist) + ")");
  }
  return d;
}

Vector3 readSize(const YamlReader& r) {
  Eigen::VectorXd v = r.asVector(3);
  if (!(v.minCoeff() > 0.0)) r.fail("sizes must be > 0");
  return v;
}

Isometry readPose(const YamlReader& r) {
  Isometry X = Isometry::Identity();
  if (auto p = r.optionalChild("pos")) X.translation() = p->asVector(3);
  if (auto a = r.optionalChild("rpy")) {
    Eigen::VectorXd rpy = a->asVector(3);
    X.linear() = (Eigen::AngleAxisd(rpy[2], Vector3::UnitZ()) * Eigen::AngleAxisd(rpy[1], Vector3::UnitY()) *
                  Eigen::AngleAxisd(rpy[0], Vector3::UnitX()))
                     .toRotationMatrix();
  }
  return X;
}

bool isPersonName(const std::string& pattern) {
  for (const char* n : {"human_hand", "human_forearm", "human_upper_arm", "human_torso", "human_legs", "human_head",
                        "human_free_arm", "human_hand_forecast"})
    if (globMatch(pattern, n)) return true;
  return false;
}

CollisionConfig parse(const YamlReader& root) {
  if (!root.isMap()) root.fail("expected a map at the top level");
  CollisionConfig cfg;
  cfg.file = root.file();

  if (auto c = root.optionalChild("broadphase_margin")) cfg.broadphase_margin = c->checkRange(c->asDouble(), 0.0, 1.0);
  if (auto c = root.optionalChild("max_escape_acceleration"))
    cfg.max_escape_acceleration = c->checkRange(c->asDouble(), 0.1, 1000.0);
  if (auto c = root.optionalChild("escape_reach_fraction"))
    cfg.escape_reach_fraction = c->checkRange(c->asDouble(), 0.01, 1000.0);
  if (auto c = root.optionalChild("defaults")) {
    cfg.defaults = readDamper(*c, cfg.defaults);
    c->finish();
  }
  if (auto t = root.optionalChild("table")) {
    if (auto c = t->optionalChild("size")) cfg.table.size = readSize(*c);
    if (auto c = t->optionalChild("center_xy")) {
      Eigen::VectorXd v = c->asVector(2);
      cfg.table.center_xy = Vector3(v[0], v[1], 0.0);
    }
    t->finish();
  }
  if (auto p = root.optionalChild("person")) {
    if (auto h = p->optionalChild("hand")) {
      if (auto c = h->optionalChild("size")) cfg.person.hand_size = readSize(*c);
      cfg.person.hand_offset = readPose(*h);
      h->finish();
    }
    if (auto c = p->optionalChild("forearm_radius")) cfg.person.forearm_radius = c->checkRange(c->asDouble(), 0.001, 0.5);
    if (auto c = p->optionalChild("upper_arm_radius")) cfg.person.upper_arm_radius = c->checkRange(c->asDouble(), 0.001, 0.5);
    if (auto c = p->optionalChild("free_arm_radius")) cfg.person.free_arm_radius = c->checkRange(c->asDouble(), 0.001, 0.5);
    if (auto c = p->optionalChild("margin")) cfg.person.margin = c->checkRange(c->asDouble(), 0.0, 0.5);
    if (auto c = p->optionalChild("unseen_hold")) cfg.person.unseen_hold = c->checkRange(c->asDouble(), 0.0, 60.0);
    p->finish();
  }

  if (auto e = root.optionalChild("sensing_error")) {
    SensingError& se = cfg.sensing_error;
    if (auto c = e->optionalChild("calibration")) se.calibration = c->checkRange(c->asDouble(), 0.0, 0.2);
    if (auto c = e->optionalChild("noise")) se.noise = c->checkRange(c->asDouble(), 0.0, 0.1);
    if (auto c = e->optionalChild("noise_sigmas")) se.noise_sigmas = c->checkRange(c->asDouble(), 0.0, 10.0);
    if (auto c = e->optionalChild("latency")) se.latency = c->checkRange(c->asDouble(), 0.0, 1.0);
    if (auto c = e->optionalChild("person_speed")) se.person_speed = c->checkRange(c->asDouble(), 0.0, 5.0);
    if (se.budget() > 0.2) {
      e->fail("the sensing budget calibration + noise_sigmas * noise + latency * person_speed = " +
              std::to_string(se.budget()) + " m exceeds 0.2 m: the robot could not come near the person");
    }
    e->finish();
  }

  Groups groups;
  if (auto g = root.optionalChild("groups")) {
    if (!g->isMap()) g->fail("expected a map of group names to lists of link patterns");
    for (const std::string& k : g->keys()) {
      YamlReader item = g->child(k);
      groups[k] = readNames(item);
      for (const auto& n : groups[k]) {
        if (groups.count(n) && n != k) item.fail("group '" + n + "' inside a group: list its patterns instead");
      }
    }
  }

  YamlReader pairs = root.child("pairs");
  if (!pairs.isSequence() || pairs.size() == 0) pairs.fail("expected a non-empty list of pair rules");
  std::set<std::string> names;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    YamlReader r = pairs.at(i);
    if (!r.isMap()) r.fail("expected a map with name, robot, other");
    PairRule rule;
    rule.line = r.line();
    rule.name = r.getString("name");
    if (rule.name.empty()) r.fail("empty pair name");
    if (!names.insert(rule.name).second) r.child("name").fail("duplicate pair name '" + rule.name + "'");
    rule.robot = expandGroups(readNames(r.child("robot")), groups);
    rule.other = expandGroups(readNames(r.child("other")), groups);
    rule.damper = readDamper(r, cfg.defaults);
    bool person = false;
    for (const auto& o : rule.other) person = person || isPersonName(o);
    rule.margin = person ? cfg.person.margin : 0.0;
    if (auto c = r.optionalChild("margin")) rule.margin = c->checkRange(c->asDouble(), 0.0, 0.5);
    rule.enabled = r.getBool("enabled", true);
    if (auto w = r.optionalChild("when")) {
      const std::string when = w->asString();
      if (when == "always") rule.scope = RuleScope::kAlways;
      else if (when == "apart") rule.scope = RuleScope::kApart;
      else if (when == "sharing") rule.scope = RuleScope::kSharing;
      else if (when == "taking") rule.scope = RuleScope::kTaking;
      else w->fail("'" + when + "' is not one of: always | apart | sharing | taking");
      if (r.has("enabled") && rule.scope != RuleScope::kAlways) w->fail("give `when` or `enabled`, not both");
      if (whileSharing(rule.scope)) rule.enabled = false;  // nothing is shared at start-up
    }
    r.finish();
    cfg.pairs.push_back(std::move(rule));
  }
  root.finish();
  return cfg;
}

}  // namespace

CollisionConfig loadCollisionConfig(const std::string& path) { return parse(YamlReader::loadFile(path)); }

CollisionConfig parseCollisionConfig(const std::string& text, const std::string& origin) {
  return parse(YamlReader::loadString(text, origin));
}

}  // namespace handover::control
