// The handover behaviour: loads config/fsm.yaml (shared `params` and the
// `machine`), owns the state machine, the controller ledger and the context,
// and is stepped once per control cycle with the cycle's inputs.
//
//   auto fsm = HandoverFsm::fromFile(HandoverFsm::defaultConfigPath(), controller, object);
//   every 1 ms: fsm->plan();  (with a planner, outside the timed step)
//               fsm->step(input);   log fsm->activePath(); read fsm->stats()
//
// Construction is not RT safe; step(), activePath() and stats() are. plan()
// allocates nothing but may run the planner's search (about 1.5 ms).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fsm/core/registry.hpp"
#include "fsm/core/state_machine.hpp"
#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Registers every handover state and condition type.
void registerHandoverTypes(Registry& registry);

class HandoverFsm {
 public:
  /// `root` has keys `params` (optional: config/fsm.yaml's when absent) and `machine`. The controller must outlive the
  /// machine. Throws handover::InputError naming file, key and line.
  HandoverFsm(const YamlReader& root, ControllerInterface& controller, const ObjectInfo& object);
  static std::unique_ptr<HandoverFsm> fromFile(const std::string& path, ControllerInterface& controller,
                                               const ObjectInfo& object);
  /// config/fsm.yaml of the source tree.
  static std::string defaultConfigPath();

  /// One control cycle: sanitises the inputs (non-finite values are dropped
  /// and counted), filters the wrist force, runs interrupts and states.
  void step(const HandoverInput& input);
  /// The grasp planner the states consult (optional; must outlive the
  /// machine). Without one they track the declared grasp and named poses.
  void setPlanner(PlannerInterface* planner) { ctx_.planner = planner; }
  /// The planning stage, outside step(): answers the carry request a state
  /// posted in an earlier step (an upright placement of the held object,
  /// carry_request.hpp) with the planner's search; returns at once without
  /// a planner or a request. With a planner, call it before every step (or
  /// from a slower thread, under the same lock as step): a carrying state
  /// waits for the answer before it can finish.
  void plan();
  /// Tears down every active state (end of a run).
  void stop();

  /// Path of the deepest active state, e.g. "Handover/HumanToRobot/Approach".
  const std::string& activePath() const { return machine_->activePath(); }
  const HandoverStats& stats() const { return ctx_.stats; }
  /// Outcome decided (a final Rest state was reached).
  bool done() const;
  const StateMachine& machine() const { return *machine_; }
  const HandoverParams& params() const { return params_; }
  const HandoverContext& context() const { return ctx_; }
  /// Visited states, full paths in order (copies; not RT safe).
  std::vector<std::string> visitedStates() const { return machine_->history().paths(); }

 private:
  void sanitise(const HandoverInput& input);
  HandoverParams params_;
  Registry registry_;
  CommandLedger ledger_;
  HandoverContext ctx_;
  std::unique_ptr<StateMachine> machine_;
  double last_time_ = 0.0;
};

}  // namespace handover::fsm
