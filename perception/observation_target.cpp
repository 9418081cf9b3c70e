#include "perception/observation_target.hpp"
#include "interfaces/minimum_jerk.hpp"

#include <algorithm>

namespace handover::perception {

namespace {

Eigen::Isometry3d interpolate(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double phase) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = a.translation() + phase * (b.translation() - a.translation());
  const Eigen::Quaterniond qa(a.rotation()), qb(b.rotation());
  T.linear() = qa.slerp(phase, qb).normalized().toRotationMatrix();
  return T;
}

}  // namespace

const char* toString(TargetSource s) { return s == TargetSource::Object ? "object" : "hand"; }

ObservationTarget::ObservationTarget(const ObservationTargetSettings& settings) : settings_(settings) {}

void ObservationTarget::reset() {
  out_ = TargetOutput{};
  have_output_ = selected_ = blending_ = old_live_ = false;
}

bool ObservationTarget::sourcePose(TargetSource s, const Eigen::Isometry3d& attached,
                                   const PerceptionEstimate& e, Eigen::Isometry3d& pose) const {
  if (s == TargetSource::Object) {
    if (!e.object.valid || e.object.stale) return false;
    pose = e.object.pose * attached;
  } else {
    if (!e.human.valid || e.human.stale) return false;
    pose = e.human.hand * attached;
  }
  return true;
}

void ObservationTarget::select(TargetSource source, double now, const Eigen::Isometry3d& attached) {
  if (selected_ && source == current_ && attached.isApprox(attached_, 1e-12)) return;
  if (selected_ && have_output_ && settings_.blend_time > 0.0) {
    // a switch during a blend starts from where the blend is now (frozen)
    old_live_ = !blending_;
    old_source_ = current_;
    old_attached_ = attached_;
    old_pose_ = out_.pose;
    blending_ = true;
    blend_start_ = now;
  } else {
    blending_ = false;
  }
  selected_ = true;
  current_ = source;
  attached_ = attached;
  out_.source = source;
}

const TargetOutput& ObservationTarget::update(double now, const PerceptionEstimate& estimate) {
  Eigen::Isometry3d target;
  const bool fresh = selected_ && sourcePose(current_, attached_, estimate, target);
  if (blending_) {
    Eigen::Isometry3d old;
    if (old_live_ && sourcePose(old_source_, old_attached_, estimate, old)) old_pose_ = old;
    const double s = (now - blend_start_) / settings_.blend_time;
    out_.blend_phase = minimumJerkPhase(s);
    if (s >= 1.0) blending_ = false;
    if (fresh) target = interpolate(old_pose_, target, out_.blend_phase);
  } else {
    out_.blend_phase = 1.0;
  }
  out_.blending = blending_;
  out_.valid = fresh;
  // no data: hold the last target rather than guess where it went
  if (fresh) {
    out_.pose = target;
    have_output_ = true;
  }
  return out_;
}

}  // namespace handover::perception
