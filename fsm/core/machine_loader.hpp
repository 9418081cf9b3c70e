// Builds machines from YAML and validates them (start-up only, not RT safe).
//
// A machine definition is a map:
//   states:      {Name: {type: T, timeout: s, ...state keys}, ...}   (optional)
//   initial:     Name
//   transitions: [[From, Output, To], ...]  (To: a state, or an exit name)
//   outputs:     [ExitName, ...]            (optional; exits of this machine)
// A meta state is a state definition with `type: Meta` and the same keys.
// Names are looked up in the enclosing definitions' `states` maps from the
// inside out (lexical scope), so an inner "Approach" may differ from an
// outer one. Every error names the file, the dotted key and the line.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "config/yaml_reader.hpp"
#include "fsm/core/history.hpp"
#include "fsm/core/machine.hpp"
#include "fsm/core/registry.hpp"

namespace handover::fsm {

class MachineLoader {
 public:
  /// State definitions visible at one level, with the enclosing level.
  struct Scope {
    std::map<std::string, YamlReader> defs;
    const Scope* parent = nullptr;
  };

  MachineLoader(const Registry& registry, History* history) : registry_(registry), history_(history) {}

  /// Reads `def.states` (if any) into a scope whose parent is `parent`.
  static Scope makeScope(const YamlReader& def, const Scope* parent);

  /// Builds the machine of `def` whose own definitions are `scope`.
  /// `prefix` is the path of the enclosing state ("" at the top);
  /// `extra_states` (name, reader blamed if unknown) are instantiated even
  /// if the table does not name them.
  using Extra = std::vector<std::pair<std::string, YamlReader>>;
  std::unique_ptr<Machine> build(const YamlReader& def, const Scope& scope, const std::string& prefix,
                                 const Extra& extra_states = {}, int depth = 0);

  /// Creates, names and configures one state from its definition. `where`
  /// is the reader blamed when the name is unknown.
  std::unique_ptr<State> instantiate(const std::string& name, const Scope& scope, const std::string& prefix,
                                     const YamlReader& where, int depth, const Machine** inner_out);

 private:
  const Registry& registry_;
  History* history_;
};

}  // namespace handover::fsm
