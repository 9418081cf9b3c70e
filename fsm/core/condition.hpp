// A predicate of the interrupt (safety) layer, evaluated every cycle before
// the active state runs, whatever that state is.
// Real-time: evaluate() must not allocate.
#pragma once

#include "config/yaml_reader.hpp"
#include "fsm/core/context.hpp"

namespace handover::fsm {

class Condition {
 public:
  virtual ~Condition() = default;
  /// Reads the condition's keys (`type` already read). Not RT safe.
  virtual void configure(const YamlReader& def) { (void)def; }
  /// True while the interrupt should be in force. May keep filter state.
  virtual bool evaluate(Context& ctx) = 0;
};

}  // namespace handover::fsm
