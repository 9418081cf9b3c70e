#include "app/validate/scenario_validation.hpp"

#include <cmath>
#include <sstream>

#include "app/validate/person_trunk.hpp"
#include "config/input_error.hpp"
#include "config/yaml_reader.hpp"
#include "control/collision/collision_config.hpp"
#include "control/collision/collision_data.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"
#include "control/collision/environment_from_human.hpp"
#include "control/controller_registry.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "scenes/human/human_facts.hpp"
#include "scenes/human/scripted_human.hpp"
#include "scenes/scenario/scenario_check.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {

namespace {

// a.b.c := value in `doc` (the key was checked to exist by the parser)
void setDotted(YAML::Node doc, const std::string& dotted, const YAML::Node& value) {
  const auto dot = dotted.find('.');
  if (dot == std::string::npos) {
    doc[dotted] = YAML::Clone(value);
    return;
  }
  setDotted(doc[dotted.substr(0, dot)], dotted.substr(dot + 1), value);
}

// "file:line: key 'k': message" -> "key 'k': message"
std::string withoutFile(const std::string& message, const std::string& file) {
  if (message.rfind(file, 0) != 0) return message;
  const auto colon = message.find(": ", file.size());
  return colon == std::string::npos ? message : message.substr(colon + 2);
}

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(3);
  os << v;
  return os.str();
}

const char* kindName(control::CollisionBodyKind k) {
  switch (k) {
    case control::CollisionBodyKind::kRobot: return "the robot itself";
    case control::CollisionBodyKind::kTable: return "the table";
    case control::CollisionBodyKind::kHumanHand: return "the person's hand";
    case control::CollisionBodyKind::kHumanForearm: return "the person's forearm";
    case control::CollisionBodyKind::kHumanUpperArm: return "the person's upper arm";
    case control::CollisionBodyKind::kObject: return "the object the person holds out";
    case control::CollisionBodyKind::kHumanTrunk: return "the person's body (torso, legs, head or the other arm)";
    case control::CollisionBodyKind::kHumanHandForecast: return "where the person's reaching hand will rest";
  }
  return "?";
}

// where a config setting was given: its `set:` line, else the `config:` line
scenario::SourceRef whereSet(const scenario::Scenario& sc, const std::string& key) {
  for (const auto& [k, where] : sc.override_where) {
    if (k == key) return where;
  }
  return sc.config_where;
}

}  // namespace

control::ControllerConfig controllerConfigOf(const scenario::Scenario& sc) {
  if (sc.config_path.empty() || !sc.config || sc.config.IsNull()) {
    return control::loadControllerConfig(control::defaultControllerConfigPath());
  }
  // the file as written first (its own lines in messages), then each override
  // in turn, so that the one that breaks a bound is named at its line
  const YamlReader file = YamlReader::loadFile(sc.config_path);
  control::ControllerConfig cfg;
  try {
    cfg = control::parseControllerConfig(file);
  } catch (const InputError& e) {
    scenario::failAt(sc.config_where, std::string("in the controller config: ") + e.what());
  }
  YAML::Node doc = YAML::Clone(file.node());
  for (const auto& [key, where] : sc.override_where) {
    setDotted(doc, key, sc.overrides[key]);
    try {
      cfg = control::parseControllerConfig(YamlReader(YAML::Clone(doc), sc.config_path, ""));
    } catch (const InputError& e) {
      scenario::failAt(where, "overriding " + sc.config_path + ": " + withoutFile(e.what(), sc.config_path));
    }
  }
  return cfg;
}

void validateScenario(const scenario::Scenario& sc) {
  const control::ControllerConfig cfg = controllerConfigOf(sc);
  if (std::abs(cfg.period - kSceneTimestep) > 1e-12) {
    scenario::failAt(whereSet(sc, "period"), "the controller period " + fmt(cfg.period) +
                                          " s must equal the simulator's step " + fmt(kSceneTimestep) +
                                          " s (the run steps both once per cycle)");
  }
  // the QP is assembled from the config's entries: every type must be registered
  // (the parameters are checked when the run builds the controller)
  const control::ControllerRegistry registry = control::ControllerRegistry::shipped();
  for (const control::ElementEntry& e : cfg.tasks)
    if (!registry.hasTask(e.type))
      scenario::failAt(sc.config_where, "in the controller config: task '" + e.name + "' has the unknown type '" +
                                            e.type + "'");
  for (const control::ElementEntry& e : cfg.constraints)
    if (!registry.hasConstraint(e.type))
      scenario::failAt(sc.config_where, "in the controller config: constraint '" + e.name +
                                            "' has the unknown type '" + e.type + "'");

  // a latency beyond the estimator's max_latency (perception.yaml) is a
  // valid scenario (the contract allows up to 1 s): the robot then sees only
  // stale samples, a sensing fault the run reports, not bad input

  const scenario::SourceRef q_where = sc.start_q_where.file.empty() ? sc.config_where : sc.start_q_where;
  const control::Vector7 q0 = sc.robot.start_q.value_or(cfg.posture.target);

  // the start posture clears the table, the arm itself and the person at t = 0
  const control::Model model = control::loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  control::Data data(model);
  control::CollisionConfig ccfg = control::loadCollisionConfig(control::defaultCollisionConfigPath());
  human::ScriptedHuman person(sc);
  ccfg.person.trunk = personTrunkFor(person.body(), sc.human.hand);
  const control::CollisionModel cm = control::buildCollisionModel(model, ccfg);
  control::CollisionData cd(cm);
  const human::HumanOutput& h0 = person.step(0.0, human::HumanFacts{});
  control::computeAll(model, data, q0, control::Vector7::Zero());
  control::updateCollisions(cm, cd, model, data, control::environmentFromHuman(h0.poses));
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& res = cd.results[i];
    if (!res.active) continue;
    const double clearance = res.distance + cm.pairs[i].margin;
    if (clearance < 0.0) {
      scenario::failAt(q_where, "at the start posture the robot (" + cm.pairLabel(i) + ") overlaps " +
                                    kindName(cm.bodies[cm.pairs[i].other_body].kind) + " by " +
                                    fmt(-clearance * 1e3) + " mm");
    }
  }

  // gravity at rest takes at most limits.torque.hold.share of each scaled torque limit
  // (the share the gravity-hold constraint keeps the arm within),
  // at the start (with the object if the robot holds it) and at the posture
  // target carrying the object (where a taken object goes)
  auto checkGravity = [&](const control::Vector7& q, bool payload, const scenario::SourceRef& where, const char* what) {
    if (payload) {
      control::Payload p;
      p.mass = sc.object.mass;
      p.com = sc.object.grasp.inverse().translation();
      control::setPayload(model, data, p);
    } else {
      control::clearPayload(model, data);
    }
    control::computeAll(model, data, q, control::Vector7::Zero());
    for (int j = 0; j < control::kArmDofs; ++j) {
      const double limit = cfg.limits.torque_scale * model.tau_max[j];
      const double share = cfg.limits.gravity_hold.share;
      if (std::abs(data.h[j]) > share * limit) {
        scenario::failAt(where, std::string("gravity at ") + what + " needs " + fmt(std::abs(data.h[j])) +
                                    " N m at joint " + std::to_string(j + 1) + ", more than " +
                                    fmt(share * 100) + "% of its limit " + fmt(limit) +
                                    " N m (limits.torque.scale " + fmt(cfg.limits.torque_scale) + ")");
      }
    }
  };
  const scenario::SourceRef torque_where = whereSet(sc, "limits.torque.scale");
  checkGravity(q0, sc.robot.holds_object, sc.robot.start_q ? q_where : torque_where, "the start posture");
  checkGravity(cfg.posture.target, true, torque_where, "the posture target carrying the object");
}

scenario::Scenario loadValidScenario(const std::string& path) {
  scenario::Scenario sc = scenario::parseScenario(path);
  validateScenario(sc);
  return sc;
}

}  // namespace handover::app
