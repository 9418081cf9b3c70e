// The validation `check` and `run` share (app/validate): controller configs
// and `set:` overrides reported at the scenario's line, the control period,
// the start posture against the table and the person, gravity against the
// scaled torque limits. Each case was accepted by `check` before issue 17.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "app/batch/scenario_variation.hpp"
#include "app/validate/scenario_validation.hpp"
#include "config/input_error.hpp"
#include "config/yaml_reader.hpp"
#include "control/controller_config.hpp"
#include "control/controller_config_bounds.hpp"
#include "fsm/handover/handover_params.hpp"
#include "tests/support/temp_path.hpp"

namespace fs = std::filesystem;
using namespace handover;

namespace {

std::string shipped(const std::string& name) { return std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/" + name; }

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// default.yaml with `from` replaced by `to`, written to a temporary file
std::string derived(const std::string& from, const std::string& to, const std::string& from2 = "",
                    const std::string& to2 = "") {
  std::string t = readText(shipped("default.yaml"));
  for (const auto& [f, r] : {std::make_pair(from, to), std::make_pair(from2, to2)}) {
    if (f.empty()) continue;
    const auto pos = t.find(f);
    EXPECT_NE(pos, std::string::npos) << f;
    if (pos != std::string::npos) t.replace(pos, f.size(), r);
  }
  const fs::path p = fs::path(handover::test::uniqueTempPath("validate.yaml"));
  std::ofstream(p) << t;
  return p.string();
}

int lineOf(const std::string& path, const std::string& marker) {
  const std::string t = readText(path);
  const auto pos = t.find(marker);
  EXPECT_NE(pos, std::string::npos) << marker;
  return 1 + static_cast<int>(std::count(t.begin(), t.begin() + static_cast<long>(pos), '\n'));
}

// expects an InputError at `path`:line-of-`marker` naming `key` and containing `extra`
void expectError(const std::string& path, const std::string& key, const std::string& marker, const std::string& extra) {
  try {
    app::loadValidScenario(path);
    ADD_FAILURE() << "accepted: " << key;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path + ":" + std::to_string(lineOf(path, marker)) + ":", 0), 0u) << m;
    EXPECT_NE(m.find("'" + key + "'"), std::string::npos) << m;
    EXPECT_NE(m.find(extra), std::string::npos) << m;
  }
}

}  // namespace

TEST(Validation, ShippedScenariosPass) {
  for (const auto& e : fs::directory_iterator(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios")) {
    if (e.path().extension() == ".yaml") EXPECT_NO_THROW(app::loadValidScenario(e.path().string())) << e.path();
  }
}

TEST(Validation, OverridesAreReportedAtTheScenarioLine) {
  expectError(derived("seed: 1", "seed: 1\nset:\n  period: 0.1"), "set.period", "period:", "too fast for the period");
  expectError(derived("seed: 1", "seed: 1\nset:\n  observation.stiffness: 1.0e7"), "set.observation.stiffness",
              "observation.stiffness", "pole");
  expectError(derived("seed: 1", "seed: 1\nset:\n  observation.damping: 1.0e5"), "set.observation.damping",
              "observation.damping", "pole");
  expectError(derived("seed: 1", "seed: 1\nset:\n  tracking.weight: abc"), "set.tracking.weight", "tracking.weight",
              "expected a number");
  expectError(derived("seed: 1", "seed: 1\nset:\n  tracking.weight: .nan"), "set.tracking.weight", "tracking.weight",
              "finite");
  expectError(derived("seed: 1", "seed: 1\nset:\n  posture.weight: 0\n  qp.regularisation: 0"), "set.qp.regularisation",
              "qp.regularisation", "singular");
  expectError(derived("seed: 1", "seed: 1\nset:\n  posture.target: [3, 0, 0, -1.5, 0, 1.5, 0]"), "set.posture.target",
              "posture.target", "outside");
}

TEST(Validation, PeriodMustMatchTheSimulator) {
  expectError(derived("seed: 1", "seed: 1\nset:\n  period: 1.0e-5"), "set.period", "period:", "simulator's step");
}

TEST(Validation, LatencyBeyondTheEstimatorsLimitIsAValidScenario) {
  // 300 ms latency > max_latency 0.2 s: the contract allows latencies up to
  // 1 s; staleness is the run's to report
  EXPECT_NO_THROW(handover::app::loadValidScenario(derived("rate_hz: 60", "rate_hz: 40\n  latency: 0.3")));
}

TEST(Validation, TorqueScaleMustHoldTheArmAgainstGravity) {
  expectError(derived("seed: 1", "seed: 1\nset:\n  limits.torque.scale: 0.001"), "set.limits.torque.scale",
              "limits.torque.scale", "gravity");
}

TEST(Validation, StartPostureClearOfTableAndPerson) {
  // shoulder forward and elbow open: the wrist goes through the table top
  expectError(derived("holds_object: false", "holds_object: false\n  start_q: [0, 1.7, 0, -0.3, 0, 1.571, 0.785]"),
              "robot.start_q", "start_q", "table");
  // the person's hand starts in front of the robot, the gripper starts in their forearm
  expectError(derived("holds_object: false", "holds_object: false\n  start_q: [0, 0.3, 0, -1.6, 0, 1.9, 0.785]",
                      "start: {pos: [0.85, 0.25, 0.10]", "start: {pos: [0.5, 0.0, 0.4]"),
              "robot.start_q", "start_q", "person's forearm");
}

TEST(Validation, ConfigFilesThatAreNotControllerConfigs) {
  // another config of the project: its own unknown key, named at the scenario's config line too
  const std::string fsm = derived("seed: 1", "seed: 1\nconfig: config/fsm.yaml");
  expectError(fsm, "config", "config:", "fsm.yaml");
}

TEST(Validation, ControllerEntriesOfUnknownTypes) {
  // the shipped controller config with one more task entry, of a type nobody registered
  std::string text = readText(std::string(HANDOVER_SOURCE_DIR) + "/config/controller.yaml");
  const std::string last = "  - {name: pose, type: pose, enabled: false}";
  ASSERT_NE(text.find(last), std::string::npos);
  text.replace(text.find(last), last.size(), last + "\n  - {name: wrist, type: no_such_task}");
  const fs::path cfg = fs::path(handover::test::uniqueTempPath("validate_unknown_task.yaml"));
  std::ofstream(cfg) << text;
  const std::string sc = derived("seed: 1", "seed: 1\nconfig: " + cfg.string());
  expectError(sc, "config", "config:", "no_such_task");
}

// `handover batch --vary` runs generated variants: each must pass the same
// validation, or the batch would report inputs that `check` never saw
TEST(Validation, GeneratedVariantsOfShippedScenariosPass) {
  for (const auto& e : fs::directory_iterator(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios")) {
    if (e.path().extension() != ".yaml") continue;
    const scenario::Scenario base = app::loadValidScenario(e.path().string());
    for (int k = 1; k <= 20; ++k) {
      EXPECT_NO_THROW(app::validateScenario(app::makeVariant(base, k))) << e.path() << " variant " << k;
    }
  }
}

// The state machine's phase gains (config/fsm.yaml params.tracking) are read
// in [0, 1000] 1/s^2 and applied critically damped at the controller's
// period, which the validation holds to the simulator's 1 ms step: the
// loader's whole range, and so the shipped values, keep the PD bound.
namespace handover::app {
namespace {
TEST(Validation, StateMachinePhaseGainsKeepThePdBound) {
  const control::ControllerConfig cfg = control::loadControllerConfig(control::defaultControllerConfigPath());
  const YamlReader fsm = YamlReader::loadFile(std::string(HANDOVER_SOURCE_DIR) + "/config/fsm.yaml");
  const fsm::HandoverParams p = fsm::loadHandoverParams(fsm.child("params"));
  for (double k : {p.tracking_translation_stiffness, p.tracking_orientation_stiffness, 1000.0}) {
    EXPECT_EQ(control::pdGainsProblem(k, 2.0 * std::sqrt(k), cfg.period), "") << "K = " << k;
  }
}
}  // namespace
}  // namespace handover::app
