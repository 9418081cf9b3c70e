#include "control/grasp/grasp_selection_config.hpp"

#include <cmath>

namespace handover::control::grasp {

namespace {

constexpr double kDeg = M_PI / 180.0;

double positive(const YamlReader& r, const std::string& key, double def, double hi) {
  auto c = r.optionalChild(key);
  if (!c) return def;
  const double v = c->asDouble();
  if (!(v > 0.0)) c->fail("must be > 0, got " + std::to_string(v));
  return c->checkRange(v, 0.0, hi);
}

double nonNegative(const YamlReader& r, const std::string& key, double def, double hi) {
  auto c = r.optionalChild(key);
  return c ? c->checkRange(c->asDouble(), 0.0, hi) : def;
}

IkOptions readIk(const YamlReader& r, std::vector<Vector7>& seeds) {
  IkOptions o;
  if (auto c = r.optionalChild("max_iterations")) o.max_iterations = static_cast<int>(c->checkRange(c->asInt(), 1, 10000));
  o.position_tolerance = positive(r, "position_tolerance", o.position_tolerance, 0.01);
  o.orientation_tolerance = positive(r, "orientation_tolerance_deg", o.orientation_tolerance / kDeg, 5.0) * kDeg;
  o.orientation_weight = positive(r, "orientation_weight", o.orientation_weight, 10.0);
  o.damping = positive(r, "damping", o.damping, 1.0);
  o.max_step = positive(r, "max_step", o.max_step, M_PI);
  o.limit_clearance = nonNegative(r, "limit_clearance", o.limit_clearance, 0.5);
  o.nullspace_gain = nonNegative(r, "nullspace_gain", o.nullspace_gain, 1.0);
  o.nullspace_max_step = nonNegative(r, "nullspace_max_step", o.nullspace_max_step, M_PI);
  o.stall_ratio = nonNegative(r, "stall_ratio", o.stall_ratio, 1.0);
  if (auto c = r.optionalChild("stall_window")) o.stall_window = static_cast<int>(c->checkRange(c->asInt(), 1, 1000));
  if (auto c = r.optionalChild("seeds")) {
    if (!c->isSequence()) c->fail("expected a list of 7-joint configurations (rad)");
    seeds.clear();
    for (std::size_t i = 0; i < c->size(); ++i) seeds.push_back(c->at(i).asVector(kArmDofs));
  }
  r.finish();
  return o;
}

PalmGeometry readPalm(const YamlReader& r) {
  PalmGeometry g;
  g.depth = positive(r, "depth", g.depth, 0.5);
  g.half_width = positive(r, "half_width", g.half_width, 0.5);
  g.half_length = positive(r, "half_length", g.half_length, 0.5);
  g.clearance = nonNegative(r, "clearance", g.clearance, 0.1);
  r.finish();
  return g;
}

CandidateOptions readCandidates(const YamlReader& r, PalmGeometry& palm) {
  CandidateOptions o;
  o.free_axis_step = positive(r, "free_axis_step_deg", o.free_axis_step / kDeg, 180.0) * kDeg;
  o.parallel_gripper_twin = r.getBool("parallel_gripper_twin", o.parallel_gripper_twin);
  o.pre_grasp_standoff = nonNegative(r, "pre_grasp_standoff", o.pre_grasp_standoff, 0.5);
  if (auto c = r.optionalChild("palm")) palm = readPalm(*c);
  r.finish();
  return o;
}

ScoreWeights readScore(const YamlReader& r) {
  ScoreWeights w;
  w.joint_margin = nonNegative(r, "joint_margin", w.joint_margin, 1e3);
  w.margin_ref = positive(r, "margin_ref", w.margin_ref, 3.0);
  w.manipulability = nonNegative(r, "manipulability", w.manipulability, 1e3);
  w.manipulability_ref = positive(r, "manipulability_ref", w.manipulability_ref, 1.0);
  w.motion = nonNegative(r, "motion", w.motion, 1e3);
  w.motion_ref = positive(r, "motion_ref", w.motion_ref, 20.0);
  w.clearance = nonNegative(r, "clearance", w.clearance, 1e3);
  w.clearance_ref = positive(r, "clearance_ref", w.clearance_ref, 2.0);
  w.shortfall = nonNegative(r, "shortfall", w.shortfall, 1e3);
  w.shortfall_ref = positive(r, "shortfall_ref", w.shortfall_ref, 0.5);
  w.exit = nonNegative(r, "exit", w.exit, 1e3);
  r.finish();
  return w;
}

UprightOptions readUpright(const YamlReader& r) {
  UprightOptions o;
  o.yaw_step = positive(r, "yaw_step_deg", o.yaw_step / kDeg, 180.0) * kDeg;
  o.tilt_tolerance = positive(r, "tilt_tolerance_deg", o.tilt_tolerance / kDeg, 90.0) * kDeg;
  if (auto c = r.optionalChild("position_offsets")) {
    if (!c->isSequence() || c->size() == 0) c->fail("expected a non-empty list of [x, y, z] offsets (m)");
    o.position_offsets.clear();
    for (std::size_t i = 0; i < c->size(); ++i) o.position_offsets.push_back(c->at(i).asVector(3));
  }
  r.finish();
  return o;
}

}  // namespace

GraspSelectionConfig graspSelectionConfigFrom(const YamlReader& root) {
  if (!root.isMap()) root.fail("expected a map at the top level");
  GraspSelectionConfig c;
  c.frame = root.getString("frame", c.frame);
  if (auto r = root.optionalChild("ik")) c.ik = readIk(*r, c.seeds);
  if (auto r = root.optionalChild("candidates")) c.candidates = readCandidates(*r, c.palm);
  if (auto r = root.optionalChild("score")) c.score = readScore(*r);
  if (auto r = root.optionalChild("table")) {
    if (auto h = r->optionalChild("height")) c.table_height = h->checkRange(h->asDouble(), -10.0, 10.0);
    c.table_clearance = nonNegative(*r, "clearance", c.table_clearance, 1.0);
    r->finish();
  }
  c.hysteresis = nonNegative(root, "hysteresis", c.hysteresis, 1e3);
  if (auto r = root.optionalChild("keep_tolerance")) {
    c.keep_tolerance.position = nonNegative(*r, "position", c.keep_tolerance.position, 0.05);
    c.keep_tolerance.orientation =
        nonNegative(*r, "orientation_deg", c.keep_tolerance.orientation / kDeg, 10.0) * kDeg;
    r->finish();
  }
  c.declared_preference = nonNegative(root, "declared_preference", c.declared_preference, 1e3);
  if (auto r = root.optionalChild("cold_solves_per_update")) {
    c.cold_solves_per_update = static_cast<int>(r->checkRange(r->asInt(), 0, 100000));
  }
  if (auto r = root.optionalChild("branch_solves_per_update")) {
    c.branch_solves_per_update = static_cast<int>(r->checkRange(r->asInt(), 0, 100000));
  }
  if (auto r = root.optionalChild("upright")) c.upright = readUpright(*r);
  if (auto r = root.optionalChild("presentation_tilt_deg")) c.presentation_tilt = r->checkRange(r->asDouble(), 0.0, 60.0) * kDeg;
  root.finish();
  return c;
}

GraspSelectionConfig loadGraspSelectionConfig(const std::string& path) {
  return graspSelectionConfigFrom(YamlReader::loadFile(path));
}

}  // namespace handover::control::grasp
