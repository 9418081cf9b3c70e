// Base of every handover state: casts the context once, gives the state a
// ControllerHandle, and undoes the handle's scoped changes in teardown after
// the state's own onTeardown, so no state can forget to remove what it added.
// Also small helpers for reading thresholds at configure time.
#pragma once

#include "fsm/core/state.hpp"
#include "fsm/handover/controller_handle.hpp"
#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

class HandoverState : public State {
 public:
  void start(Context& ctx) final;
  bool run(Context& ctx) final;
  void teardown(Context& ctx) final;
  /// The state's handle (tests inspect what it touched).
  const ControllerHandle& handle() const { return ctrl_; }

  /// Required number in (0, hi]; error names the key.
  static double readPositive(const YamlReader& def, const char* key, double hi);
  /// Required number in [lo, hi].
  static double readRange(const YamlReader& def, const char* key, double lo, double hi);

 protected:
  virtual void onStart(HandoverContext& ctx) { (void)ctx; }
  virtual bool onRun(HandoverContext& ctx) = 0;
  virtual void onTeardown(HandoverContext& ctx) { (void)ctx; }
  ControllerHandle& ctrl() { return ctrl_; }

 private:
  ControllerHandle ctrl_;
};

/// Checked downcast (throws std::logic_error when a handover state is run
/// with another context type: a wiring bug, not an input error).
HandoverContext& handoverContext(Context& ctx);

}  // namespace handover::fsm
