#include "fsm/handover/handover_state.hpp"

#include <stdexcept>

namespace handover::fsm {

HandoverContext& handoverContext(Context& ctx) {
  auto* h = dynamic_cast<HandoverContext*>(&ctx);
  if (!h || !h->params || !h->ledger) {
    throw std::logic_error("handover state run without a complete HandoverContext");
  }
  return *h;
}

void HandoverState::start(Context& ctx) {
  HandoverContext& h = handoverContext(ctx);
  ctrl_.bind(h.ledger);
  onStart(h);
}

bool HandoverState::run(Context& ctx) { return onRun(static_cast<HandoverContext&>(ctx)); }

void HandoverState::teardown(Context& ctx) {
  HandoverContext& h = static_cast<HandoverContext&>(ctx);
  onTeardown(h);
  ctrl_.undo();
}

double HandoverState::readPositive(const YamlReader& def, const char* key, double hi) {
  const YamlReader c = def.child(key);
  const double v = c.asDouble();
  if (!(v > 0.0)) c.fail("must be > 0, got " + std::to_string(v));
  return c.checkRange(v, 0.0, hi);
}

double HandoverState::readRange(const YamlReader& def, const char* key, double lo, double hi) {
  const YamlReader c = def.child(key);
  return c.checkRange(c.asDouble(), lo, hi);
}

}  // namespace handover::fsm
