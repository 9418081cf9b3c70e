// The top of a hierarchical state machine: the root machine, the interrupt
// (safety) layer and the history. Load once (not RT safe); then start() and
// step() every control cycle (RT safe when the states and conditions are).
//
// YAML (the root machine definition plus):
//   history_capacity: 4096        # entries kept (default 4096)
//   interrupts:                   # evaluated in order, every cycle
//     - name: stop
//       condition: {type: T, ...} # a registered Condition
//       preempt: SafetyStop       # a state of the root machine: the whole
//                                 # active path is torn down, then it starts
//       except: [Done]            # root states during which it is ignored
//     - name: slow
//       condition: {type: T, ...}
//       overlay: SlowDown         # a state run alongside the active path while
//                                 # the condition holds, torn down when it clears
// A preempting interrupt is ignored while its own target is active.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fsm/core/condition.hpp"
#include "fsm/core/history.hpp"
#include "fsm/core/machine.hpp"
#include "fsm/core/registry.hpp"

namespace handover::fsm {

class StateMachine {
 public:
  /// Builds and validates everything; throws handover::InputError naming
  /// file, key and line.
  StateMachine(const YamlReader& def, const Registry& registry);
  ~StateMachine();
  StateMachine(const StateMachine&) = delete;
  StateMachine& operator=(const StateMachine&) = delete;

  /// Enters the initial state. RT safe (history reserved).
  void start(Context& ctx);
  /// Interrupts, overlays, then one cycle of the active path.
  void step(Context& ctx);
  /// Tears down the active path and the overlays (end of a run).
  void stop(Context& ctx);

  bool started() const { return started_; }
  /// The root machine exited (no state active any more).
  bool finished() const { return root_->finished(); }
  const std::string& finalOutput() const { return root_->finalOutput(); }
  /// Path of the deepest active state, "" when none. RT safe (no copy).
  const std::string& activePath() const;
  const History& history() const { return *history_; }
  const Machine& root() const { return *root_; }

  int interruptCount() const { return static_cast<int>(interrupts_.size()); }
  const std::string& interruptName(int i) const { return interrupts_[static_cast<std::size_t>(i)].name; }
  /// Overlay: running now. Preempt: its condition held on the last cycle.
  bool interruptActive(int i) const { return interrupts_[static_cast<std::size_t>(i)].active; }
  /// Times the interrupt preempted the active path / started its overlay.
  int interruptFired(int i) const { return interrupts_[static_cast<std::size_t>(i)].fired; }

 private:
  struct Interrupt {
    std::string name;
    std::unique_ptr<Condition> condition;
    int preempt_target = -1;           ///< root state index, or -1 for an overlay
    std::unique_ptr<State> overlay;    ///< overlay state, or nullptr
    std::vector<int> except;           ///< root state indices
    bool active = false;
    int fired = 0;
  };
  bool excepted(const Interrupt& it) const;

  std::unique_ptr<History> history_;
  std::unique_ptr<Machine> root_;
  std::vector<Interrupt> interrupts_;
  bool started_ = false;
};

}  // namespace handover::fsm
