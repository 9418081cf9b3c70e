#include "control/collision/collision_model.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <utility>

#include "config/input_error.hpp"

namespace handover::control {

int CollisionModel::ruleIndex(const std::string& name) const {
  for (std::size_t i = 0; i < rule_names.size(); ++i)
    if (rule_names[i] == name) return static_cast<int>(i);
  return -1;
}

std::string CollisionModel::pairLabel(int pair) const {
  const CollisionPair& p = pairs[pair];
  auto label = [](const CollisionBody& b) { return b.isRobot() ? b.link + "/" + b.name : b.name; };
  return rule_names[p.rule] + ": " + label(bodies[p.robot_body]) + " - " + label(bodies[p.other_body]);
}

namespace {

bool hasWildcard(const std::string& s) { return s.find_first_of("*?") != std::string::npos; }

// canonical frame of segment [a, b]: centre at the midpoint, z along b - a
Isometry segmentFrame(const Vector3& a, const Vector3& b) {
  Isometry X = Isometry::Identity();
  X.translation() = 0.5 * (a + b);
  const Vector3 d = b - a;
  if (d.norm() > 1e-12) X.linear() = Quaternion::FromTwoVectors(Vector3::UnitZ(), d).toRotationMatrix();
  return X;
}

[[noreturn]] void ruleError(const CollisionConfig& cfg, const PairRule& rule, const std::string& what) {
  std::string msg = cfg.file;
  if (rule.line > 0) msg += ":" + std::to_string(rule.line);
  msg += ": key 'pairs' rule '" + rule.name + "': " + what;
  throw InputError(msg);
}

bool matchesRobot(const std::string& pattern, const CollisionBody& b) {
  return b.isRobot() && (globMatch(pattern, b.link) || globMatch(pattern, b.name));
}

// a name of one of the robot description's link groups stands for its patterns
std::vector<std::string> expandLinkGroups(const std::vector<std::string>& names, const Model& model) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    const auto g = std::find_if(model.link_groups.begin(), model.link_groups.end(),
                                [&](const LinkGroup& group) { return group.name == n; });
    if (g == model.link_groups.end()) out.push_back(n);
    else out.insert(out.end(), g->patterns.begin(), g->patterns.end());
  }
  return out;
}

}  // namespace

CollisionModel buildCollisionModel(const Model& model, const CollisionConfig& cfg) {
  CollisionModel cm;
  cm.broadphase_margin = cfg.broadphase_margin;

  // robot capsules
  for (std::size_t i = 0; i < model.capsules.size(); ++i) {
    const Capsule& c = model.capsules[i];
    if (c.body < 0 || c.body >= kNumBodies || !(c.radius >= 0.0))
      throw InputError(model.urdf_path + ": collision capsule '" + c.name + "' has an invalid body or radius");
    CollisionBody b;
    b.name = c.name;
    b.link = c.link;
    b.role = c.role;
    b.kind = CollisionBodyKind::kRobot;
    b.capsule = static_cast<int>(i);
    b.body = c.body;
    b.shape.kind = ShapeSpec::Kind::kSegment;
    b.shape.length = (c.b - c.a).norm();
    b.radius = c.radius;
    b.local = segmentFrame(c.a, c.b);
    cm.bodies.push_back(b);
    if (c.role != CapsuleRole::kArm && cm.gripper_body < 0) cm.gripper_body = c.body;
  }
  const int num_robot = static_cast<int>(cm.bodies.size());

  // environment
  auto addEnv = [&](const char* name, CollisionBodyKind kind, ShapeSpec shape, double radius, const Isometry& local) {
    CollisionBody b;
    b.name = b.link = name;
    b.kind = kind;
    b.shape = shape;
    b.radius = radius;
    b.local = local;
    cm.bodies.push_back(b);
    return static_cast<int>(cm.bodies.size()) - 1;
  };
  ShapeSpec box;
  box.kind = ShapeSpec::Kind::kBox;
  box.size = cfg.table.size;
  Isometry table_pose = Isometry::Identity();
  table_pose.translation() = Vector3(cfg.table.center_xy.x(), cfg.table.center_xy.y(), -0.5 * cfg.table.size.z());
  cm.table = addEnv("table", CollisionBodyKind::kTable, box, 0.0, table_pose);
  box.size = cfg.person.hand_size;
  cm.human_hand = addEnv("human_hand", CollisionBodyKind::kHumanHand, box, 0.0, cfg.person.hand_offset);
  ShapeSpec seg;
  seg.kind = ShapeSpec::Kind::kSegment;
  seg.length = 0.27;
  cm.human_forearm = addEnv("human_forearm", CollisionBodyKind::kHumanForearm, seg, cfg.person.forearm_radius,
                            Isometry::Identity());
  // the hand's way to the end of its reach: a capsule as wide as the hand box, re-laid every cycle
  seg.length = 0.0;
  cm.human_hand_forecast = addEnv("human_hand_forecast", CollisionBodyKind::kHumanHandForecast, seg,
                                  0.5 * cfg.person.hand_size.maxCoeff(), Isometry::Identity());
  seg.length = 0.33;
  cm.human_upper_arm = addEnv("human_upper_arm", CollisionBodyKind::kHumanUpperArm, seg,
                              cfg.person.upper_arm_radius, Isometry::Identity());
  // the trunk, in the torso frame (floor under the body centre)
  const PersonTrunk& trunk = cfg.person.trunk;
  if (!(trunk.torso_size.minCoeff() > 0.0) || !(trunk.legs_size.minCoeff() > 0.0) || !(trunk.head_radius > 0.0))
    throw InputError(cfg.file + ": the person's trunk sizes must be > 0");
  auto above = [](double z) {
    Isometry X = Isometry::Identity();
    X.translation().z() = z;
    return X;
  };
  box.size = trunk.torso_size;
  cm.human_torso = addEnv("human_torso", CollisionBodyKind::kHumanTrunk, box, 0.0, above(trunk.torso_centre));
  box.size = trunk.legs_size;
  cm.human_legs = addEnv("human_legs", CollisionBodyKind::kHumanTrunk, box, 0.0, above(trunk.legs_centre));
  seg.length = 0.0;  // a sphere: a point core with a radius
  cm.human_head = addEnv("human_head", CollisionBodyKind::kHumanTrunk, seg, trunk.head_radius, above(trunk.head_centre));
  if (!trunk.free_arm_top.allFinite() || !trunk.free_arm_bottom.allFinite() || !(cfg.person.free_arm_radius > 0.0))
    throw InputError(cfg.file + ": the person's free arm must be finite with a radius > 0");
  seg.length = (trunk.free_arm_bottom - trunk.free_arm_top).norm();
  cm.human_free_arm = addEnv("human_free_arm", CollisionBodyKind::kHumanTrunk, seg, cfg.person.free_arm_radius,
                             segmentFrame(trunk.free_arm_top, trunk.free_arm_bottom));
  // cores are centred on their frame, as the object frame is on its shape
  cm.object = addEnv("object", CollisionBodyKind::kObject, cfg.object.shape,
                     cfg.object.shape.kind == ShapeSpec::Kind::kBox ? 0.0 : cfg.object.radius, Isometry::Identity());

  // pair rules
  std::map<std::pair<int, int>, int> seen;  // unordered body pair -> rule
  for (std::size_t r = 0; r < cfg.pairs.size(); ++r) {
    const PairRule& rule = cfg.pairs[r];
    cm.rule_names.push_back(rule.name);
    cm.rule_enabled.push_back(rule.enabled);
    cm.rule_scope.push_back(rule.scope);

    std::vector<int> robots, others;
    const std::vector<std::string> robot_side = expandLinkGroups(rule.robot, model);
    const std::vector<std::string> other_side = expandLinkGroups(rule.other, model);
    for (const auto& pat : robot_side) {
      bool any = false;
      for (int i = 0; i < num_robot; ++i) {
        if (matchesRobot(pat, cm.bodies[i])) {
          any = true;
          if (std::find(robots.begin(), robots.end(), i) == robots.end()) robots.push_back(i);
        }
      }
      if (!any) {
        for (int i = num_robot; i < static_cast<int>(cm.bodies.size()); ++i)
          if (globMatch(pat, cm.bodies[i].name))
            ruleError(cfg, rule, "robot side '" + pat + "' names '" + cm.bodies[i].name + "', which is not a robot link");
        if (!hasWildcard(pat)) ruleError(cfg, rule, "robot side '" + pat + "' matches no robot link or capsule");
      }
    }
    for (const auto& pat : other_side) {
      bool any = false;
      for (int i = 0; i < static_cast<int>(cm.bodies.size()); ++i) {
        const CollisionBody& b = cm.bodies[i];
        if (b.isRobot() ? matchesRobot(pat, b) : globMatch(pat, b.name)) {
          any = true;
          if (std::find(others.begin(), others.end(), i) == others.end()) others.push_back(i);
        }
      }
      if (!any && !hasWildcard(pat))
        ruleError(cfg, rule, "other side '" + pat + "' matches no robot link, 'table', 'object' or human_* body");
    }

    const int before = cm.numPairs();
    for (int a : robots) {
      for (int o : others) {
        const CollisionBody& ra = cm.bodies[a];
        const CollisionBody& ob = cm.bodies[o];
        if (ob.isRobot() && (a == o || std::abs(ra.body - ob.body) <= 1)) continue;  // same or adjacent links
        if (ob.kind == CollisionBodyKind::kTable && ra.body <= 1)
          ruleError(cfg, rule, "'" + ra.link + "' rests on the table and cannot be paired with it");
        const auto key = std::make_pair(std::min(a, o), std::max(a, o));
        auto it = seen.find(key);
        if (it != seen.end()) {
          if (it->second == static_cast<int>(r)) continue;  // e.g. "arm vs arm" lists both orders
          const RuleScope earlier = cfg.pairs[it->second].scope;
          const bool exclusive = (earlier == RuleScope::kApart && whileSharing(rule.scope)) ||
                                 (whileSharing(earlier) && rule.scope == RuleScope::kApart);
          // never on together (the pair's settings while apart and while sharing): both may list it
          if (!exclusive) {
            ruleError(cfg, rule, "pair '" + ra.link + "/" + ra.name + " - " + ob.name + "' is already listed by rule '" +
                                     cfg.pairs[it->second].name + "'");
          }
        }
        seen[key] = static_cast<int>(r);
        CollisionPair p;
        p.rule = static_cast<int>(r);
        p.robot_body = a;
        p.other_body = o;
        p.damper = rule.damper;
        // the person is sensed: the pair also budgets the sensor's declared
        // error, except while the gripper shares the object with the person's
        // hand (`sharing` rules: there robot and hand meet at the object by design)
        const bool sensed = ob.isPerson() || ob.kind == CollisionBodyKind::kHumanHandForecast;
        const bool budget = sensed && !whileSharing(rule.scope);
        p.margin = rule.margin + (budget ? cfg.sensing_error.budget() : 0.0);
        cm.pairs.push_back(p);
      }
    }
    if (cm.numPairs() == before) ruleError(cfg, rule, "yields no collision pair (only adjacent links or no match)");
  }
  return cm;
}

}  // namespace handover::control
