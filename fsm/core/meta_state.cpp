#include "fsm/core/meta_state.hpp"

namespace handover::fsm {

MetaState::MetaState(std::unique_ptr<Machine> inner) : inner_(std::move(inner)) {
  for (const std::string& e : inner_->exits()) exit_to_output_.push_back(declareOutput(e));
}

void MetaState::start(Context& ctx) { inner_->start(ctx); }

bool MetaState::run(Context& ctx) {
  inner_->step(ctx);
  if (!inner_->finished()) return false;
  setOutput(exit_to_output_[static_cast<std::size_t>(inner_->finalExit())]);
  return true;
}

void MetaState::teardown(Context& ctx) { inner_->stop(ctx); }

}  // namespace handover::fsm
