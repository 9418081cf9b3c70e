// A state that runs its own inner machine (type `Meta` in YAML). It is done
// when the inner machine exits; its output is the name of that exit. Its
// teardown tears down the inner active path first, so leaving a meta state
// for any reason (done, timeout, interrupt) leaves nothing running inside.
#pragma once

#include <memory>

#include "fsm/core/machine.hpp"

namespace handover::fsm {

class MetaState final : public State {
 public:
  explicit MetaState(std::unique_ptr<Machine> inner);
  void start(Context& ctx) override;
  bool run(Context& ctx) override;
  void teardown(Context& ctx) override;
  const Machine& inner() const { return *inner_; }

 private:
  std::unique_ptr<Machine> inner_;
  std::vector<int> exit_to_output_;  ///< inner exit index -> own output index
};

}  // namespace handover::fsm
