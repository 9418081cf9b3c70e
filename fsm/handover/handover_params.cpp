#include "fsm/handover/handover_params.hpp"

#include <algorithm>
#include <cmath>

namespace handover::fsm {

double HandoverParams::gripForce(double mass, const Vector3& com_in_tcp) const {
  const double load = grip_margin * mass * (gravity + grip_acceleration);
  const double lever = std::hypot(com_in_tcp.x(), com_in_tcp.z());  // from the closing axis (TCP y)
  const double f = std::max(load / (2.0 * grip_friction), load * lever / (2.0 * grip_torsional_friction));
  return std::min(grip_max_force, std::max(grip_min_force, f));
}

bool Workspace::contains(const Vector3& p, double margin) const {
  return (p - center).norm() <= radius + margin && (p.array() >= box_min.array() - margin).all() &&
         (p.array() <= box_max.array() + margin).all();
}

Isometry readPose(const YamlReader& node) {
  if (!node.isMap()) node.fail("expected {pos: [x, y, z], rpy: [roll, pitch, yaw]}");
  const Vector3 pos = node.child("pos").asVector(3);
  Vector3 rpy = Vector3::Zero();
  if (auto r = node.optionalChild("rpy")) rpy = r->asVector(3);
  node.finish();
  Isometry T = Isometry::Identity();
  T.translation() = pos;
  T.linear() = (Eigen::AngleAxisd(rpy.z(), Vector3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vector3::UnitY()) *
                Eigen::AngleAxisd(rpy.x(), Vector3::UnitX()))
                   .toRotationMatrix();
  return T;
}

namespace {
double positive(const YamlReader& parent, const char* key, double hi) {
  const YamlReader c = parent.child(key);
  const double v = c.asDouble();
  if (!(v > 0.0)) c.fail("must be > 0, got " + std::to_string(v));
  return c.checkRange(v, 0.0, hi);
}
double inRange(const YamlReader& parent, const char* key, double lo, double hi) {
  const YamlReader c = parent.child(key);
  return c.checkRange(c.asDouble(), lo, hi);
}
}  // namespace

HandoverParams loadHandoverParams(const YamlReader& n) {
  if (!n.isMap()) n.fail("expected a map of handover parameters");
  HandoverParams p;
  const YamlReader ws = n.child("workspace");
  p.workspace.center = ws.child("center").asVector(3);
  p.workspace.radius = positive(ws, "radius", 2.0);
  p.workspace.box_min = ws.child("box_min").asVector(3);
  p.workspace.box_max = ws.child("box_max").asVector(3);
  if (!(p.workspace.box_min.array() < p.workspace.box_max.array()).all()) {
    ws.child("box_max").fail("box_max must exceed box_min on every axis");
  }
  ws.finish();
  p.reach_radius = positive(n, "reach_radius", 2.0);
  {
    const YamlReader r = n.child("max_retries");
    p.max_retries = static_cast<int>(r.checkRange(r.asInt(), 0, 100));
  }
  if (auto t = n.optionalChild("tracking")) {
    // at most 1000 1/s^2: critically damped at the 1 ms period that is K dt^2 = 1e-3, far
    // inside the PD bound (control/controller_config_bounds.hpp; a test holds it)
    p.tracking_translation_stiffness = inRange(*t, "translation_stiffness", 0.0, 1000.0);
    p.tracking_orientation_stiffness = inRange(*t, "orientation_stiffness", 0.0, 1000.0);
    if (auto align = t->optionalChild("align")) {
      p.align_tracking_translation_stiffness = inRange(*align, "translation_stiffness", 0.0, 1000.0);
      p.align_tracking_orientation_stiffness = inRange(*align, "orientation_stiffness", 0.0, 1000.0);
      if (align->has("max_speed")) p.align_tracking_max_speed = inRange(*align, "max_speed", 0.01, 5.0);
      if (auto closing = align->optionalChild("closing")) {
        p.closing_tracking_translation_stiffness = inRange(*closing, "translation_stiffness", 0.0, 1000.0);
        p.closing_tracking_orientation_stiffness = inRange(*closing, "orientation_stiffness", 0.0, 1000.0);
        closing->finish();
      } else {  // the fingers close at the align gains
        p.closing_tracking_translation_stiffness = p.align_tracking_translation_stiffness;
        p.closing_tracking_orientation_stiffness = p.align_tracking_orientation_stiffness;
      }
      align->finish();
    }
    if (auto a = t->optionalChild("anticipate_reach")) p.anticipate_reach = a->asBool();
    if (auto arrive = t->optionalChild("arrive")) {
      p.arrive_tracking_translation_stiffness = inRange(*arrive, "translation_stiffness", 0.0, 1000.0);
      p.arrive_tracking_orientation_stiffness = inRange(*arrive, "orientation_stiffness", 0.0, 1000.0);
      p.arrive_speed = inRange(*arrive, "speed", 0.001, 5.0);
      if (auto take = arrive->optionalChild("take")) {
        p.take_arrive_tracking_translation_stiffness = inRange(*take, "translation_stiffness", 0.0, 1000.0);
        p.take_arrive_tracking_orientation_stiffness = inRange(*take, "orientation_stiffness", 0.0, 1000.0);
        p.take_arrive_speed = take->has("speed") ? inRange(*take, "speed", 0.001, 5.0) : p.arrive_speed;
        take->finish();
      }
      arrive->finish();
    }
    t->finish();
  }
  const YamlReader g = n.child("gripper");
  p.gripper_open_width = inRange(g, "open_width", 0.0, 0.08);
  p.gripper_close_width = inRange(g, "close_width", 0.0, 0.08);
  if (p.gripper_close_width >= p.gripper_open_width) g.child("close_width").fail("must be below open_width");
  p.gripper_force = positive(g, "force", 140.0);
  if (g.has("closing_speed")) p.gripper_closing_speed = positive(g, "closing_speed", 1.0);
  if (g.has("empty_width")) p.gripper_empty_width = inRange(g, "empty_width", 0.0, 0.08);
  if (g.has("finger_half_span")) p.finger_half_span = inRange(g, "finger_half_span", 0.0, 0.05);
  if (g.has("pad_reach")) p.finger_pad_reach = inRange(g, "pad_reach", 0.0, 0.05);
  if (g.has("grip_depth")) p.grip_depth = inRange(g, "grip_depth", 0.0, 0.05);
  {
    const YamlReader grip = g.child("grip");
    p.grip_friction = positive(grip, "friction", 2.0);
    if (grip.has("torsional_friction")) p.grip_torsional_friction = positive(grip, "torsional_friction", 0.1);
    p.grip_margin = inRange(grip, "margin", 1.0, 10.0);
    p.grip_acceleration = inRange(grip, "acceleration", 0.0, 50.0);
    p.grip_min_force = positive(grip, "min_force", 140.0);
    p.grip_max_force = positive(grip, "max_force", 140.0);
    if (p.grip_max_force < p.grip_min_force) grip.child("max_force").fail("must be at least min_force");
    grip.finish();
  }
  g.finish();
  const YamlReader ft = n.child("ft");
  p.ft_filter_tau = inRange(ft, "filter_tau", 0.0, 1.0);
  {
    const YamlReader s = ft.child("gravity_sign");
    p.ft_gravity_sign = s.asDouble();
    if (p.ft_gravity_sign != 1.0 && p.ft_gravity_sign != -1.0) s.fail("must be -1 or 1");
  }
  p.gravity = positive(ft, "gravity", 20.0);
  ft.finish();
  const YamlReader w = n.child("withdraw");
  p.max_data_age = positive(w, "max_data_age", 5.0);
  p.stale_timeout = positive(w, "stale_timeout", 10.0);
  p.withdraw_speed = positive(w, "speed", 5.0);
  if (auto d = w.optionalChild("distance")) p.withdraw_distance = d->checkRange(d->asDouble(), 0.0, 1.0);
  if (auto m = w.optionalChild("workspace_margin")) p.withdraw_workspace_margin = m->checkRange(m->asDouble(), 0.0, 0.5);
  if (auto r = w.optionalChild("home_radius")) p.withdraw_home_radius = r->checkRange(r->asDouble(), 0.0, 0.5);
  if (auto a = w.optionalChild("away_time_constant")) p.away_time_constant = a->checkRange(a->asDouble(), 0.0, 2.0);
  if (auto f = w.optionalChild("take_back_force")) p.take_back_force = f->checkRange(f->asDouble(), 0.0, 200.0);
  w.finish();
  const YamlReader poses = n.child("poses");
  p.stow_pose = readPose(poses.child("stow"));
  p.safe_pose = readPose(poses.child("safe"));
  p.ready_pose = readPose(poses.child("ready"));
  poses.finish();
  p.object_in_hand = readPose(n.child("object_in_hand"));
  if (auto s = n.optionalChild("object_in_hand_seat")) p.object_in_hand_seat = s->checkRange(s->asDouble(), 0.0, 0.1);
  if (auto r = n.optionalChild("release_ride")) p.release_ride = r->asBool();
  if (auto c = n.optionalChild("carry")) {
    p.carry_joint_speed = inRange(*c, "joint_speed", 0.0, 2.6);
    if (c->has("joint_acceleration")) p.carry_joint_acceleration = inRange(*c, "joint_acceleration", 0.1, 15.0);
    p.carry_min_duration = inRange(*c, "min_duration", 0.05, 10.0);
    c->finish();
  }
  n.finish();
  return p;
}

}  // namespace handover::fsm
