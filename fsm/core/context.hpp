// What every state sees each cycle. Behaviours derive from it to add their
// inputs and outputs (fsm/handover/handover_context.hpp); the core only needs
// the clock, for timeouts and the history.
#pragma once

namespace handover::fsm {

struct Context {
  virtual ~Context() = default;
  double time = 0.0;  ///< s, monotonic; the caller sets it before each step
};

}  // namespace handover::fsm
