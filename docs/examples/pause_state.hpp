// Example state (docs/architecture.md): hold still for `duration` seconds,
// then end with output "Done". The speed scale it sets is a scoped channel:
// HandoverState's teardown gives it back, whatever ends the state.
#pragma once

#include "fsm/handover/handover_state.hpp"

namespace handover::examples {

class Pause : public fsm::HandoverState {
 public:
  Pause() { done_ = declareOutput("Done"); }
  void configure(const YamlReader& def) override { duration_ = readPositive(def, "duration", 60.0); }

 protected:
  void onStart(fsm::HandoverContext&) override { ctrl().setSpeedScale(0.0); }
  bool onRun(fsm::HandoverContext& ctx) override {
    if (elapsed(ctx) < duration_) return false;
    setOutput(done_);
    return true;
  }

 private:
  int done_ = -1;
  double duration_ = 1.0;  ///< s
};

}  // namespace handover::examples
