#include "control/wrench/contact_wrench.hpp"

#include <algorithm>
#include <cmath>

#include "control/model/rigid_inertia.hpp"

namespace handover::control {

ContactWrenchEstimator::ContactWrenchEstimator(const Model& model, const ContactWrenchSettings& settings,
                                               double period)
    : settings_(settings),
      tool_(model.tool),
      sensor_T_tcp_(model.frames[model.frameId("ft_sensor")].placement.inverse() *
                    model.frames[model.frameId("tcp")].placement),
      gravity_(model.gravity),
      alpha_(period / (std::max(0.0, settings.filter_tau) + period)),
      calibrator_(std::max(1, static_cast<int>(std::lround(settings.calibration_time / period)))),
      ff_step_(settings.ramp_time > 0.0 ? std::min(1.0, period / settings.ramp_time) : 1.0) {
  held_at_start_ = tool_;
}

Inertia ContactWrenchEstimator::objectInSensor(double share) const {
  Inertia in;
  in.mass = share * object_.mass;
  in.com = object_.com;
  in.inertia_com = share * object_.inertia_com;
  return transformInertia(in, sensor_T_tcp_);
}

void ContactWrenchEstimator::start(const Payload& object, bool holds) {
  object_ = object;
  held_at_start_ = holds ? combineInertia(tool_, objectInSensor(1.0)) : tool_;
  calibrator_.restart();
  holds_at_start_ = holds;
  calibrating_ = true;
  filtered_ = false;
  load_.setZero();
  interaction_.setZero();
  share_ = holds ? 1.0 : 0.0;
  payload_ = object_;
  payload_.mass = share_ * object_.mass;
  payload_.inertia_com = share_ * object_.inertia_com;
  feed_forward_.setZero();
  ff_gain_ = 0.0;
  disturbance_gain_ = 0.0;
}

void ContactWrenchEstimator::update(const ContactWrenchInput& in) {
  if (!in.reading.allFinite() || !in.sensor_rotation.allFinite() || !in.sensor_acceleration.allFinite()) return;
  const Matrix3& R = in.sensor_rotation;
  // calibrate only as the run started: at rest, the gripper as it was (empty and open, or
  // closed on the known object); once it changed, what it holds is no longer known
  if (in.gripper_closed != holds_at_start_) calibrating_ = false;
  if (calibrating_ && in.at_rest) calibrator_.add(in.reading, R, held_at_start_, gravity_);

  // 1-2. what the tool does not explain (offset zero until calibrated: trust the model meanwhile)
  const Vector3 g_eff = gravity_ - in.sensor_acceleration;
  const Vector6 rest = calibrator_.compensate(in.reading, R, tool_, g_eff);
  Vector6 w;
  w.head<3>() = R * rest.head<3>();
  w.tail<3>() = R * rest.tail<3>();

  // what the whole object alone would put on the sensor, taken out before the filter
  Vector3 beyond_object = w.head<3>();
  if (in.gripper_closed && object_.mass > 0.0) beyond_object -= R * hangingWrench(objectInSensor(1.0), R, g_eff).head<3>();

  // 3. low-pass
  if (!filtered_) {
    load_ = w;
    interaction_ = beyond_object;
    filtered_ = true;
  } else {
    load_ += alpha_ * (w - load_);
    interaction_ += alpha_ * (beyond_object - interaction_);
  }

  // 4. load share: the share of the object's weight on the sensor
  const double g = gravity_.norm();
  double share = 0.0;
  if (in.gripper_closed && object_.mass > 0.0 && g > 0.0) {
    share = std::clamp(load_.head<3>().dot(gravity_) / (g * g * object_.mass), 0.0, 1.0);
  }
  share_ = share;

  // 5. the model carries that share
  payload_.mass = share_ * object_.mass;
  payload_.com = object_.com;
  payload_.inertia_com = share_ * object_.inertia_com;

  // 6. the rest is the known external wrench
  using Mode = ContactWrenchSettings::FeedForward;
  const bool wanted = calibrator_.done() &&  // an unknown offset would be fed forward too
                      (settings_.feed_forward == Mode::kAlways ||
                       (settings_.feed_forward == Mode::kCarry && in.carried_alone));
  ff_gain_ = std::clamp(ff_gain_ + (wanted ? ff_step_ : -ff_step_), 0.0, 1.0);
  disturbance_gain_ = std::clamp(disturbance_gain_ + (in.carried_alone ? ff_step_ : -ff_step_), 0.0, 1.0);
  if (ff_gain_ == 0.0) {
    feed_forward_.setZero();
    return;
  }
  const Vector6 modelled = hangingWrench(objectInSensor(share_), R, g_eff);
  feed_forward_.head<3>() = ff_gain_ * (load_.head<3>() - R * modelled.head<3>());
  feed_forward_.tail<3>() = ff_gain_ * (load_.tail<3>() - R * modelled.tail<3>());
}

ContactWrenchSettings parseContactWrenchSettings(const YamlReader& s) {
  ContactWrenchSettings c;
  if (!s.isMap())
    s.fail("expected a map with feed_forward, ramp_time, shared_distance, filter_tau, calibration_time, rest_speed");
  if (auto v = s.optionalChild("feed_forward")) {
    using Mode = ContactWrenchSettings::FeedForward;
    const std::string m = v->asEnum({"off", "carry", "always", "false", "true"});
    c.feed_forward = (m == "carry") ? Mode::kCarry : (m == "always" || m == "true") ? Mode::kAlways : Mode::kOff;
  }
  if (auto v = s.optionalChild("ramp_time")) c.ramp_time = v->checkRange(v->asDouble(), 0.0, 5.0);
  if (auto v = s.optionalChild("shared_distance")) c.shared_distance = v->checkRange(v->asDouble(), 0.0, 2.0);
  if (auto v = s.optionalChild("filter_tau")) c.filter_tau = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = s.optionalChild("calibration_time")) c.calibration_time = v->checkRange(v->asDouble(), 0.001, 10.0);
  if (auto v = s.optionalChild("rest_speed")) c.rest_speed = v->checkRange(v->asDouble(), 1e-6, 1.0);
  s.finish();
  return c;
}

}  // namespace handover::control
