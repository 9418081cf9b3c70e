#include "fsm/core/registry.hpp"

#include <stdexcept>

namespace handover::fsm {

namespace {
template <class Map>
std::string joinKeys(const Map& m, const char* extra) {
  std::string s = extra ? extra : "";
  for (const auto& kv : m) s += (s.empty() ? "" : " | ") + kv.first;
  return s;
}
}  // namespace

void Registry::addState(const std::string& type, StateMaker make) {
  if (type == metaType() || states_.count(type)) {
    throw std::invalid_argument("fsm registry: state type '" + type + "' already exists");
  }
  states_[type] = std::move(make);
}

void Registry::addCondition(const std::string& type, ConditionMaker make) {
  if (conditions_.count(type)) {
    throw std::invalid_argument("fsm registry: condition type '" + type + "' already exists");
  }
  conditions_[type] = std::move(make);
}

std::unique_ptr<State> Registry::makeState(const std::string& type) const {
  auto it = states_.find(type);
  return it == states_.end() ? nullptr : it->second();
}

std::unique_ptr<Condition> Registry::makeCondition(const std::string& type) const {
  auto it = conditions_.find(type);
  return it == conditions_.end() ? nullptr : it->second();
}

std::string Registry::stateTypes() const { return joinKeys(states_, metaType()); }
std::string Registry::conditionTypes() const { return joinKeys(conditions_, nullptr); }

}  // namespace handover::fsm
