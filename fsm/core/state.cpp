#include "fsm/core/state.hpp"

#include <stdexcept>

namespace handover::fsm {

int State::findOutput(const std::string& output) const {
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    if (outputs_[i] == output) return static_cast<int>(i);
  }
  return -1;
}

const std::string& State::output() const {
  static const std::string kNone;
  return output_ >= 0 ? outputs_[static_cast<std::size_t>(output_)] : kNone;
}

int State::declareOutput(const std::string& output) {
  const int existing = findOutput(output);
  if (existing >= 0) return existing;
  outputs_.push_back(output);
  return static_cast<int>(outputs_.size()) - 1;
}

void State::setOutput(int index) {
  // an undeclared index is a programming error in the state, not bad input
  if (index < 0 || index >= static_cast<int>(outputs_.size())) {
    throw std::logic_error("state '" + path_ + "': setOutput with an undeclared output index");
  }
  output_ = index;
}

}  // namespace handover::fsm
