#include "app/generate/scenario_generator.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include "app/report/output_files.hpp"
#include "app/validate/scenario_validation.hpp"
#include "config/input_error.hpp"
#include "scenes/scenario/body_dimensions.hpp"
#include "scenes/scenario/scenario.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace handover::app {

namespace {

using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr int kMaxDraws = 200;
const Vector3d kRobotShoulder(0.0, 0.0, 0.333);  // Panda joint 2 axis height (facts file)

// splitmix64: small, fast, and the same numbers on every platform (the
// standard distributions are not specified bit for bit)
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double a, double b) { return a + (b - a) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }
  /// index drawn with the given relative weights
  int pick(std::initializer_list<double> weights) {
    double total = 0.0;
    for (double w : weights) total += w;
    double u = uniform(0.0, total);
    int i = 0;
    for (double w : weights) {
      if (u < w) return i;
      u -= w;
      ++i;
    }
    return i - 1;
  }

 private:
  std::uint64_t state_;
};

std::uint64_t drawSeed(std::uint64_t seed, int index, int attempt) {
  Rng r(seed * 0x100000001B3ull ^ (static_cast<std::uint64_t>(index) << 20) ^ static_cast<std::uint64_t>(attempt));
  r.next();
  return r.next();
}

// ---- text ------------------------------------------------------------------

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", v);
  std::string s = b;
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}
std::string vec(const Vector3d& v) { return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]"; }
Vector3d rpyOf(const Matrix3d& R) {
  // R = Rz(yaw) Ry(pitch) Rx(roll), the scenario convention
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}
std::string pose(const Vector3d& p, const Matrix3d& R) { return "{pos: " + vec(p) + ", rpy: " + vec(rpyOf(R)) + "}"; }

// ---- the draw ---------------------------------------------------------------

struct ObjectDraw {
  std::string shape, family;
  std::vector<double> size;
  double mass = 0.3;
  Isometry3d grasp = Isometry3d::Identity();  // in the object frame
  bool free_z = false;
  Vector3d grip_in_object = Vector3d::Zero();  // where the person's grip point sits (take)
  bool sphere_on_palm = false;                  // the ball rests on the palm: offset is vertical in the world
};

// support: farthest extent of the object along unit direction d (object frame)
double support(const ObjectDraw& o, const Vector3d& d) {
  if (o.shape == "sphere") return o.size[0];
  if (o.shape == "box") return 0.5 * (std::abs(d.x()) * o.size[0] + std::abs(d.y()) * o.size[1] + std::abs(d.z()) * o.size[2]);
  return 0.5 * o.size[1] * std::abs(d.z()) + o.size[0] * std::hypot(d.x(), d.y());
}

// radius of the smallest sphere about the object's centre that holds it
double circumradius(const ObjectDraw& o) {
  if (o.shape == "sphere") return o.size[0];
  if (o.shape == "box") return 0.5 * std::sqrt(o.size[0] * o.size[0] + o.size[1] * o.size[1] + o.size[2] * o.size[2]);
  return std::hypot(o.size[0], 0.5 * o.size[1]);
}

Matrix3d graspRotation(const std::string& family) {
  // grasp z = approach, y = finger closing; about the object's y axis
  const double pitch = family == "top" ? kPi : family == "angled" ? 0.75 * kPi : 0.5 * kPi;
  return AngleAxisd(pitch, Vector3d::UnitY()).toRotationMatrix();
}

ObjectDraw drawObject(Rng& rng, bool take) {
  ObjectDraw o;
  const int shape = rng.pick({0.45, 0.30, 0.25});
  o.shape = shape == 0 ? "cylinder" : shape == 1 ? "box" : "sphere";
  // around_axis is how a person presents a lying object; an object the robot
  // holds has no presentation of the person's, so a give takes the other three
  if (o.shape == "cylinder" && take) {
    o.family = std::vector<std::string>{"top", "side", "angled", "around_axis"}[static_cast<std::size_t>(rng.pick({1, 1, 1, 1}))];
  } else {
    o.family = std::vector<std::string>{"top", "side", "angled"}[static_cast<std::size_t>(rng.pick({1, 1, 1}))];
  }
  const bool top = o.family == "top";
  double volume = 0.0;
  if (o.shape == "cylinder" && o.family == "around_axis") {
    // a baton or a bottle carried lying: held at one end, the other end offered
    const double r = rng.uniform(0.015, 0.03), len = rng.uniform(0.18, 0.32);
    o.size = {r, len};
    o.free_z = true;
    o.grasp.linear() = graspRotation("side");
    o.grasp.translation() = Vector3d(0, 0, 0.5 * len - 0.06);
    o.grip_in_object = Vector3d(0, 0, -0.5 * len + 0.045);
    volume = kPi * r * r * len;
  } else if (o.shape == "cylinder" || o.shape == "box") {
    // upright; the person grips the lower part, the robot takes the upper part
    const double h = top ? rng.uniform(0.12, 0.25) : rng.uniform(0.15, 0.25);
    if (o.shape == "cylinder") {
      const double r = rng.uniform(0.02, 0.035);
      o.size = {r, h};
      o.free_z = rng.chance(0.7);
      volume = kPi * r * r * h;
    } else {
      const double depth = rng.uniform(0.035, 0.10), width = rng.uniform(0.035, 0.07);  // width across the fingers
      o.size = {depth, width, h};
      volume = depth * width * h;
    }
    o.grasp.linear() = graspRotation(o.family);
    const double below_top = top ? std::min(0.04, 0.3 * h) : o.family == "angled" ? 0.045 : 0.035;
    o.grasp.translation() = Vector3d(0, 0, 0.5 * h - below_top);
    o.grip_in_object = Vector3d(0, 0, -0.5 * h + rng.uniform(0.02, 0.035));
  } else {
    const double r = rng.uniform(0.025, 0.035);
    o.size = {r};
    o.free_z = rng.chance(0.7);
    o.grasp.linear() = graspRotation(o.family);
    o.sphere_on_palm = true;
    o.grip_in_object = Vector3d(0, 0, -(r + 0.015));  // resting on the palm (the hand is 3 cm thick)
    volume = 4.0 / 3.0 * kPi * r * r * r;
  }
  // 0.1-1.0 kg, and no denser than steel
  o.mass = std::min(rng.uniform(0.1, 1.0), std::max(0.1, 7800.0 * volume));
  return o;
}

struct Person {
  double height = 1.75;
  bool right = true;
  Vector2d stand{1.0, 0.0};
  double yaw = kPi;
  Vector3d shoulder = Vector3d::Zero();
  double reach = 0.7;
};

Person drawPerson(Rng& rng) {
  Person p;
  p.height = rng.uniform(1.50, 2.00);
  p.right = rng.chance(0.5);
  const int where = rng.pick({0.40, 0.35, 0.25});
  if (where == 0) {  // in front, beyond the table's far edge (x = 0.75)
    p.stand = Vector2d(rng.uniform(0.95, 1.15), rng.uniform(-0.15, 0.15));
  } else if (where == 1) {  // off to one side of the far end
    p.stand = Vector2d(rng.uniform(0.95, 1.15), rng.sign() * rng.uniform(0.15, 0.45));
  } else {  // beside the table (|y| = 0.5)
    p.stand = Vector2d(rng.uniform(0.30, 0.70), rng.sign() * rng.uniform(0.75, 0.90));
  }
  // facing the robot's workspace, turned by up to +-30 degrees
  const Vector2d toward = Vector2d(0.45, 0.0) - p.stand;
  p.yaw = std::atan2(toward.y(), toward.x()) + rng.uniform(-30.0, 30.0) * kDeg;
  const scenario::BodyDimensions body = scenario::bodyDimensionsFromHeight(p.height);
  p.shoulder = scenario::shoulderPosition(body, p.stand, p.yaw,
                                          p.right ? scenario::HandSide::Right : scenario::HandSide::Left);
  p.reach = body.reach();
  return p;
}

struct Presentation {
  Vector3d grip = Vector3d::Zero();  // hand grip point, world
  Matrix3d hand = Matrix3d::Identity();
  Matrix3d object = Matrix3d::Identity();  // object in the world
  Vector3d object_pos = Vector3d::Zero();
};

double azimuth(const Vector3d& v) { return std::atan2(v.y(), v.x()); }

Matrix3d objectOrientation(Rng& rng, const ObjectDraw& o, const Vector3d& grip) {
  if (o.family == "around_axis") {
    // lying, its +z end pointing toward the robot (+-60 deg), tilted by up to
    // 25 deg, turned about its own axis at random (the axis is free)
    const double psi = azimuth(-grip) + rng.uniform(-60.0, 60.0) * kDeg;
    return (AngleAxisd(psi, Vector3d::UnitZ()) * AngleAxisd(0.5 * kPi + rng.uniform(-25.0, 25.0) * kDeg, Vector3d::UnitY()) *
            AngleAxisd(rng.uniform(-kPi, kPi), Vector3d::UnitZ()))
        .toRotationMatrix();
  }
  // upright, tilted by up to 25 deg about a random horizontal axis; a side or
  // angled approach comes from the robot's side turned by up to 60 deg about
  // the vertical (any turn when the object is free about its axis)
  const double psi = o.free_z ? rng.uniform(-kPi, kPi) : azimuth(grip) + rng.uniform(-60.0, 60.0) * kDeg;
  const double beta = rng.uniform(-kPi, kPi);
  const Vector3d tilt_axis(std::cos(beta), std::sin(beta), 0.0);
  return (AngleAxisd(rng.uniform(0.0, 25.0) * kDeg, tilt_axis) * AngleAxisd(psi, Vector3d::UnitZ())).toRotationMatrix();
}

// object centre from the grip point
Vector3d objectCentre(const ObjectDraw& o, const Vector3d& grip, const Matrix3d& R) {
  if (o.sphere_on_palm) return grip - o.grip_in_object;  // the ball sits on the palm whatever the tilt
  return grip - R * o.grip_in_object;
}

bool insideTable(const Vector3d& p) { return p.x() > -0.35 && p.x() < 0.75 && std::abs(p.y()) < 0.5; }

/// A handover location the person reaches comfortably and the robot can
/// reach, with the object clear of the table; false if none was found.
bool drawPresentation(Rng& rng, const ObjectDraw& o, const Person& person, bool take, Presentation& out) {
  const Vector2d facing(std::cos(person.yaw), std::sin(person.yaw));
  const double chest = 0.72 * person.height + scenario::kFloorZ;
  for (int i = 0; i < 400; ++i) {
    const Vector3d grip(rng.uniform(0.20, 0.90), rng.uniform(-0.60, 0.60), rng.uniform(0.05, chest));
    const double from_shoulder = (grip - person.shoulder).norm();
    if (from_shoulder < 0.40 * person.reach || from_shoulder > 0.90 * person.reach) continue;
    if ((grip.head<2>() - person.stand).dot(facing) < 0.20) continue;  // in front of the body
    const Matrix3d R = objectOrientation(rng, o, grip);
    const Vector3d centre = objectCentre(o, grip, R);
    const double lowest = centre.z() - support(o, R.transpose() * Vector3d::UnitZ());
    if (lowest < 0.05 || grip.z() - 0.05 < 0.03) continue;  // just above the table, the hand too
    // the robot: where its fingers go (take), or where it brings the object (give)
    const Vector3d g = centre + R * o.grasp.translation();
    const Vector3d target = take ? g : grip;
    if ((target - kRobotShoulder).norm() > 0.75 || target.head<2>().norm() < 0.25 || target.x() < 0.15) continue;
    if (take) {
      const Vector3d approach = R * o.grasp.linear().col(2);
      if ((g - 0.10 * approach - kRobotShoulder).norm() > 0.80) continue;
      const double clearance = (g - grip).norm();
      if (clearance < (o.shape == "sphere" ? 0.04 : 0.06)) continue;  // fingers clear of the person's hand
    }
    out.grip = grip;
    out.object = R;
    out.object_pos = centre;
    out.hand = AngleAxisd(person.yaw + kPi + rng.uniform(-0.3, 0.3), Vector3d::UnitZ()).toRotationMatrix();
    return true;
  }
  return false;
}

struct Script {
  std::ostringstream text;
  double time = 0.0;  // scripted seconds (waits counted at their delay)
  // "    - reach:    {" with the bodies aligned
  std::ostream& item(const std::string& kind) {
    return text << "    - " << kind << ":" << std::string(kind.size() < 9 ? 9 - kind.size() : 1, ' ') << "{";
  }
  void reach(const char* kind, const Vector3d& p, const Matrix3d* R, double d) {
    item(kind) << "pos: " << vec(p);
    if (R) text << ", rpy: " << vec(rpyOf(*R));
    text << ", duration: " << num(d) << "}\n";
    time += d;
  }
  void hold(double d) {
    item("hold") << "duration: " << num(d) << "}\n";
    time += d;
  }
  void wait(const char* until, double timeout, double delay) {
    item("wait") << "until: " << until << ", timeout: " << num(timeout) << ", delay: " << num(delay) << "}\n";
    time += delay + 1.5;  // the robot's part, roughly
  }
  void step(const char* name) { item(name) << "}\n"; }
  void pull(const Vector3d& dir, double dist, double d) {
    item("pull") << "dir: " << vec(dir) << ", distance: " << num(dist) << ", duration: " << num(d) << "}\n";
    time += d;
  }
};

const char* kTakeBehaviours[] = {"plain", "moving", "retry", "abort", "late_release", "sensing"};
const char* kGiveBehaviours[] = {"plain", "moving", "retry", "abort", "late_pull", "sensing"};

std::string drawText(Rng& rng, std::uint64_t seed, int index, bool take, std::string& name) {
  const ObjectDraw o = drawObject(rng, take);
  const int b = rng.pick({0.30, 0.14, 0.12, 0.10, 0.12, 0.22});
  const std::string behaviour = take ? kTakeBehaviours[b] : kGiveBehaviours[b];
  Person person;
  Presentation at;
  bool found = false;
  for (int k = 0; k < 20 && !found; ++k) {
    person = drawPerson(rng);
    found = drawPresentation(rng, o, person, take, at);
  }
  if (!found) return "";

  char idx[16];
  std::snprintf(idx, sizeof idx, "%05d", index);
  name = "g" + std::to_string(seed) + "_" + idx + "_" + (take ? "take" : "give") + "_" + o.family + "_" + o.shape + "_" +
         behaviour;

  // the hand at rest beside the body, before and after
  const Vector2d facing(std::cos(person.yaw), std::sin(person.yaw));
  const Vector2d outward = (person.right ? 1.0 : -1.0) * Vector2d(facing.y(), -facing.x());
  const Vector2d rest_xy = person.stand + 0.18 * facing + 0.22 * outward;
  Vector3d rest(rest_xy.x(), rest_xy.y(), 0.50 * person.height + scenario::kFloorZ);
  if (insideTable(rest)) rest.z() = std::max(rest.z(), 0.15);
  // the object the resting hand holds (take: before the reach; give: after
  // the withdraw) stays 3 cm above the table's height: the straight reach
  // between rest and handover would otherwise sweep it through the table's
  // edge or top
  double lowest = 0.0;
  if (take) {
    // it hangs where it hangs at the handover, shifted
    const Vector3d centre = at.object_pos + (rest - at.grip);
    lowest = centre.z() - support(o, at.object.transpose() * Vector3d::UnitZ());
  } else {
    // held where the robot put it: it rests in or on the hand, its centre at
    // or above the grip point (4-5 cm above in the benchmark's gives)
    lowest = rest.z() - circumradius(o);
  }
  if (lowest < 0.03) rest.z() += 0.03 - lowest;

  // how the person moves
  Script s;
  s.hold(rng.uniform(take ? 0.2 : 0.3, take ? 0.8 : 1.2));  // reaction time
  const double reach_time = rng.uniform(0.5, 2.0);
  auto moveTo = [&](const Vector3d& p, double d) { s.reach("reach", p, &at.hand, d); };
  auto nearby = [&](double lo, double hi) {
    const Vector3d dir = Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.5, 0.5)).normalized();
    return Vector3d(at.grip + rng.uniform(lo, hi) * dir);
  };
  if (behaviour == "moving") {
    moveTo(nearby(0.08, 0.15), reach_time);
    if (rng.chance(0.5)) moveTo(nearby(0.05, 0.12), rng.uniform(0.4, 0.9));
    moveTo(at.grip, rng.uniform(0.4, 0.9));
  } else {
    moveTo(at.grip, reach_time);
  }
  if (behaviour == "retry" || behaviour == "abort") {
    s.hold(rng.uniform(0.1, 0.5));
    s.reach("withdraw", rest, nullptr, rng.uniform(0.7, 1.1));
    if (behaviour == "abort") {
      s.hold(8.0);
    } else {
      s.hold(rng.uniform(0.8, 2.0));
      moveTo(nearby(0.0, 0.03), rng.uniform(0.6, 1.4));
    }
  }
  if (behaviour != "abort") {
    if (take) {
      const double delay = behaviour == "late_release" ? rng.uniform(1.5, 3.0) : rng.uniform(0.05, 0.2);
      s.wait("fingers_on_object", 10.0, delay);
      s.step("release");
    } else {
      s.wait("object_in_reach", 10.0, rng.uniform(0.1, 0.3));
      s.step("grasp");
      s.hold(behaviour == "late_pull" ? rng.uniform(2.0, 4.0) : rng.uniform(0.1, 0.4));
      Vector3d dir = person.shoulder - at.grip;
      dir.z() = 0.0;
      s.pull(dir.normalized(), rng.uniform(0.06, 0.15), rng.uniform(0.4, 0.8));
      s.wait("object_free", 3.0, 0.0);
    }
    s.reach("withdraw", rest, nullptr, rng.uniform(0.8, 1.2));
  }

  std::ostringstream y;
  y << "# Generated by `handover generate --seed " << seed << "` (file " << index
    << "); distribution: docs/benchmark.md\n";
  y << "name: " << name << "\n";
  y << "mode: " << (take ? "human_to_robot" : "robot_to_human") << "\n";
  y << "behaviour: " << behaviour << "\n";
  y << "duration: " << num(std::min(60.0, std::ceil(s.time + (take ? 14.0 : 16.0)))) << "\n";
  y << "seed: " << (seed * 7919 + static_cast<std::uint64_t>(index)) % 2147483647ull << "\n\n";
  y << "object:\n  shape: " << o.shape << "\n  size: [";
  for (std::size_t i = 0; i < o.size.size(); ++i) y << (i ? ", " : "") << num(o.size[i]);
  y << "]\n  mass: " << num(o.mass) << "\n";
  y << "  grasp: " << pose(o.grasp.translation(), o.grasp.linear()) << "   # " << o.family << "\n";
  if (o.free_z) y << "  free_axis: z\n";
  y << "\nrobot:\n  holds_object: " << (take ? "false" : "true") << "\n\n";
  y << "human:\n  stand: {pos: [" << num(person.stand.x()) << ", " << num(person.stand.y()) << "], yaw: " << num(person.yaw)
    << "}\n";
  y << "  height: " << num(person.height) << "\n  hand: " << (person.right ? "right" : "left") << "\n";
  y << "  start: " << pose(rest, at.hand) << "\n";
  if (take) {
    // the object in the hand frame, from its pose in the world at the presentation
    const Matrix3d R = at.hand.transpose() * at.object;
    const Vector3d p = at.hand.transpose() * (at.object_pos - at.grip);
    y << "  holds_object: " << pose(p, R) << "\n";
  }
  y << "  script:\n" << s.text.str() << "\n";

  // sensing: ordinary, or degraded for the `sensing` behaviour
  const bool degraded = behaviour == "sensing";
  const double rates[] = {30, 60, 90, 120};
  y << "sensor:\n  rate_hz: " << num(rates[rng.pick({0.2, 0.4, 0.2, 0.2})]) << "\n";
  y << "  latency: " << num(degraded ? rng.uniform(0.03, 0.10) : rng.uniform(0.0, 0.03)) << "\n";
  y << "  noise: {pos: " << num(degraded ? rng.uniform(0.002, 0.004) : rng.uniform(0.0005, 0.002))
    << ", rot_deg: " << num(degraded ? rng.uniform(1.0, 2.5) : rng.uniform(0.2, 1.0)) << "}\n";
  if (degraded && rng.chance(0.7)) {
    const double t0 = rng.uniform(0.3, 0.3 + reach_time), len = rng.uniform(0.2, 0.6);
    y << "  dropouts: [[" << num(t0) << ", " << num(t0 + len) << "]]\n";
  }
  if (degraded && rng.chance(0.7)) {
    const Vector3d dp(rng.uniform(-0.006, 0.006), rng.uniform(-0.006, 0.006), rng.uniform(-0.006, 0.006));
    const Vector3d dr(rng.uniform(-0.03, 0.03), rng.uniform(-0.03, 0.03), rng.uniform(-0.03, 0.03));
    y << "  offset: {pos: " << vec(dp) << ", rpy: " << vec(dr) << "}\n";
  }
  y << "\nexpect: {outcome: " << (behaviour == "abort" ? "aborted" : "success") << "}\n";
  return y.str();
}

}  // namespace

GenerateMode parseGenerateMode(const std::string& word) {
  if (word == "take") return GenerateMode::Take;
  if (word == "give") return GenerateMode::Give;
  if (word == "both") return GenerateMode::Both;
  throw std::invalid_argument("mode must be take, give or both, got '" + word + "'");
}

GeneratedScenario generateScenario(std::uint64_t seed, int index, GenerateMode mode) {
  std::string last_error;
  Rng direction(drawSeed(seed, index, -1));  // kept across redraws
  const bool take = mode == GenerateMode::Take ? true : mode == GenerateMode::Give ? false : direction.chance(0.5);
  for (int attempt = 0; attempt < kMaxDraws; ++attempt) {
    Rng rng(drawSeed(seed, index, attempt));
    GeneratedScenario g;
    g.yaml = drawText(rng, seed, index, take, g.name);
    g.draws = attempt + 1;
    if (g.yaml.empty()) continue;
    try {
      validateScenario(scenario::parseScenarioString(g.yaml, g.name + ".yaml"));  // what `check` does
      return g;
    } catch (const InputError& e) {
      last_error = e.what();  // e.g. a script target the person cannot reach: draw again
    }
  }
  throw std::runtime_error("generate: no valid scenario for seed " + std::to_string(seed) + ", index " +
                           std::to_string(index) + " in " + std::to_string(kMaxDraws) + " draws; last: " + last_error);
}

std::vector<std::string> generateScenarios(const GenerateOptions& opt) {
  namespace fs = std::filesystem;
  prepareOutputDir(opt.out_dir);
  std::vector<std::string> paths;
  paths.reserve(static_cast<std::size_t>(std::max(0, opt.count)));
  for (int i = 0; i < opt.count; ++i) {
    const GeneratedScenario g = generateScenario(opt.seed, i, opt.mode);
    const std::string path = (fs::path(opt.out_dir) / (g.name + ".yaml")).string();
    writeFileChecked(path, g.yaml);  // a failed write names the file and leaves no partial file
    paths.push_back(path);
  }
  return paths;
}

}  // namespace handover::app
