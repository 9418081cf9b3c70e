#include "fsm/handover/handover_fsm.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "fsm/handover/back_out.hpp"
#include "fsm/handover/common_states.hpp"
#include "fsm/handover/h2r_states.hpp"
#include "fsm/handover/object_lost.hpp"
#include "fsm/handover/seated_in_hand.hpp"
#include "fsm/handover/r2h_states.hpp"
#include "fsm/handover/reach_states.hpp"
#include "fsm/handover/safety.hpp"
#include "config/config_directory.hpp"

namespace handover::fsm {

void registerHandoverTypes(Registry& r) {
  r.addState<SelectDirection>("SelectDirection");
  r.addState<Rest>("Rest");
  r.addState<Retract>("Retract");
  r.addState<Retreat>("Retreat");
  r.addState<BackOut>("BackOut");
  r.addState("WaitForOffer", [] { return std::unique_ptr<State>(new WaitForPerson(false)); });
  r.addState("WaitForReceiver", [] { return std::unique_ptr<State>(new WaitForPerson(true)); });
  r.addState("ApproachObject", [] { return std::unique_ptr<State>(new Approach(false)); });
  r.addState("ApproachHand", [] { return std::unique_ptr<State>(new Approach(true)); });
  r.addState<Grasp>("Grasp");
  r.addState<WaitForRelease>("WaitForRelease");
  r.addState<HoldReady>("HoldReady");
  r.addState<Present>("Present");
  r.addState<DetectPull>("DetectPull");
  r.addState<Release>("Release");
  r.addState<ConfirmGone>("ConfirmGone");
  r.addState<SafetyStop>("SafetyStop");
  r.addState<SlowDown>("SlowDown");
  r.addState<Reach>("Reach");
  r.addState<Hold>("Hold");
  r.addCondition<HumanTooClose>("HumanTooClose");
  r.addCondition<ObjectLost>("ObjectLost");
}

namespace {
bool finite(const Isometry& T) { return T.matrix().allFinite(); }
bool finite(const SensedBody& b) {
  return finite(b.pose) && b.velocity.allFinite() && std::isfinite(b.age) && std::isfinite(b.stamp);
}
// share of the step `dt` (s) a first-order low-pass of time constant `tau` (s) moves toward its
// input (1: no filter)
double lowPassGain(double dt, double tau) { return tau > 0.0 ? dt / (tau + dt) : 1.0; }
}  // namespace

HandoverFsm::HandoverFsm(const YamlReader& root, ControllerInterface& controller, const ObjectInfo& object)
    : ledger_(controller) {
  if (!root.isMap()) root.fail("expected a map with 'params' and 'machine'");
  if (!(object.mass > 0.0) || !std::isfinite(object.mass)) {
    throw InputError(root.file() + ": object mass must be > 0 kg, got " + std::to_string(object.mass));
  }
  // a state table of its own (config/fsm_reach.yaml, fsm_hold.yaml) may leave
  // the shared parameters to config/fsm.yaml: one place for them
  if (root.has("params")) params_ = loadHandoverParams(root.child("params"));
  else params_ = loadHandoverParams(YamlReader::loadFile(defaultConfigPath()).child("params"));
  registerHandoverTypes(registry_);
  machine_ = std::make_unique<StateMachine>(root.child("machine"), registry_);
  root.finish();
  ctx_.params = &params_;
  ctx_.ledger = &ledger_;
  ctx_.object = object;
  ctx_.grasp.offset = object.grasp_in_object;
  // a flat object sits on the receiver's hand, not a ball's height above it
  params_.object_in_hand = seatedInHand(params_.object_in_hand, object.shape, params_.object_in_hand_seat);
  ctx_.presentation.offset = params_.object_in_hand * object.grasp_in_object;
}

std::unique_ptr<HandoverFsm> HandoverFsm::fromFile(const std::string& path, ControllerInterface& controller,
                                                   const ObjectInfo& object) {
  return std::make_unique<HandoverFsm>(YamlReader::loadFile(path), controller, object);
}

std::string HandoverFsm::defaultConfigPath() { return configFile("fsm.yaml"); }

bool HandoverFsm::done() const { return std::string_view(ctx_.stats.outcome) != "running"; }

void HandoverFsm::sanitise(const HandoverInput& in) {
  const HandoverInput previous = ctx_.in;
  ctx_.in = in;
  bool bad = false;
  if (!std::isfinite(in.time)) {
    ctx_.in.time = last_time_;
    bad = true;
  }
  // arm state the controller reports: keep the last good value
  if (!finite(in.tcp_pose) || !in.tcp_velocity.allFinite() || !in.q.allFinite() || !in.qd.allFinite()) {
    ctx_.in.tcp_pose = previous.tcp_pose;
    ctx_.in.tcp_velocity = previous.tcp_velocity;
    ctx_.in.q = previous.q;
    ctx_.in.qd = previous.qd;
    bad = true;
  }
  if (!std::isfinite(in.load_share)) {
    ctx_.in.load_share = previous.load_share;
    bad = true;
  }
  if (!std::isfinite(in.finger_width)) {
    ctx_.in.finger_width = previous.finger_width;
    bad = true;
  }
  // perception: a non-finite sample is no sample
  if (!finite(in.hand)) {
    ctx_.in.hand = previous.hand;
    ctx_.in.hand.valid = false;
    bad = true;
  }
  if (!finite(in.object)) {
    ctx_.in.object = previous.object;
    ctx_.in.object.valid = false;
    bad = true;
  }
  if (std::isnan(in.human_distance) || std::isnan(in.arm_distance) || std::isnan(in.hand_distance)) {
    // unknown distance: assume the worst, and that it is the arm (no grasp-zone exception)
    ctx_.in.human_distance = ctx_.in.arm_distance = ctx_.in.hand_distance = 0.0;
    bad = true;
  }
  if (!finite(in.target_pose) || !in.target_velocity.allFinite()) {
    ctx_.in.target_pose = previous.target_pose;
    ctx_.in.target_velocity = previous.target_velocity;
    bad = true;
  }
  // wrist force: low-pass in world axes; skip non-finite samples. The
  // interaction force comes filtered (ContactWrenchEstimator, 10 ms): a
  // second, slower filter here told a fast pull 50 ms late, 1-2 cm into it
  const Vector3 f = in.ft_rotation * in.wrench.head<3>();
  if (f.allFinite() && in.interaction_force.allFinite()) {
    const double dt = ctx_.force_valid ? std::max(0.0, ctx_.in.time - last_time_) : 0.0;
    const double tau = params_.ft_filter_tau;
    if (!ctx_.force_valid || tau <= 0.0) {
      ctx_.force = f;
      ctx_.force_valid = true;
    } else {
      ctx_.force += lowPassGain(dt, tau) * (f - ctx_.force);
    }
    ctx_.interaction = in.interaction_force;
  } else {
    bad = true;
  }
  if (bad) ++ctx_.stats.bad_input_cycles;
  // the person's rest place: where each body was first seen
  if (!ctx_.home_hand_known && ctx_.in.hand.valid) {
    ctx_.home_hand = ctx_.in.hand.pose.translation();
    ctx_.home_hand_known = true;
  }
  if (!ctx_.home_object_known && ctx_.in.object.valid) {
    ctx_.home_object = ctx_.in.object.pose.translation();
    ctx_.home_object_known = true;
  }
  // how far each went from home, low-passed: an estimate's transient is no excursion
  const double dt = std::max(0.0, ctx_.in.time - last_time_);
  const double tau = params_.away_time_constant;
  const auto away = [&](const SensedBody& body, const Vector3& home, double& from, double& farthest) {
    const double d = (body.pose.translation() - home).norm();
    from += lowPassGain(dt, tau) * (d - from);
    farthest = std::max(farthest, from);
  };
  if (ctx_.home_hand_known && ctx_.in.hand.valid)
    away(ctx_.in.hand, ctx_.home_hand, ctx_.hand_from_home, ctx_.hand_farthest_from_home);
  if (ctx_.home_object_known && ctx_.in.object.valid)
    away(ctx_.in.object, ctx_.home_object, ctx_.object_from_home, ctx_.object_farthest_from_home);
  last_time_ = ctx_.in.time;
}

void HandoverFsm::step(const HandoverInput& input) {
  sanitise(input);
  ctx_.time = ctx_.in.time;
  machine_->step(ctx_);
}

void HandoverFsm::plan() {
  if (ctx_.planner == nullptr || !ctx_.carry.pending()) return;
  const CarryRequest& r = ctx_.carry.request();
  ctx_.carry.answer(ctx_.planner->uprightPlacement(r.object_in_tcp, r.up_axis, r.object_position, r.q, r.receiver_stop));
}

void HandoverFsm::stop() { machine_->stop(ctx_); }

}  // namespace handover::fsm
