#include "fsm/core/machine.hpp"

#include <stdexcept>

namespace handover::fsm {

const std::string& Machine::finalOutput() const {
  static const std::string kNone;
  return final_exit_ >= 0 ? exits_[static_cast<std::size_t>(final_exit_)] : kNone;
}

const State* Machine::activeState() const {
  return active_ >= 0 ? nodes_[static_cast<std::size_t>(active_)].state.get() : nullptr;
}

const State* Machine::innermostActive() const {
  if (active_ < 0) return nullptr;
  const Node& n = nodes_[static_cast<std::size_t>(active_)];
  if (n.inner) {
    const State* deeper = n.inner->innermostActive();
    if (deeper) return deeper;
  }
  return n.state.get();
}

int Machine::findState(const std::string& name) const {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].state->name() == name) return static_cast<int>(i);
  }
  return -1;
}

const Machine::Target& Machine::target(int state, int output) const {
  return nodes_.at(static_cast<std::size_t>(state)).next.at(static_cast<std::size_t>(output));
}

void Machine::enter(Context& ctx, int i, bool interrupt) {
  Node& n = nodes_[static_cast<std::size_t>(i)];
  active_ = i;
  n.state->start_time_ = ctx.time;
  n.state->output_ = -1;
  if (history_) history_->record(ctx.time, n.state.get(), interrupt);
  n.state->start(ctx);
}

void Machine::start(Context& ctx) {
  finished_ = false;
  final_exit_ = -1;
  enter(ctx, initial_, false);
}

void Machine::step(Context& ctx) {
  if (active_ < 0) return;
  Node& n = nodes_[static_cast<std::size_t>(active_)];
  State& s = *n.state;
  bool done = false;
  if (n.timeout_output >= 0 && ctx.time - s.start_time_ >= s.timeout_) {
    s.output_ = n.timeout_output;
    done = true;
  } else {
    done = s.run(ctx);
  }
  if (!done) return;
  if (s.output_ < 0) {
    throw std::logic_error("state '" + s.path() + "' finished without setting an output");
  }
  const Target t = n.next[static_cast<std::size_t>(s.output_)];
  active_ = -1;  // teardown sees the machine between states
  s.teardown(ctx);
  if (t.state >= 0) {
    enter(ctx, t.state, false);
  } else {
    finished_ = true;
    final_exit_ = t.exit;
  }
}

void Machine::stop(Context& ctx) {
  if (active_ < 0) return;
  State& s = *nodes_[static_cast<std::size_t>(active_)].state;
  active_ = -1;
  s.teardown(ctx);  // a meta state stops its inner machine first
}

void Machine::preempt(Context& ctx, int state) {
  stop(ctx);
  finished_ = false;
  final_exit_ = -1;
  enter(ctx, state, true);
}

}  // namespace handover::fsm
