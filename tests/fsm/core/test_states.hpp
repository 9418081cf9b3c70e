// Scripted states and conditions for the core tests: each logs what happens
// to it and holds a "resource" (its path in TestContext::resources) from
// start to teardown, so tests can see that teardown removed what start added.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "fsm/core/registry.hpp"

namespace handover::fsm::test {

struct TestContext : Context {
  std::vector<std::string> log;      ///< "start X", "run X", "teardown X"
  std::set<std::string> resources;   ///< held by started, not yet torn down states
  bool flags[4] = {false, false, false, false};
};

/// Keys: outputs: [..] (declared), output: name (set when done),
/// cycles: n (runs before done; -1 = never).
class ScriptedState : public State {
 public:
  void configure(const YamlReader& def) override;
  void start(Context& ctx) override;
  bool run(Context& ctx) override;
  void teardown(Context& ctx) override;

 private:
  int cycles_ = 1;
  int out_ = -1;
  int count_ = 0;
};

/// Keys: flag: index (0..3); holds while TestContext::flags[index].
class FlagCondition : public Condition {
 public:
  void configure(const YamlReader& def) override;
  bool evaluate(Context& ctx) override;

 private:
  int index_ = 0;
};

Registry testRegistry();
TestContext& asTest(Context& ctx);

}  // namespace handover::fsm::test
