// Factory of state and condition types by name, so YAML files can say
// `type: Approach`. Filled at start-up (not RT safe); `Meta` is built in.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fsm/core/condition.hpp"
#include "fsm/core/state.hpp"

namespace handover::fsm {

class Registry {
 public:
  using StateMaker = std::function<std::unique_ptr<State>()>;
  using ConditionMaker = std::function<std::unique_ptr<Condition>()>;

  /// Registers a state type; throws std::invalid_argument on a duplicate
  /// name or on the reserved name "Meta".
  void addState(const std::string& type, StateMaker make);
  template <class T>
  void addState(const std::string& type) {
    addState(type, [] { return std::unique_ptr<State>(new T()); });
  }
  void addCondition(const std::string& type, ConditionMaker make);
  template <class T>
  void addCondition(const std::string& type) {
    addCondition(type, [] { return std::unique_ptr<Condition>(new T()); });
  }

  /// nullptr when the type is unknown.
  std::unique_ptr<State> makeState(const std::string& type) const;
  std::unique_ptr<Condition> makeCondition(const std::string& type) const;
  /// "A | B | C" for error messages.
  std::string stateTypes() const;
  std::string conditionTypes() const;

  static const char* metaType() { return "Meta"; }

 private:
  std::map<std::string, StateMaker> states_;
  std::map<std::string, ConditionMaker> conditions_;
};

}  // namespace handover::fsm
