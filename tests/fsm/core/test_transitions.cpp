// Transition table, nesting, timeouts and history of the core machine.
#include <gtest/gtest.h>

#include "fsm/core/state_machine.hpp"
#include "tests/fsm/core/test_states.hpp"

namespace handover::fsm::test {
namespace {

struct Runner {
  explicit Runner(const std::string& yaml)
      : registry(testRegistry()), sm(YamlReader::loadString(yaml, "test.yaml"), registry) {}
  void stepUntil(double t_end, double dt = 0.01) {
    while (ctx.time <= t_end + 1e-9) {
      sm.step(ctx);
      ctx.time += dt;
    }
  }
  Registry registry;
  StateMachine sm;
  TestContext ctx;
};

TEST(FsmTransitions, FollowsTableAndExits) {
  Runner r(R"(
states:
  A: {type: Scripted, outputs: [Go, Stay], output: Go, cycles: 2}
  B: {type: Scripted, outputs: [Done], output: Done, cycles: 1}
initial: A
transitions:
  - [A, Go, B]
  - [B, Done, Finished]
outputs: [Finished]
)");
  r.sm.step(r.ctx);  // starts A, runs it once
  EXPECT_EQ(r.sm.activePath(), "A");
  r.sm.step(r.ctx);  // A done -> B started
  EXPECT_EQ(r.sm.activePath(), "B");
  EXPECT_FALSE(r.sm.finished());
  r.sm.step(r.ctx);  // B done -> exit
  EXPECT_TRUE(r.sm.finished());
  EXPECT_EQ(r.sm.finalOutput(), "Finished");
  EXPECT_EQ(r.sm.activePath(), "");
  EXPECT_EQ(r.sm.history().paths(), (std::vector<std::string>{"A", "B"}));
  EXPECT_TRUE(r.ctx.resources.empty());
  const std::vector<std::string> expected{"start A", "run A", "run A", "teardown A",
                                          "start B", "run B", "teardown B"};
  EXPECT_EQ(r.ctx.log, expected);
}

TEST(FsmTransitions, OutputWithoutRowExitsUnderItsName) {
  Runner r(R"(
states:
  A: {type: Scripted, outputs: [Go, Other], output: Other}
initial: A
transitions: [[A, Go, A]]
)");
  r.sm.step(r.ctx);
  EXPECT_TRUE(r.sm.finished());
  EXPECT_EQ(r.sm.finalOutput(), "Other");
}

TEST(FsmTransitions, MetaStateRunsInnerMachineAndTakesItsExit) {
  Runner r(R"(
states:
  Outer:
    type: Meta
    states:
      A: {type: Scripted, outputs: [Next], output: Next}
      B: {type: Scripted, outputs: [Ok, Bad], output: Bad}
    initial: A
    transitions: [[A, Next, B]]
  After: {type: Scripted, outputs: [x], cycles: -1}
initial: Outer
transitions:
  - [Outer, Bad, After]
)");
  r.sm.step(r.ctx);
  EXPECT_EQ(r.sm.activePath(), "Outer/B");
  r.sm.step(r.ctx);  // B exits with Bad: Outer ends with Bad -> After
  EXPECT_EQ(r.sm.activePath(), "After");
  EXPECT_EQ(r.sm.history().paths(), (std::vector<std::string>{"Outer", "Outer/A", "Outer/B", "After"}));
  // the meta's outputs are the inner exits
  const State& outer = r.sm.root().state(r.sm.root().findState("Outer"));
  EXPECT_GE(outer.findOutput("Ok"), 0);
  EXPECT_GE(outer.findOutput("Bad"), 0);
  EXPECT_EQ(r.ctx.resources, (std::set<std::string>{"After"}));
}

TEST(FsmTransitions, InnerDefinitionShadowsOuterOne) {
  Runner r(R"(
states:
  X: {type: Scripted, outputs: [outer], output: outer}
  M:
    type: Meta
    states:
      X: {type: Scripted, outputs: [inner], output: inner}
    initial: X
initial: M
)");
  r.sm.step(r.ctx);
  r.sm.step(r.ctx);
  EXPECT_TRUE(r.sm.finished());
  EXPECT_EQ(r.sm.finalOutput(), "inner");
}

TEST(FsmTransitions, TimeoutEndsStateWithTimeoutOutput) {
  Runner r(R"(
states:
  Wait: {type: Scripted, outputs: [never], cycles: -1, timeout: 0.5}
  Next: {type: Scripted, outputs: [x], cycles: -1}
initial: Wait
transitions: [[Wait, Timeout, Next]]
)");
  r.stepUntil(0.45);
  EXPECT_EQ(r.sm.activePath(), "Wait");
  r.stepUntil(0.52);
  EXPECT_EQ(r.sm.activePath(), "Next");
  EXPECT_NEAR(r.sm.history().entries().back().time, 0.5, 0.011);
  EXPECT_EQ(r.ctx.resources, (std::set<std::string>{"Next"}));
}

TEST(FsmTransitions, MetaTimeoutTearsDownInnerPathInnermostFirst) {
  Runner r(R"(
states:
  M:
    type: Meta
    timeout: 0.2
    states:
      N:
        type: Meta
        states:
          L: {type: Scripted, outputs: [x], cycles: -1}
        initial: L
    initial: N
  End: {type: Scripted, outputs: [x], cycles: -1}
initial: M
transitions: [[M, Timeout, End]]
)");
  r.stepUntil(0.15);
  EXPECT_EQ(r.sm.activePath(), "M/N/L");
  r.ctx.log.clear();
  r.stepUntil(0.25);
  EXPECT_EQ(r.sm.activePath(), "End");
  std::vector<std::string> changes;  // starts and teardowns only
  for (const auto& e : r.ctx.log) {
    if (e.rfind("run ", 0) != 0) changes.push_back(e);
  }
  EXPECT_EQ(changes, (std::vector<std::string>{"teardown M/N/L", "start End"}));
  EXPECT_EQ(r.ctx.resources, (std::set<std::string>{"End"}));
}

TEST(FsmTransitions, HistoryKeepsCapacityAndCountsDropped) {
  Runner r(R"(
history_capacity: 3
states:
  A: {type: Scripted, outputs: [Go], output: Go}
initial: A
transitions: [[A, Go, A]]
)");
  const std::size_t cap = r.sm.history().entries().capacity();
  for (int i = 0; i < 10; ++i) r.sm.step(r.ctx);
  EXPECT_EQ(r.sm.history().entries().size(), 3u);
  EXPECT_EQ(r.sm.history().dropped(), 8u);  // 11 starts: the initial one and 10 transitions
  EXPECT_EQ(r.sm.history().entries().capacity(), cap);
}

}  // namespace
}  // namespace handover::fsm::test
