#include "control/wrench/disturbance_observer.hpp"

#include <cmath>

namespace handover::control {

DisturbanceObserver::DisturbanceObserver(const DisturbanceSettings& settings, const Vector7& tau_max, double period)
    : period_(period),
      alpha_(settings.filter_tau > 0.0 ? 1.0 - std::exp(-period / settings.filter_tau) : 1.0),
      limit_(settings.max_torque_fraction * tau_max),
      tau_max_(tau_max) {}

void DisturbanceObserver::reset() {
  estimate_.setZero();
  latest_.setZero();
  qd_prev_.setZero();
  have_prev_ = false;
}

void DisturbanceObserver::update(const Data& data, const Vector7& qd, const Vector7& tau_applied, bool learn) {
  if (!qd.allFinite() || !tau_applied.allFinite()) return;
  if (!have_prev_) {
    qd_prev_ = qd;
    have_prev_ = true;
    return;
  }
  const Vector7 qdd = (qd - qd_prev_) / period_;
  qd_prev_ = qd;
  Vector7 d = data.M * qdd;
  d += data.h - tau_applied;
  if (!d.allFinite()) return;
  latest_ = d.cwiseMax(-tau_max_).cwiseMin(tau_max_);
  if (!learn) return;
  estimate_ += alpha_ * (d - estimate_);
  estimate_ = estimate_.cwiseMax(-limit_).cwiseMin(limit_);
}

DisturbanceSettings parseDisturbanceSettings(const YamlReader& s) {
  DisturbanceSettings c;
  if (!s.isMap()) s.fail("expected a map with compensation, filter_tau, max_torque_fraction");
  if (auto v = s.optionalChild("compensation")) {
    c.compensation = v->asEnum({"off", "carry"}) == "carry" ? DisturbanceSettings::Compensation::kCarry
                                                             : DisturbanceSettings::Compensation::kOff;
  }
  if (auto v = s.optionalChild("filter_tau")) c.filter_tau = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = s.optionalChild("max_torque_fraction"))
    c.max_torque_fraction = v->checkRange(v->asDouble(), 0.0, 1.0);
  s.finish();
  return c;
}

}  // namespace handover::control
