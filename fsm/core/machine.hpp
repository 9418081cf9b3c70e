// One level of a hierarchical state machine: a set of states and the table
// that maps (state, output) to the next state or to an exit of the machine.
// Built by MachineLoader (machine_loader.hpp) from YAML; at run time all
// names are resolved to indices, so step() is RT safe as long as the states'
// start/run/teardown are.
//
// Semantics per step(): if the active state's timeout has elapsed it ends
// with output "Timeout" without running; else run() is called. When it is
// done: teardown(), then the next state is started (it runs from the next
// cycle), or the machine finishes with the exit the table names. An output
// with no row in the table exits the machine under the same name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fsm/core/history.hpp"
#include "fsm/core/state.hpp"

namespace handover::fsm {

class Machine {
 public:
  /// Where an output leads: a state of this machine or an exit (one is >= 0).
  struct Target {
    int state = -1;
    int exit = -1;
  };

  /// Enters the initial state (records it in the history).
  void start(Context& ctx);
  /// One cycle of the active state and, when it is done, its transition.
  void step(Context& ctx);
  /// Tears down the whole active path, innermost first. Idempotent.
  void stop(Context& ctx);
  /// stop(), then enters `state` (an index of this machine), marked in the
  /// history as entered by an interrupt.
  void preempt(Context& ctx, int state);

  bool running() const { return active_ >= 0; }
  bool finished() const { return finished_; }
  /// Exit taken when finished (-1 otherwise) and its name ("" otherwise).
  int finalExit() const { return final_exit_; }
  const std::string& finalOutput() const;

  int activeIndex() const { return active_; }
  const State* activeState() const;
  /// Deepest active state through meta states (nullptr when not running).
  const State* innermostActive() const;

  int size() const { return static_cast<int>(nodes_.size()); }
  const State& state(int i) const { return *nodes_[static_cast<std::size_t>(i)].state; }
  /// -1 when absent.
  int findState(const std::string& name) const;
  const Target& target(int state, int output) const;
  const std::vector<std::string>& exits() const { return exits_; }
  int initial() const { return initial_; }

 private:
  friend class MachineLoader;
  struct Node {
    std::unique_ptr<State> state;
    std::vector<Target> next;   ///< one per output of the state
    const Machine* inner = nullptr;  ///< the inner machine when the state is a meta state
    int timeout_output = -1;
  };
  void enter(Context& ctx, int i, bool interrupt);

  std::vector<Node> nodes_;
  std::vector<std::string> exits_;
  int initial_ = 0;
  History* history_ = nullptr;
  int active_ = -1;
  bool finished_ = false;
  int final_exit_ = -1;
};

}  // namespace handover::fsm
