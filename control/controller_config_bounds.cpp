#include "control/controller_config_bounds.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>


namespace handover::control {

namespace {

// spectral radius of the one-step map of e'' = -K e - D e' over dt
double radius(const Eigen::Matrix2d& a) { return a.eigenvalues().cwiseAbs().maxCoeff(); }

double exactStepRadius(double k, double d, double dt) {
  // constant acceleration over the step: e+ = e + dt v + dt^2/2 a, v+ = v + dt a
  Eigen::Matrix2d a;
  a << 1.0 - k * dt * dt / 2.0, dt - d * dt * dt / 2.0, -k * dt, 1.0 - d * dt;
  return radius(a);
}

double semiImplicitRadius(double k, double d, double dt) {
  // v+ = v + dt a, e+ = e + dt v+
  Eigen::Matrix2d a;
  a << 1.0 - k * dt * dt, dt * (1.0 - d * dt), -k * dt, 1.0 - d * dt;
  return radius(a);
}

std::string num(double v) {
  std::ostringstream os;
  os.precision(4);
  os << v;
  return os.str();
}

// fails at the deepest present node of the dotted `key` (its file line), or
// at the root when the setting is a default
[[noreturn]] void failAt(const YamlReader& root, const std::string& key, const std::string& message) {
  YAML::Node cur = root.node();
  YAML::Node found = root.node();
  std::string path, found_path;
  std::stringstream ss(key);
  std::string part;
  while (std::getline(ss, part, '.')) {
    if (!cur.IsMap()) break;
    const YAML::Node next = cur[part];
    if (!next.IsDefined()) break;
    cur.reset(next);
    path += (path.empty() ? "" : ".") + part;
    found.reset(cur);
    found_path = path;
  }
  YamlReader(found, root.file(), found_path.empty() ? key : found_path).fail(message);
}

}  // namespace

std::string pdGainsProblem(double k, double d, double dt) {
  if (!(k > 0.0) || !(d >= 0.0) || !(dt > 0.0)) return "stiffness must be > 0 and damping >= 0";
  const double disc = d * d - 4.0 * k;
  const double fastest = disc >= 0.0 ? (d + std::sqrt(disc)) / 2.0 : std::sqrt(k);
  if (fastest * dt > kMaxPolePeriod) {
    return "stiffness " + num(k) + " / damping " + num(d) + " make a pole of " + num(fastest) +
           " 1/s, too fast for the period " + num(dt) + " s (need |pole| x period <= " + num(kMaxPolePeriod) +
           "; with critical damping, stiffness <= " + num(kMaxPolePeriod * kMaxPolePeriod / (dt * dt)) + ")";
  }
  // tolerance: for slow gains the radius is 1 - O(D dt) and rounding matters
  if (exactStepRadius(k, d, dt) > 1.0 + 1e-12 || semiImplicitRadius(k, d, dt) > 1.0 + 1e-12) {
    return "stiffness " + num(k) + " with damping " + num(d) + " is unstable at the period " + num(dt) +
           " s (the discrete loop grows; the damping must exceed stiffness x period / 2 = " + num(k * dt / 2.0) + ")";
  }
  return "";
}

void checkControllerBounds(const ControllerConfig& cfg, const YamlReader& root, const JointLimits& joints) {
  const double dt = cfg.period;
  auto gains = [&](const char* key, const PdGains& g) {
    const std::string p = pdGainsProblem(g.stiffness, g.damping, dt);
    if (!p.empty()) failAt(root, std::string(key) + ".stiffness", p);
  };
  gains("observation", cfg.observation.gains);
  gains("tracking.translation", cfg.tracking.translation.gains);
  gains("tracking.orientation", cfg.tracking.orientation.gains);
  gains("posture", cfg.posture.gains);
  gains("pose_task.translation", cfg.pose_task.translation.gains);
  gains("pose_task.orientation", cfg.pose_task.orientation.gains);
  // the damped stop qddot = -kd qdot over one period must not overshoot
  if (cfg.fallback.damping * dt > 1.0) {
    failAt(root, "fallback.damping", "fallback.damping " + num(cfg.fallback.damping) + " x period " + num(dt) +
              " > 1: the damped stop would reverse the joint velocity each step");
  }

  // the solver's pivot test needs the Hessian's smallest direction well above
  // 1e-13 x its largest (qp.regularisation comment in controller_config.hpp)
  const double w_max = std::max({cfg.observation.weight, cfg.tracking.weight, cfg.pose_task.weight, cfg.posture.weight});
  if (cfg.qp.regularisation < kMinRegularisationRatio * w_max) {
    failAt(root, "qp.regularisation", "qp.regularisation " + num(cfg.qp.regularisation) + " is below " + num(kMinRegularisationRatio) +
              " x the largest task weight (" + num(w_max) +
              "): the QP is singular whenever no task covers a direction (e.g. posture weight 0)");
  }
  // the observation task couples to the object's acceleration: it must dominate
  if (cfg.observation.weight < cfg.tracking.weight || cfg.observation.weight < cfg.pose_task.weight) {
    failAt(root, "observation.weight", "observation.weight " + num(cfg.observation.weight) +
              " must be at least the tracking and pose_task weights (the observed object would lag the sensor)");
  }
  // the posture resolves redundancy only; above the tracking weight it pulls the TCP off target
  if (cfg.posture.weight > cfg.tracking.weight || cfg.posture.weight > cfg.pose_task.weight) {
    failAt(root, "posture.weight", "posture.weight " + num(cfg.posture.weight) +
              " must not exceed the tracking and pose_task weights (the posture would win over the grasp)");
  }

  // the posture target lies where the position damper lets the arm go
  const double safety = cfg.limits.position.safety;
  for (int i = 0; i < kArmDofs; ++i) {
    const double range = joints.q_max[i] - joints.q_min[i];
    const double lo = joints.q_min[i] + safety * range, hi = joints.q_max[i] - safety * range;
    const double q = cfg.posture.target[i];
    if (!(q >= lo && q <= hi)) {
      failAt(root, "posture.target", "posture.target[" + std::to_string(i) + "] = " + num(q) + " rad is outside joint " +
                std::to_string(i + 1) + "'s limits less the safety zone [" + num(lo) + ", " + num(hi) + "]");
    }
  }
}

}  // namespace handover::control
