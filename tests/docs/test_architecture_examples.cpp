// The worked examples of docs/architecture.md, kept honest: each example file
// (docs/examples/) is quoted verbatim in the document, compiles, and does
// what the document says when plugged in the way the document shows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "docs/examples/integrating_arm_driver.hpp"
#include "docs/examples/pause_state.hpp"
#include "docs/examples/wrist_damping_task.hpp"
#include "control/controller_config.hpp"
#include "fsm/core/registry.hpp"
#include "fsm/core/state_machine.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "runtime/handover_cycle.hpp"
#include "control/model/robot_description.hpp"
#include "tests/fsm/handover/fake_world.hpp"
#include "tests/support/temp_path.hpp"

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

// "A task": a class, a registry line and a YAML entry in config/controller.yaml's
// `tasks:` (here appended to the shipped file's list, as the document shows it).
constexpr const char* kWristEntry = "{name: wrist_damping, type: wrist_damping, damping: 20.0, weight: 1.0e-3}";

runtime::CycleSettings settingsWithEntry(const std::string& entry) {
  runtime::CycleSettings settings = runtime::defaultCycleSettings();
  examples::registerWristDamping(settings.registry);
  const YamlReader file = YamlReader::loadFile(control::defaultControllerConfigPath());
  YAML::Node doc = YAML::Clone(file.node());
  doc["tasks"].push_back(YAML::Load(entry));
  settings.controller = control::parseControllerConfig(YamlReader(doc, "controller.yaml", ""));
  return settings;
}

// built from its entry, the QP asks for its rows in every cycle
TEST(ArchitectureDoc, TaskExampleIsBuiltFromItsEntryAndJoinsEveryCycle) {
  EXPECT_NE(readFile("docs/architecture.md").find(std::string("  - ") + kWristEntry), std::string::npos);
  runtime::HandoverCycle cycle(settingsWithEntry(kWristEntry));
  const int index = cycle.controller().taskIndex("wrist_damping");
  ASSERT_GE(index, 0);
  const auto& wrist = dynamic_cast<const examples::WristDampingTask&>(cycle.controller().task(index));
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  examples::IntegratingArmDriver arm(cycle.controller().model(), q0);
  NobodyInView nobody;
  cycle.start(arm.state(), false);
  for (int k = 0; k < 200; ++k) arm.apply(cycle.step(k * 0.001, arm.state(), nobody));
  EXPECT_EQ(wrist.calls, 200);
  EXPECT_DOUBLE_EQ(cycle.controller().formulation().taskWeight("wrist_damping"), 1e-3);
}

// a state switches it by name through its handle, and its teardown (undo) gives it back
TEST(ArchitectureDoc, TaskExampleIsSwitchedByNameAndGivenBack) {
  runtime::HandoverCycle cycle(
      settingsWithEntry("{name: wrist_damping, type: wrist_damping, damping: 20.0, enabled: false}"));
  fsm::CommandLedger ledger(cycle.adapter());
  fsm::ControllerHandle ctrl;
  ctrl.bind(&ledger);
  const int wrist = ctrl.taskHandle("wrist_damping");
  ASSERT_GE(wrist, 0);
  EXPECT_FALSE(cycle.controller().taskEnabled(wrist));
  ctrl.setTaskEnabled(wrist, true);
  EXPECT_TRUE(cycle.controller().taskEnabled(wrist));
  ctrl.undo();
  EXPECT_FALSE(cycle.controller().taskEnabled(wrist));
  EXPECT_EQ(ctrl.taskHandle("no_such_task"), -1);
}

// the entry is read strictly: a parameter the factory does not read is refused
TEST(ArchitectureDoc, TaskEntryWithAnUnknownKeyIsRefused) {
  try {
    runtime::HandoverCycle cycle(settingsWithEntry("{name: wrist_damping, type: wrist_damping, damping: 20.0, dampnig: 1}"));
    ADD_FAILURE() << "an entry with an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dampnig"), std::string::npos) << e.what();
  }
  try {
    runtime::HandoverCycle cycle(settingsWithEntry("{name: wrist_damping, type: wrist_dampnig, damping: 20.0}"));
    ADD_FAILURE() << "an entry with an unknown type was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wrist_dampnig"), std::string::npos) << e.what();
  }
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

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

/// The arm after `steps` cycles of the hold table from a posture 0.05 rad off
/// the held one, on `robot`'s model, driven by the integrating driver.
io::ArmState holdRun(const control::RobotDescription& robot, int steps) {
  runtime::CycleSettings settings = runtime::defaultCycleSettings();
  settings.robot = robot;
  settings.fsm_config_path = std::string(HANDOVER_SOURCE_DIR) + "/config/fsm_hold.yaml";
  runtime::HandoverCycle cycle(settings);
  io::Vector7 q0 = cycle.controller().config().posture.target;
  q0.array() += 0.05;
  examples::IntegratingArmDriver arm(cycle.controller().model(), q0);
  NobodyInView nobody;
  cycle.start(arm.state(), false);
  for (int k = 0; k < steps; ++k) arm.apply(cycle.step(k * 0.001, arm.state(), nobody));
  return arm.state();
}

// "Another 7-DoF arm": the Panda's URDF and description with every name
// changed run the cycle exactly as the Panda's (the simulator's side:
// tests/scenes/sim/simulation_load_test.cpp).
TEST(ArchitectureDoc, AnotherArmIsADescriptionChange) {
  EXPECT_NE(readFile("docs/architecture.md").find("### Another 7-DoF arm"), std::string::npos);
  const control::RobotDescription panda = control::defaultRobotDescription();
  const std::string folder = test::uniqueTempPath("arm7/");
  std::filesystem::create_directories(folder);
  std::ofstream(folder + "arm7.urdf") << replaceAll(readFile("scenes/panda.urdf"), "panda_", "arm7_");
  std::string yaml = replaceAll(readFile("config/robot.yaml"), "panda_", "arm7_");
  yaml = replaceAll(yaml, "urdf: ../scenes/panda.urdf", "urdf: arm7.urdf");
  std::ofstream(folder + "robot.yaml") << yaml;
  const control::RobotDescription arm7 = control::loadRobotDescription(folder + "robot.yaml");
  EXPECT_EQ(arm7.base_link, "arm7_link0");
  EXPECT_EQ(arm7.finger_links[0], "arm7_leftfinger");

  const io::ArmState a = holdRun(arm7, 300), p = holdRun(panda, 300);
  EXPECT_GT((p.q - (runtime::defaultCycleSettings().controller.posture.target.array() + 0.05).matrix()).norm(), 1e-3)
      << "the hold did not move the arm: the comparison says nothing";
  EXPECT_EQ(a.q, p.q);
  EXPECT_EQ(a.qd, p.qd);
  std::filesystem::remove_all(folder);
}

// The state tables docs/architecture.md names exist and load in the cycle.
TEST(ArchitectureDoc, TheJobsStateTablesLoad) {
  const std::string doc = readFile("docs/architecture.md");
  for (const char* table : {"config/fsm_reach.yaml", "config/fsm_reach_baseline.yaml", "config/fsm_hold.yaml"}) {
    EXPECT_NE(doc.find(table), std::string::npos) << table;
    runtime::CycleSettings settings = runtime::defaultCycleSettings();
    settings.fsm_config_path = std::string(HANDOVER_SOURCE_DIR) + "/" + table;
    EXPECT_NO_THROW(runtime::HandoverCycle cycle(settings)) << table;
  }
}

}  // namespace
}  // namespace handover
