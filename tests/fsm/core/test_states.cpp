#include "tests/fsm/core/test_states.hpp"

namespace handover::fsm::test {

TestContext& asTest(Context& ctx) { return static_cast<TestContext&>(ctx); }

void ScriptedState::configure(const YamlReader& def) {
  if (auto outs = def.optionalChild("outputs")) {
    for (std::size_t i = 0; i < outs->size(); ++i) declareOutput(outs->at(i).asString());
  }
  if (auto out = def.optionalChild("output")) {
    out_ = findOutput(out->asString());
    if (out_ < 0) out->fail("not among outputs");
  }
  cycles_ = def.getInt("cycles", 1);
}

void ScriptedState::start(Context& ctx) {
  count_ = 0;
  asTest(ctx).log.push_back("start " + path());
  asTest(ctx).resources.insert(path());
}

bool ScriptedState::run(Context& ctx) {
  asTest(ctx).log.push_back("run " + path());
  ++count_;
  if (cycles_ < 0 || count_ < cycles_ || out_ < 0) return false;
  setOutput(out_);
  return true;
}

void ScriptedState::teardown(Context& ctx) {
  asTest(ctx).log.push_back("teardown " + path());
  asTest(ctx).resources.erase(path());
}

void FlagCondition::configure(const YamlReader& def) {
  if (auto f = def.optionalChild("flag")) index_ = static_cast<int>(f->checkRange(f->asInt(), 0, 3));
}

bool FlagCondition::evaluate(Context& ctx) { return asTest(ctx).flags[index_]; }

Registry testRegistry() {
  Registry r;
  r.addState<ScriptedState>("Scripted");
  r.addCondition<FlagCondition>("Flag");
  return r;
}

}  // namespace handover::fsm::test
