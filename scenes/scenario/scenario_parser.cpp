#include "scenes/scenario/scenario_parser.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "config/yaml_reader.hpp"
#include "control/model/joint_limits.hpp"
#include "scenes/scenario/object_geometry.hpp"
#include "scenes/scenario/scenario_bounds.hpp"
#include "scenes/scenario/scenario_check.hpp"

namespace handover::scenario {

namespace fs = std::filesystem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxAngle = 2.0 * M_PI;  // rad
constexpr double kMaxPosition = 5.0;      // m

SourceRef refOf(const YamlReader& r) { return {r.file(), r.path(), r.line()}; }

// a name goes into JSON, CSV and folder names: printable UTF-8, at most 200 bytes
const char* badName(const std::string& name) {
  if (name.size() > 200) return "name longer than 200 bytes";
  for (std::size_t i = 0; i < name.size();) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (c < 0x20 || c == 0x7f) return "name contains a control character";
    const int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    if (len == 0 || i + len > name.size()) return "name is not valid UTF-8";
    for (int k = 1; k < len; ++k) {
      if ((static_cast<unsigned char>(name[i + k]) & 0xc0) != 0x80) return "name is not valid UTF-8";
    }
    i += static_cast<std::size_t>(len);
  }
  return nullptr;
}

double positive(const YamlReader& r) {
  const double v = r.asDouble();
  if (!(v > 0.0)) r.fail("must be > 0, got " + r.node().Scalar());
  return v;
}
double nonNegative(const YamlReader& r) {
  const double v = r.asDouble();
  if (v < 0.0) r.fail("must be >= 0, got " + r.node().Scalar());
  return v;
}
int nonNegativeInt(const YamlReader& r) {
  const int v = r.asInt();
  if (v < 0) r.fail("must be >= 0, got " + r.node().Scalar());
  return v;
}

// roll-pitch-yaw angles within one turn either way: larger values are typos
// (degrees for radians) and lose precision in sin/cos
Eigen::Vector3d readRpy(const YamlReader& r) {
  const Eigen::Vector3d rpy = r.asVector(3);
  for (int i = 0; i < 3; ++i) r.at(static_cast<std::size_t>(i)).checkRange(rpy[i], -kMaxAngle, kMaxAngle);
  return rpy;
}

// positions within kMaxPosition of the origin (any pose of a scenario is
// within a few metres of the robot)
Eigen::Vector3d readPosition(const YamlReader& r) {
  const Eigen::Vector3d p = r.asVector(3);
  for (int i = 0; i < 3; ++i) r.at(static_cast<std::size_t>(i)).checkRange(p[i], -kMaxPosition, kMaxPosition);
  return p;
}

// x | y | z as 0 | 1 | 2
int readAxis(const YamlReader& r) { return r.asEnum({"x", "y", "z"})[0] - 'x'; }

// {pos: [x, y, z], rpy: [r, p, y]} with rpy optional (identity when missing)
Eigen::Isometry3d readPose(const YamlReader& r) {
  if (!r.isMap()) r.fail("expected a map {pos: [x, y, z], rpy: [r, p, y]}");
  const Eigen::Vector3d pos = readPosition(r.child("pos"));
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  if (auto c = r.optionalChild("rpy")) rpy = readRpy(*c);
  r.finish();
  return poseFromPosRpy(pos, rpy);
}

// an empty step body may be written `release:` or `release: {}`
void expectEmpty(const YamlReader& r) {
  if (r.isNull()) return;
  if (!r.isMap()) r.fail("expected {} (this step takes no settings)");
  r.finish();
}

ScriptStep readStep(const YamlReader& item) {
  if (!item.isMap() || item.size() != 1) {
    item.fail("a script step is a map with exactly one of: reach, withdraw, hold, wait, release, grasp, pull");
  }
  const std::string kind = item.keys().front();
  ScriptStep s;
  const YamlReader body = item.child(kind);
  s.where = refOf(body);
  auto needMap = [&]() {
    if (!body.isMap()) body.fail("expected a map of settings");
  };
  if (kind == "reach" || kind == "withdraw") {
    needMap();
    s.kind = kind == "reach" ? StepKind::Reach : StepKind::Withdraw;
    const YamlReader pos = body.child("pos");
    s.pos = readPosition(pos);
    s.target_where = refOf(pos);
    if (auto r = body.optionalChild("rpy")) s.rpy = readRpy(*r);
    s.duration = positive(body.child("duration"));
  } else if (kind == "hold") {
    needMap();
    s.kind = StepKind::Hold;
    s.duration = nonNegative(body.child("duration"));
  } else if (kind == "wait") {
    needMap();
    s.kind = StepKind::Wait;
    const std::string u = body.child("until").asEnum({"fingers_on_object", "object_free", "object_in_reach"});
    s.until = u == "fingers_on_object" ? WaitUntil::FingersOnObject
              : u == "object_free"     ? WaitUntil::ObjectFree
                                       : WaitUntil::ObjectInReach;
    if (auto t = body.optionalChild("timeout")) s.timeout = positive(*t);
    if (auto d = body.optionalChild("delay")) {
      s.delay = nonNegative(*d);
      if (s.timeout && s.delay >= *s.timeout) d->fail("delay must be shorter than timeout, or the wait can never fire");
    }
  } else if (kind == "release" || kind == "grasp") {
    s.kind = kind == "release" ? StepKind::Release : StepKind::Grasp;
    expectEmpty(body);
    return s;
  } else if (kind == "pull") {
    needMap();
    s.kind = StepKind::Pull;
    const YamlReader dir = body.child("dir");
    const Eigen::Vector3d d = dir.asVector(3);
    if (d.norm() < 1e-9) dir.fail("direction must not be zero");
    s.dir = d.normalized();
    const YamlReader dist = body.child("distance");
    s.distance = positive(dist);
    s.target_where = refOf(dist);
    s.duration = positive(body.child("duration"));
  } else {
    YamlReader(item.node().begin()->first, item.file(), item.path() + "." + kind)
        .fail("unknown script step '" + kind + "' (allowed: reach, withdraw, hold, wait, release, grasp, pull)");
  }
  body.finish();
  return s;
}

void readObject(const YamlReader& r, ObjectSpec& o) {
  if (!r.isMap()) r.fail("expected a map");
  const std::string shape = r.child("shape").asEnum({"cylinder", "box", "sphere"});
  o.shape = shape == "cylinder" ? Shape::Cylinder : shape == "box" ? Shape::Box : Shape::Sphere;
  const YamlReader size = r.child("size");
  const int n = o.shape == Shape::Cylinder ? 2 : o.shape == Shape::Box ? 3 : 1;
  if (!size.isSequence() || static_cast<int>(size.size()) != n) {
    const char* what = o.shape == Shape::Cylinder ? "[radius, height]" : o.shape == Shape::Box ? "[x, y, z] edges" : "[radius]";
    size.fail("a " + shape + " needs size " + what + " (" + std::to_string(n) + " numbers)");
  }
  const Eigen::VectorXd v = size.asVector(n);
  o.size.assign(v.data(), v.data() + n);
  for (int i = 0; i < n; ++i) {
    if (!(v[i] >= kMinObjectSize)) size.at(static_cast<std::size_t>(i)).fail("sizes below 5 mm are not a hand-held object");
    if (v[i] > 1.0) size.at(static_cast<std::size_t>(i)).fail("sizes above 1 m are not a hand-held object");
  }
  const YamlReader mass = r.child("mass");
  o.mass = positive(mass);
  if (o.mass < kMinObjectMass) mass.fail("mass below 10 g is not a hand-held object (the simulator needs a real inertia)");
  if (o.mass > 5.0) mass.fail("mass above 5 kg exceeds what the Panda hands over (payload 3 kg)");
  const double density = o.mass / objectVolume(o);
  if (density < kMinDensity || density > kMaxDensity) {
    std::ostringstream os;
    os << "mass " << o.mass << " kg in " << objectVolume(o) * 1e3 << " l is a density of " << density
       << " kg/m^3; a solid object is between " << kMinDensity << " (foam) and " << kMaxDensity << " (tungsten)";
    mass.fail(os.str());
  }
  if (auto g = r.optionalChild("grasp")) o.grasp = readPose(*g);
  if (auto a = r.optionalChild("free_axis")) o.free_axis = readAxis(*a);
  if (auto list = r.optionalChild("grasps")) {
    if (!list->isSequence() || list->size() < 1 || list->size() > 16)
      list->fail("expected a list of 1 to 16 grasps {pos: [x, y, z], rpy: [r, p, y], free_axis: x|y|z}");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const YamlReader g = list->at(i);
      if (!g.isMap()) g.fail("expected a map {pos: [x, y, z], rpy: [r, p, y], free_axis: x|y|z}");
      Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
      if (auto c = g.optionalChild("rpy")) rpy = readRpy(*c);
      ObjectSpec::ExtraGrasp extra;
      extra.grasp = poseFromPosRpy(readPosition(g.child("pos")), rpy);
      if (auto a = g.optionalChild("free_axis")) extra.free_axis = readAxis(*a);
      g.finish();
      o.grasps.push_back(extra);
    }
  }
  r.finish();
}

void readRobot(const YamlReader& r, Scenario& s) {
  if (!r.isMap()) r.fail("expected a map");
  if (auto q = r.optionalChild("start_q")) {
    const Vector7 v = q->asVector(7);
    // inside the joint limits (the robot description's model) less the position
    // damper's default safety zone (1% of each range), which the controller
    // never lets the arm enter
    const control::JointLimits& limits = control::defaultJointLimits();
    for (int i = 0; i < 7; ++i) {
      const double margin = kStartQSafety * (limits.q_max[i] - limits.q_min[i]);
      q->at(static_cast<std::size_t>(i)).checkRange(v[i], limits.q_min[i] + margin, limits.q_max[i] - margin);
    }
    s.robot.start_q = v;
    s.start_q_where = refOf(*q);
  }
  if (auto h = r.optionalChild("holds_object")) {
    s.robot.holds_object = h->asBool();
    s.robot_holds_where = refOf(*h);
  } else {
    s.robot_holds_where = refOf(r);
  }
  r.finish();
}

void readHuman(const YamlReader& r, HumanSpec& h) {
  if (!r.isMap()) r.fail("expected a map");
  const YamlReader stand = r.child("stand");
  if (!stand.isMap()) stand.fail("expected {pos: [x, y], yaw: rad}");
  const YamlReader stand_pos = stand.child("pos");
  h.stand_pos = stand_pos.asVector(2);
  const double stand_dist = h.stand_pos.norm();
  if (stand_dist < kMinStandDistance || stand_dist > kMaxStandDistance) {
    std::ostringstream os;
    os << "the person stands " << stand_dist << " m from the robot's base; between " << kMinStandDistance
       << " m (clear of the table's robot end) and " << kMaxStandDistance << " m (a handover needs them near)";
    stand_pos.fail(os.str());
  }
  if (auto y = stand.optionalChild("yaw")) h.stand_yaw = y->checkRange(y->asDouble(), -kMaxAngle, kMaxAngle);
  stand.finish();
  const YamlReader height = r.child("height");
  h.height = height.checkRange(height.asDouble(), 1.2, 2.2);
  const std::string hand = r.getString("hand", "right");
  if (hand != "right" && hand != "left") r.child("hand").asEnum({"right", "left"});
  h.hand = hand == "right" ? HandSide::Right : HandSide::Left;
  const YamlReader start = r.child("start");
  h.start = readPose(start);
  h.start_where = refOf(start.child("pos"));
  if (auto ho = r.optionalChild("holds_object")) {
    if (!ho->isNull()) {
      h.holds_object = readPose(*ho);
      h.holds_where = refOf(*ho);
    }
  }
  const YamlReader script = r.child("script");
  if (!script.isSequence()) script.fail("expected a list of steps");
  if (script.size() == 0) script.fail("the script needs at least one step");
  for (std::size_t i = 0; i < script.size(); ++i) h.script.push_back(readStep(script.at(i)));
  r.finish();
}

void readSensor(const YamlReader& r, perception::SensorSettings& s) {
  if (!r.isMap()) r.fail("expected a map");
  if (auto c = r.optionalChild("rate_hz")) {
    s.rate_hz = positive(*c);
    if (s.rate_hz > 1000.0) c->fail("rate above 1000 Hz is faster than the control loop");
  }
  if (auto c = r.optionalChild("latency")) {
    s.latency = nonNegative(*c);
    if (s.latency > 1.0) c->fail("latency above 1 s is not a tracking sensor");
  }
  if (auto n = r.optionalChild("noise")) {
    if (!n->isMap()) n->fail("expected {pos: m, rot_deg: deg}");
    if (auto c = n->optionalChild("pos")) s.noise_pos = c->checkRange(nonNegative(*c), 0.0, kMaxNoisePos);
    if (auto c = n->optionalChild("rot_deg")) s.noise_rot_deg = c->checkRange(nonNegative(*c), 0.0, kMaxNoiseRotDeg);
    n->finish();
  }
  if (auto d = r.optionalChild("dropouts")) {
    if (!d->isSequence()) d->fail("expected a list of [begin, end] intervals");
    double prev_end = -kInf;
    for (std::size_t i = 0; i < d->size(); ++i) {
      const YamlReader iv = d->at(i);
      const Eigen::VectorXd v = iv.asVector(2);
      if (v[0] < 0.0) iv.fail("interval begins before t = 0");
      if (!(v[1] > v[0])) iv.fail("interval must end after it begins");
      if (v[0] < prev_end) iv.fail("intervals must be ordered and must not overlap");
      if (v[1] > 1e6) iv.fail("interval ends after 10^6 s");
      prev_end = v[1];
      s.dropouts.emplace_back(v[0], v[1]);
    }
  }
  if (auto o = r.optionalChild("offset")) {
    s.offset = readPose(*o);
    const double off = s.offset.translation().norm();
    const double off_rot = Eigen::AngleAxisd(s.offset.linear()).angle();
    if (off > kMaxOffsetPos) o->fail("a calibration offset above 10 cm is not a calibrated tracker");
    if (off_rot > kMaxOffsetRot) o->fail("a calibration offset above 0.2 rad (11 deg) is not a calibrated tracker");
  }
  r.finish();
}

void readExpect(const YamlReader& r, Expectations& e, double duration) {
  if (!r.isMap()) r.fail("expected a map");
  if (auto c = r.optionalChild("outcome"))
    e.outcome = c->asEnum({"success", "aborted", "hand_contact", "object_drop", "timeout", "no_perception", "unsafe", "error"});
  if (auto c = r.optionalChild("aborts")) e.aborts = nonNegativeInt(*c);
  if (auto c = r.optionalChild("retries")) e.retries = nonNegativeInt(*c);
  if (auto c = r.optionalChild("handovers")) e.handovers = nonNegativeInt(*c);
  if (auto c = r.optionalChild("max_total_time")) {
    e.max_total_time = positive(*c);
    if (*e.max_total_time > duration) c->fail("longer than the scenario's duration");
  }
  if (auto c = r.optionalChild("min_human_distance")) e.min_human_distance = nonNegative(*c);
  if (auto c = r.optionalChild("max_time_to_grasp")) e.max_time_to_grasp = positive(*c);
  if (auto c = r.optionalChild("max_human_contacts")) e.max_human_contacts = nonNegativeInt(*c);
  if (auto c = r.optionalChild("object_dropped")) e.object_dropped = c->asBool();
  r.finish();
}

// sets a.b.c in `node` (the path exists: applyOverrides checked it)
void setDotted(YAML::Node node, const std::string& dotted, const YAML::Node& value) {
  const auto dot = dotted.find('.');
  if (dot == std::string::npos) {
    node[dotted] = YAML::Clone(value);
    return;
  }
  setDotted(node[dotted.substr(0, dot)], dotted.substr(dot + 1), value);
}

std::string resolveConfig(const YamlReader& r, const std::string& scenario_file) {
  const std::string given = r.asString();
  if (given.empty()) r.fail("empty path");
  fs::path p(given);
  std::vector<fs::path> tried;
  if (p.is_absolute()) {
    tried.push_back(p);
  } else {
    tried.push_back(fs::path(scenario_file).parent_path() / p);
    tried.push_back(fs::path(HANDOVER_SOURCE_DIR) / p);
  }
  for (const auto& t : tried) {
    std::error_code ec;
    if (fs::is_regular_file(t, ec)) return t.lexically_normal().string();
  }
  std::string list;
  for (const auto& t : tried) list += (list.empty() ? "" : ", ") + t.string();
  r.fail("config file '" + given + "' not found (looked at " + list + ")");
}

Scenario readScenario(const YamlReader& root) {
  if (!root.isMap()) root.fail("a scenario file is a map of keys (name, mode, duration, ...)");
  Scenario s;
  s.file = root.file();
  s.name = root.getString("name");
  if (s.name.empty()) root.child("name").fail("name must not be empty");
  if (const char* why = badName(s.name)) root.child("name").fail(why);
  const YamlReader mode = root.child("mode");
  s.mode = mode.asEnum({"human_to_robot", "robot_to_human"}) == "human_to_robot" ? Mode::HumanToRobot
                                                                                 : Mode::RobotToHuman;
  s.mode_where = refOf(mode);
  const YamlReader duration = root.child("duration");
  s.duration = positive(duration);
  if (s.duration > 600.0) duration.fail("longer than 600 s of simulated time");
  if (auto c = root.optionalChild("seed")) s.seed = nonNegativeInt(*c);
  if (auto b = root.optionalChild("behaviour")) {
    s.behaviour = b->asString();
    const bool word = !s.behaviour.empty() && s.behaviour.size() <= 32 &&
                      s.behaviour.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
    if (!word) b->fail("behaviour is one lowercase word (a-z, 0-9, _; at most 32), got '" + s.behaviour + "'");
  }

  // controller config: given, else the default if it exists; `set:` needs one
  std::optional<YamlReader> cfg = root.optionalChild("config");
  s.config_where = cfg ? refOf(*cfg) : refOf(root);
  if (cfg) s.config_path = resolveConfig(*cfg, s.file);
  else if (fs::is_regular_file(defaultConfigPath())) s.config_path = defaultConfigPath();
  if (!s.config_path.empty()) {
    try {
      s.config = YamlReader::loadFile(s.config_path).node();
    } catch (const InputError& e) {
      failAt(s.config_where, std::string("in the controller config: ") + e.what());
    }
    if (!s.config.IsNull() && !s.config.IsMap()) {
      failAt(s.config_where, s.config_path + " is not a controller config (expected a map of settings)");
    }
  }
  if (auto set = root.optionalChild("set")) {
    if (s.config_path.empty()) {
      set->fail("no controller config to apply overrides to: give `config:` (" + defaultConfigPath() +
                " does not exist)");
    }
    if (!set->isMap()) set->fail("expected a map of dotted config keys to values");
    // applyOverrides rebinds its walking handle, which rewrites the document
    // it walks (yaml-cpp assignment semantics): check each key on a fresh
    // clone and merge the values here
    const YAML::Node pristine = YAML::Clone(s.config);
    for (const std::string& key : set->keys()) {
      s.override_where.emplace_back(key, refOf(set->child(key)));
      YAML::Node one(YAML::NodeType::Map);
      one[key] = set->node()[key];
      applyOverrides(YAML::Clone(pristine), YamlReader(one, set->file(), set->path()), s.config_path);
      setDotted(s.config, key, set->child(key).node());
    }
    s.overrides = YAML::Clone(set->node());
  }

  const YamlReader object = root.child("object");
  s.object_where = refOf(object);
  readObject(object, s.object);
  if (auto r = root.optionalChild("robot")) readRobot(*r, s);
  else s.robot_holds_where = refOf(root);
  readHuman(root.child("human"), s.human);
  if (auto r = root.optionalChild("sensor")) {
    s.sensor_where = refOf(*r);
    readSensor(*r, s.sensor);
  } else {
    s.sensor_where = refOf(root);
  }
  if (auto r = root.optionalChild("expect")) readExpect(*r, s.expect, s.duration);
  root.finish();
  checkScenario(s);
  return s;
}

}  // namespace

std::string defaultConfigPath() { return (fs::path(HANDOVER_SOURCE_DIR) / "config" / "controller.yaml").string(); }

Scenario parseScenario(const std::string& path) { return readScenario(YamlReader::loadFile(path)); }

Scenario parseScenarioString(const std::string& text, const std::string& origin) {
  return readScenario(YamlReader::loadString(text, origin));
}

}  // namespace handover::scenario
