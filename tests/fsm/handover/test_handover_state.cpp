// "A state removes from the QP what it added", for every state of
// config/fsm.yaml: each one is started alone on a ledger, run on the toy
// world until it ends (or 3 s), and torn down; then the whole set of scoped
// channels must equal what it was before the state started, on the ledger
// and at the controller. Both directions: from the defaults (every state
// changes channels away from them) and from a set where every channel is
// already changed (every state must put the parent's values back, not the
// defaults). Each runs with the person holding the object and with the robot
// holding it, so the states of both handover directions get to act.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "fsm/core/registry.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "fsm/handover/handover_state.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

using StateDefVisitor = std::function<void(const std::string& path, const YamlReader& def)>;

/// Every non-Meta state definition under `states`, depth first.
void forEachStateDef(const YamlReader& states, const std::string& prefix, const StateDefVisitor& visit) {
  for (const std::string& name : states.keys()) {
    const YamlReader def = states.child(name);
    const std::string path = prefix.empty() ? name : prefix + "/" + name;
    if (def.getString("type") == Registry::metaType()) forEachStateDef(def.child("states"), path, visit);
    else visit(path, def);
  }
}

/// The controller's view of the scoped channels that RecordingController keeps.
struct ControllerView {
  ObservationTarget observation;
  bool tracking, pose_active, posture_active, gains_active, hand_relaxed, pose_gains_active;
  double speed;
  Isometry offset, pose;
  static ControllerView of(const RecordingController& c) {
    return {c.observation, c.tracking, c.pose_active, c.posture_active, c.gains_active, c.hand_relaxed,
            c.pose_gains_active, c.speed, c.offset, c.pose};
  }
  bool operator==(const ControllerView& o) const {
    return observation == o.observation && tracking == o.tracking && pose_active == o.pose_active &&
           posture_active == o.posture_active && gains_active == o.gains_active && hand_relaxed == o.hand_relaxed &&
           pose_gains_active == o.pose_gains_active &&
           speed == o.speed && offset.matrix() == o.offset.matrix() &&
           (!pose_active || pose.matrix() == o.pose.matrix());  // a cleared target's value means nothing
  }
};

/// Sets every channel away from its default through a parent handle.
void changeEverything(ControllerHandle& parent) {
  parent.setObservationTarget(ObservationTarget::kHand);
  parent.enableTracking(true);
  Isometry off = Isometry::Identity();
  off.translation() = Vector3(0.0, 0.0, -0.05);
  parent.setTrackingOffset(off);
  Isometry pose = Isometry::Identity();
  pose.translation() = Vector3(0.4, 0.0, 0.4);
  parent.setPoseTarget(pose);
  parent.setPostureTarget(Vector7::Constant(0.1));
  parent.setSpeedScale(0.5);
  parent.setTrackingStiffness(3.0, 5.0);
  parent.setPoseStiffness(20.0, 40.0);
  parent.relaxHandClearance(true);
}

struct Harness {
  Rig rig;  // the toy world and a recording controller (its machine is not used)
  HandoverParams params;
  CommandLedger ledger{rig.ctl};
  HandoverContext ctx;
  ControllerHandle parent;

  explicit Harness(bool robot_holds) : rig(robot_holds) {
    params = rig.fsm->params();
    ctx.params = &params;
    ctx.ledger = &ledger;
    ctx.object = rig.fsm->context().object;
    parent.bind(&ledger);
    // the person offers (or waits to receive) right in front of the robot
    rig.world.moveHand(Vector3(0.55, 0.0, 0.30), 0.5);
  }
  void sense() {
    ctx.time = rig.world.time;
    ctx.in = rig.world.input(rig.ctl);
  }
  /// start, run until done or `seconds`, teardown
  void runAlone(State& s, double seconds) {
    sense();
    s.start(ctx);
    for (double t = 0.0; t < seconds; t += World::kDt) {
      rig.world.advance(rig.ctl);
      sense();
      if (s.run(ctx)) break;
    }
    s.teardown(ctx);
  }
};

void checkEveryState(bool robot_holds, bool from_changed) {
  Registry registry;
  registerHandoverTypes(registry);
  const YamlReader root = YamlReader::loadFile(HandoverFsm::defaultConfigPath());
  int states = 0;
  forEachStateDef(root.child("machine").child("states"), "", [&](const std::string& path, const YamlReader& def) {
    SCOPED_TRACE(path + (robot_holds ? " (robot holds)" : " (person holds)") +
                 (from_changed ? ", from changed channels" : ", from defaults"));
    Harness h(robot_holds);
    if (from_changed) changeEverything(h.parent);
    const ScopedCommands before = h.ledger.current();
    const ControllerView controller_before = ControllerView::of(h.rig.ctl);
    std::unique_ptr<State> state = registry.makeState(def.getString("type"));
    ASSERT_TRUE(state);
    state->configure(def);
    h.runAlone(*state, 3.0);
    EXPECT_EQ(h.ledger.current(), before) << "channels left changed: "
                                          << channelDifferences(h.ledger.current(), before);
    EXPECT_TRUE(ControllerView::of(h.rig.ctl) == controller_before);
    ++states;
  });
  EXPECT_GE(states, 10);  // the shipped machine has more; a broken walk finds none
}

TEST(HandoverState, TeardownRestoresTheDefaults) {
  checkEveryState(false, false);
  checkEveryState(true, false);
}

TEST(HandoverState, TeardownRestoresTheParentsValues) {
  checkEveryState(false, true);
  checkEveryState(true, true);
}

}  // namespace
}  // namespace handover::fsm::test
