// The worked examples of docs/architecture.md, kept honest: each example file
// (docs/examples/) is quoted verbatim in the document, compiles, and does
// what the document says when plugged in the way the document shows.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "docs/examples/integrating_arm_driver.hpp"
#include "docs/examples/pause_state.hpp"
#include "docs/examples/wrist_damping_task.hpp"
#include "fsm/core/registry.hpp"
#include "fsm/core/state_machine.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "runtime/handover_cycle.hpp"
#include "tests/fsm/handover/fake_world.hpp"

namespace handover {
namespace {

std::string readFile(const std::string& relative) {
  std::ifstream in(std::string(HANDOVER_SOURCE_DIR) + "/" + relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A source of pose samples with nobody in view.
class NobodyInView : public perception::PoseSource {
 public:
  bool poll(double, perception::PoseSample&) override { return false; }
};

TEST(ArchitectureDoc, QuotesEveryExampleVerbatim) {
  const std::string doc = readFile("docs/architecture.md");
  ASSERT_FALSE(doc.empty());
  for (const char* f : {"docs/examples/wrist_damping_task.hpp", "docs/examples/pause_state.hpp",
                        "docs/examples/integrating_arm_driver.hpp"}) {
    const std::string code = readFile(f);
    ASSERT_FALSE(code.empty()) << f;
    EXPECT_NE(doc.find(code), std::string::npos) << "docs/architecture.md does not quote " << f << " as it is";
  }
}

// "A robot driver": the cycle drives the integrating arm; with nobody in
// view the robot waits, and the QP holds the arm where it started.
TEST(ArchitectureDoc, DriverExampleIsDrivenByTheCycle) {
  runtime::HandoverCycle cycle(runtime::defaultCycleSettings());
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  examples::IntegratingArmDriver arm(cycle.controller().model(), q0);
  NobodyInView nobody;
  cycle.start(arm.state(), false);
  for (int k = 0; k < 1000; ++k) arm.apply(cycle.step(k * 0.001, arm.state(), nobody));
  EXPECT_NEAR(arm.state().time, 1.0, 1e-9);
  EXPECT_LT((arm.state().q - q0).cwiseAbs().maxCoeff(), 0.01);  // rad
  EXPECT_EQ(cycle.controller().fallbackCount(), 0);
  EXPECT_NE(cycle.machine().activePath().find("WaitForOffer"), std::string::npos);
}

// "A task": one class, added to the formulation before start(); the QP
// asks for its rows in every cycle.
TEST(ArchitectureDoc, TaskExampleJoinsEveryCycle) {
  runtime::HandoverCycle cycle(runtime::defaultCycleSettings());
  auto wrist = std::make_shared<examples::WristDampingTask>(20.0);
  cycle.formulation().addTask(wrist, 1e-3);
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  examples::IntegratingArmDriver arm(cycle.controller().model(), q0);
  NobodyInView nobody;
  cycle.start(arm.state(), false);
  for (int k = 0; k < 200; ++k) arm.apply(cycle.step(k * 0.001, arm.state(), nobody));
  EXPECT_TRUE(cycle.formulation().hasTask("wrist_damping"));
  EXPECT_EQ(wrist->calls, 200);
}

// "A state": registered next to the handover states and used in a machine;
// while it runs the speed scale is 0, after it the parent's 1 is back.
TEST(ArchitectureDoc, StateExampleRunsAndGivesBackItsChannel) {
  fsm::Registry registry;
  fsm::registerHandoverTypes(registry);
  registry.addState<examples::Pause>("Pause");
  const char* yaml = R"(
states:
  Pause: {type: Pause, duration: 0.2}
  Done:  {type: Rest, outcome: success}
initial: Pause
transitions:
  - [Pause, Done, Done]
)";
  fsm::StateMachine machine(YamlReader::loadString(yaml, "pause.yaml"), registry);
  fsm::test::RecordingController ctl;
  fsm::CommandLedger ledger(ctl);
  fsm::HandoverParams params =
      fsm::loadHandoverParams(YamlReader::loadFile(fsm::HandoverFsm::defaultConfigPath()).child("params"));
  fsm::HandoverContext ctx;
  ctx.params = &params;
  ctx.ledger = &ledger;
  machine.step(ctx);
  EXPECT_EQ(machine.activePath(), "Pause");
  EXPECT_DOUBLE_EQ(ctl.speed, 0.0);
  for (int k = 0; k < 300; ++k) {
    ctx.time += 0.001;
    machine.step(ctx);
  }
  EXPECT_EQ(machine.activePath(), "Done");
  EXPECT_DOUBLE_EQ(ctl.speed, 1.0);
  EXPECT_DOUBLE_EQ(ledger.current().speed_scale, 1.0);
}

}  // namespace
}  // namespace handover
