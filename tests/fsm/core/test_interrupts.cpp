// The interrupt layer: preemption with teardown of the whole active path,
// exceptions, and overlays that run beside the active path.
#include <gtest/gtest.h>

#include "fsm/core/state_machine.hpp"
#include "tests/fsm/core/test_states.hpp"

namespace handover::fsm::test {
namespace {

const char* kYaml = R"(
states:
  Work:
    type: Meta
    states:
      Deep:
        type: Meta
        states:
          Leaf: {type: Scripted, outputs: [x], cycles: -1}
        initial: Leaf
    initial: Deep
  Stop: {type: Scripted, outputs: [Clear], output: Clear, cycles: 3}
  Rest: {type: Scripted, outputs: [x], cycles: -1}
  Slow: {type: Scripted, outputs: [x], cycles: -1}
initial: Work
transitions:
  - [Stop, Clear, Work]
interrupts:
  - {name: slow, condition: {type: Flag, flag: 1}, overlay: Slow}
  - {name: stop, condition: {type: Flag, flag: 0}, preempt: Stop, except: [Rest]}
  - {name: rest, condition: {type: Flag, flag: 2}, preempt: Rest}
)";

struct Fixture : ::testing::Test {
  Registry registry = testRegistry();
  StateMachine sm{YamlReader::loadString(kYaml, "interrupts.yaml"), registry};
  TestContext ctx;
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) {
      sm.step(ctx);
      ctx.time += 0.001;
    }
  }
};

TEST_F(Fixture, PreemptTearsDownWholePathAndStartsTarget) {
  step(2);
  EXPECT_EQ(sm.activePath(), "Work/Deep/Leaf");
  EXPECT_EQ(ctx.resources, (std::set<std::string>{"Work/Deep/Leaf"}));
  ctx.log.clear();
  ctx.flags[0] = true;
  step();
  EXPECT_EQ(sm.activePath(), "Stop");
  const std::vector<std::string> expected{"teardown Work/Deep/Leaf", "start Stop"};
  EXPECT_EQ(ctx.log, expected);
  EXPECT_EQ(ctx.resources, (std::set<std::string>{"Stop"}));
  EXPECT_TRUE(sm.history().entries().back().interrupt);
  // while its target is active, the interrupt does not restart it
  step(2);
  EXPECT_EQ(sm.activePath(), "Stop");
  EXPECT_EQ(sm.interruptFired(1), 1);
  // clear: Stop finishes and the table leads back to Work
  ctx.flags[0] = false;
  step(3);
  EXPECT_EQ(sm.activePath(), "Work/Deep/Leaf");
  EXPECT_EQ(ctx.resources, (std::set<std::string>{"Work/Deep/Leaf"}));
}

TEST_F(Fixture, ExceptListDisablesInterrupt) {
  step();
  ctx.flags[2] = true;
  step();
  EXPECT_EQ(sm.activePath(), "Rest");
  ctx.flags[2] = false;
  ctx.flags[0] = true;
  step(5);
  EXPECT_EQ(sm.activePath(), "Rest");
  EXPECT_EQ(sm.interruptFired(1), 0);
}

TEST_F(Fixture, OverlayRunsBesideActivePathAndIsTornDown) {
  step();
  ctx.flags[1] = true;
  step(3);
  EXPECT_TRUE(sm.interruptActive(0));
  EXPECT_EQ(sm.activePath(), "Work/Deep/Leaf");
  EXPECT_EQ(ctx.resources, (std::set<std::string>{"Work/Deep/Leaf", "Slow"}));
  ctx.flags[1] = false;
  step();
  EXPECT_FALSE(sm.interruptActive(0));
  EXPECT_EQ(ctx.resources, (std::set<std::string>{"Work/Deep/Leaf"}));
  EXPECT_EQ(sm.interruptFired(0), 1);
}

TEST_F(Fixture, StopTearsDownEverything) {
  step();
  ctx.flags[1] = true;
  step();
  sm.stop(ctx);
  EXPECT_TRUE(ctx.resources.empty());
}

}  // namespace
}  // namespace handover::fsm::test
