#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace fs = std::filesystem;
using namespace handover;
using namespace handover::scenario;

namespace {

// a valid human-to-robot scenario; tests break one thing at a time
const char* kValid = R"(name: t
mode: human_to_robot
duration: 10.0
seed: 3
object:
  shape: cylinder
  size: [0.035, 0.20]
  mass: 0.3
  grasp: {pos: [0, 0, 0.05], rpy: [0, 1.5708, 0]}
  free_axis: z
robot:
  holds_object: false
human:
  stand: {pos: [1.0, 0.0], yaw: 3.1416}
  height: 1.75
  hand: right
  start: {pos: [0.85, 0.25, 0.10]}
  holds_object: {pos: [0, 0, 0.04]}
  script:
    - reach: {pos: [0.55, 0.05, 0.30], duration: 1.2}
    - wait: {until: fingers_on_object, timeout: 5.0, delay: 0.1}
    - release: {}
    - withdraw: {pos: [0.85, 0.25, 0.10], duration: 1.0}
sensor:
  rate_hz: 60
  latency: 0.02
  noise: {pos: 0.002, rot_deg: 1.0}
  dropouts: [[2.0, 2.4], [3.0, 3.5]]
expect:
  outcome: success
  max_total_time: 8.0
)";

class ScenarioFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("handover_scenario_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // replaces `from` (must occur) in the valid text
  static std::string mutate(const std::string& from, const std::string& to) {
    std::string t = kValid;
    const auto pos = t.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) t.replace(pos, from.size(), to);
    return t;
  }

  // 1-based line of the first line containing `marker`
  static int lineOf(const std::string& text, const std::string& marker) {
    const auto pos = text.find(marker);
    EXPECT_NE(pos, std::string::npos) << marker;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
  }

  // parses `text`, expects an InputError naming the file, `key` and the line of `marker`
  void expectError(const std::string& text, const std::string& key, const std::string& marker,
                   const std::string& extra = "") {
    const std::string path = write("s.yaml", text);
    try {
      parseScenario(path);
      ADD_FAILURE() << "no error for key " << key;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(path), std::string::npos) << msg;
      EXPECT_NE(msg.find("'" + key + "'"), std::string::npos) << msg;
      const std::string line = ":" + std::to_string(lineOf(text, marker)) + ":";
      EXPECT_NE(msg.find(line), std::string::npos) << "expected line " << line << " in: " << msg;
      if (!extra.empty()) {
        EXPECT_NE(msg.find(extra), std::string::npos) << msg;
      }
    }
  }

  fs::path dir_;
};

}  // namespace

TEST_F(ScenarioFiles, ValidFileParsesWithItsValues) {
  const Scenario s = parseScenario(write("s.yaml", kValid));
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.mode, Mode::HumanToRobot);
  EXPECT_DOUBLE_EQ(s.duration, 10.0);
  EXPECT_EQ(s.seed, 3);
  EXPECT_EQ(s.object.shape, Shape::Cylinder);
  ASSERT_EQ(s.object.size.size(), 2u);
  EXPECT_EQ(s.object.free_axis, 2);
  EXPECT_NEAR(s.object.grasp.translation().z(), 0.05, 1e-12);
  ASSERT_TRUE(s.human.holds_object.has_value());
  ASSERT_EQ(s.human.script.size(), 4u);
  EXPECT_EQ(s.human.script[0].kind, StepKind::Reach);
  EXPECT_FALSE(s.human.script[0].rpy.has_value());
  EXPECT_EQ(s.human.script[1].until, WaitUntil::FingersOnObject);
  EXPECT_DOUBLE_EQ(*s.human.script[1].timeout, 5.0);
  EXPECT_DOUBLE_EQ(s.human.script[1].delay, 0.1);
  EXPECT_DOUBLE_EQ(s.sensor.latency, 0.02);
  ASSERT_EQ(s.sensor.dropouts.size(), 2u);
  EXPECT_EQ(*s.expect.outcome, "success");
}

TEST_F(ScenarioFiles, UnknownKeys) {
  expectError(mutate("seed: 3", "seed: 3\nspeed: 2"), "speed", "speed:", "unknown key");
  expectError(mutate("mass: 0.3", "mass: 0.3\n  colour: red"), "object.colour", "colour:", "unknown key");
  expectError(mutate("delay: 0.1}", "delay: 0.1, untill: 3}"), "human.script[1].wait.untill", "untill");
}

TEST_F(ScenarioFiles, WrongTypes) {
  expectError(mutate("duration: 10.0", "duration: long"), "duration", "duration:", "number");
  expectError(mutate("holds_object: false", "holds_object: maybe"), "robot.holds_object", "maybe");
  expectError(mutate("size: [0.035, 0.20]", "size: 0.035"), "object.size", "size:");
}

TEST_F(ScenarioFiles, OutOfRangeValues) {
  expectError(mutate("duration: 10.0", "duration: -1"), "duration", "duration:", "> 0");
  expectError(mutate("mass: 0.3", "mass: 0"), "object.mass", "mass:", "> 0");
  expectError(mutate("rate_hz: 60", "rate_hz: 0"), "sensor.rate_hz", "rate_hz:", "> 0");
  expectError(mutate("noise: {pos: 0.002", "noise: {pos: -0.002"), "sensor.noise.pos", "noise:", ">= 0");
  expectError(mutate("latency: 0.02", "latency: -0.02"), "sensor.latency", "latency:");
  expectError(mutate("duration: 1.2}", "duration: 0}"), "human.script[0].reach.duration", "reach:");
  expectError(mutate("height: 1.75", "height: 3.5"), "human.height", "height:", "out of range");
  expectError(mutate("timeout: 5.0, delay: 0.1", "timeout: 5.0, delay: 6"), "human.script[1].wait.delay", "wait:");
}

TEST_F(ScenarioFiles, SizesMustFitTheShape) {
  expectError(mutate("shape: cylinder", "shape: box"), "object.size", "size:", "box");
  expectError(mutate("shape: cylinder", "shape: sphere"), "object.size", "size:", "sphere");
  expectError(mutate("size: [0.035, 0.20]", "size: [0.035, -0.20]"), "object.size[1]", "size:");
}

TEST_F(ScenarioFiles, UnknownEnumValues) {
  expectError(mutate("shape: cylinder", "shape: cone"), "object.shape", "shape:", "cone");
  expectError(mutate("mode: human_to_robot", "mode: robot_to_robot"), "mode", "mode:");
  expectError(mutate("hand: right", "hand: both"), "human.hand", "hand:");
  expectError(mutate("until: fingers_on_object", "until: robot_ready"), "human.script[1].wait.until", "wait:");
  expectError(mutate("release: {}", "jump: {}"), "human.script[2].jump", "jump:", "unknown script step");
}

TEST_F(ScenarioFiles, DropoutsMustBeOrdered) {
  expectError(mutate("[[2.0, 2.4], [3.0, 3.5]]", "[[3.0, 3.5], [2.0, 2.4]]"), "sensor.dropouts[1]", "dropouts:",
              "ordered");
  expectError(mutate("[[2.0, 2.4], [3.0, 3.5]]", "[[2.0, 2.4], [2.2, 3.5]]"), "sensor.dropouts[1]", "dropouts:");
  expectError(mutate("[[2.0, 2.4], [3.0, 3.5]]", "[[2.4, 2.0]]"), "sensor.dropouts[0]", "dropouts:");
}

TEST_F(ScenarioFiles, UnreachableHandTargets) {
  expectError(mutate("reach: {pos: [0.55, 0.05, 0.30]", "reach: {pos: [0.15, 0.05, 0.30]"),
              "human.script[0].reach.pos", "reach:", "reaches");
  expectError(mutate("withdraw: {pos: [0.85, 0.25, 0.10]", "withdraw: {pos: [0.85, 1.25, 0.10]"),
              "human.script[3].withdraw.pos", "withdraw:", "reaches");
  expectError(mutate("start: {pos: [0.85, 0.25, 0.10]}", "start: {pos: [0.85, 0.25, -0.50]}"), "human.start.pos",
              "start:", "reaches");
  // a pull that carries the hand past the arm's reach
  expectError(mutate("    - withdraw: {pos: [0.85, 0.25, 0.10], duration: 1.0}",
                     "    - grasp: {}\n    - pull: {dir: [-1, 0, 0], distance: 0.5, duration: 1.0}"),
              "human.script[4].pull.distance", "pull:", "reaches");
  // a shorter person cannot reach what a taller one can
  const std::string far = mutate("reach: {pos: [0.55, 0.05, 0.30]", "reach: {pos: [0.40, 0.05, 0.40]");
  EXPECT_NO_THROW(parseScenario(write("tall.yaml", far)));
  std::string shorter = far;
  shorter.replace(shorter.find("height: 1.75"), 12, "height: 1.40");
  expectError(shorter, "human.script[0].reach.pos", "reach:", "reaches");
}

TEST_F(ScenarioFiles, ModeMustFitWhoHoldsTheObject) {
  expectError(mutate("holds_object: false", "holds_object: true"), "robot.holds_object", "holds_object: true",
              "human_to_robot");
  // robot_to_human with the person still holding the object
  std::string t = mutate("mode: human_to_robot", "mode: robot_to_human");
  t.replace(t.find("holds_object: false"), 19, "holds_object: true");
  expectError(t, "human.holds_object", "holds_object: {pos", "robot_to_human");
}

TEST_F(ScenarioFiles, ScriptSequenceMustMakeSense) {
  expectError(mutate("    - withdraw: {pos: [0.85, 0.25, 0.10], duration: 1.0}",
                     "    - hold: {duration: 0.1}\n    - release: {} # again"),
              "human.script[4].release", "# again", "holds nothing");
}

TEST_F(ScenarioFiles, GraspWhileHoldingIsRejected) {
  expectError(mutate("    - release: {}", "    - grasp: {}"), "human.script[2].grasp", "- grasp: {}", "already holds");
}

TEST_F(ScenarioFiles, ConfigPathMustExist) {
  expectError(mutate("seed: 3", "seed: 3\nconfig: no/such/controller.yaml"), "config", "config:", "not found");
}

TEST_F(ScenarioFiles, ConfigRelativeToScenarioFolderAndOverridesChecked) {
  write("ctrl.yaml", "tracking:\n  orientation:\n    stiffness: 2.0\n  gains: [1, 2]\nposture: {weight: 5}\n");
  const std::string good =
      mutate("seed: 3", "seed: 3\nconfig: ctrl.yaml\nset:\n  tracking.orientation.stiffness: 4.0\n");
  const Scenario s = parseScenario(write("s.yaml", good));
  EXPECT_EQ(fs::path(s.config_path).filename(), "ctrl.yaml");
  EXPECT_DOUBLE_EQ(s.config["tracking"]["orientation"]["stiffness"].as<double>(), 4.0);
  EXPECT_DOUBLE_EQ(s.config["posture"]["weight"].as<double>(), 5.0);

  expectError(mutate("seed: 3", "seed: 3\nconfig: ctrl.yaml\nset:\n  tracking.orientation.stifness: 4.0\n"),
              "set.tracking.orientation.stifness", "stifness", "does not name a setting");
  expectError(mutate("seed: 3", "seed: 3\nconfig: ctrl.yaml\nset:\n  tracking.gains: 3\n"), "set.tracking.gains",
              "tracking.gains", "wrong kind");
  // several overrides in different sections all apply
  const Scenario two = parseScenario(write(
      "s2.yaml", mutate("seed: 3", "seed: 3\nconfig: ctrl.yaml\nset:\n  tracking.orientation.stiffness: 3.0\n"
                                   "  posture.weight: 7\n")));
  EXPECT_DOUBLE_EQ(two.config["tracking"]["orientation"]["stiffness"].as<double>(), 3.0);
  EXPECT_DOUBLE_EQ(two.config["posture"]["weight"].as<double>(), 7.0);
  EXPECT_EQ(two.config["tracking"]["gains"].size(), 2u);
}

TEST_F(ScenarioFiles, ExpectKeysAreChecked) {
  expectError(mutate("outcome: success", "outcome: great"), "expect.outcome", "outcome:");
  expectError(mutate("max_total_time: 8.0", "max_total_time: 80.0"), "expect.max_total_time", "max_total_time:",
              "duration");
  expectError(mutate("outcome: success", "outcome: success\n  aborts: -1"), "expect.aborts", "aborts:");
}

TEST_F(ScenarioFiles, MissingRequiredKeysAndSyntaxErrors) {
  const std::string no_name = std::string(kValid).substr(std::string(kValid).find('\n') + 1);
  try {
    parseScenario(write("s.yaml", no_name));
    ADD_FAILURE() << "missing name accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'name'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseScenario(write("s.yaml", "name: [unclosed\n")), InputError);
  EXPECT_THROW(parseScenario((dir_ / "absent.yaml").string()), InputError);
}

TEST(ShippedScenarios, AllParseAndCoverBothDirections) {
  const fs::path dir = fs::path(HANDOVER_SOURCE_DIR) / "scenes" / "scenarios";
  int count = 0, h2r = 0, r2h = 0;
  bool has_default = false;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    Scenario s;
    ASSERT_NO_THROW(s = parseScenario(entry.path().string()));
    (s.mode == Mode::HumanToRobot ? h2r : r2h)++;
    has_default = has_default || entry.path().filename() == "default.yaml";
    EXPECT_EQ(s.name, entry.path().stem().string()) << "name should match the file name";
  }
  EXPECT_GE(count, 12);
  EXPECT_GE(h2r, 1);
  EXPECT_GE(r2h, 1);
  EXPECT_TRUE(has_default);
}

// issue 17: values in range that are not physical, and poses that do not fit together
TEST_F(ScenarioFiles, ObjectsMustBePhysical) {
  expectError(mutate("size: [0.035, 0.20]", "size: [1.0e-12, 0.20]"), "object.size[0]", "size:", "5 mm");
  expectError(mutate("mass: 0.3", "mass: 1.0e-12"), "object.mass", "mass:", "10 g");
  // 0.3 kg in a 1 x 2 cm cylinder: 48 t/m^3
  expectError(mutate("size: [0.035, 0.20]\n  mass: 0.3", "size: [0.01, 0.02]\n  mass: 0.3"), "object.mass", "mass:",
              "density");
}

TEST_F(ScenarioFiles, ObjectMustFitTheGripperAtItsGrasp) {
  // a box 10 cm across the fingers
  const std::string wide = mutate("shape: cylinder\n  size: [0.035, 0.20]", "shape: box\n  size: [0.04, 0.10, 0.2]");
  std::string t = wide;
  t.replace(t.find("  free_axis: z\n"), 15, "");
  t.replace(t.find("rpy: [0, 1.5708, 0]"), 19, "rpy: [0, 0, 0]");
  expectError(t, "object.grasp", "shape:", "wide across the fingers");
  // rolled 1.1 rad about x: the fingers close across the cylinder's height
  expectError(mutate("rpy: [0, 1.5708, 0]", "rpy: [1.1, 0, 0]"), "object.grasp", "shape:", "wide across");
}

TEST_F(ScenarioFiles, GraspFrameAndHoldMustTouchTheObject) {
  expectError(mutate("grasp: {pos: [0, 0, 0.05]", "grasp: {pos: [0, 0, 0.15]"), "object.grasp", "shape:", "outside");
  expectError(mutate("grasp: {pos: [0, 0, 0.05]", "grasp: {pos: [1e308, 0, 0.05]"), "object.grasp.pos[0]", "grasp:");
  expectError(mutate("holds_object: {pos: [0, 0, 0.04]}", "holds_object: {pos: [0, 0, 0.5]}"), "human.holds_object",
              "holds_object: {pos", "grip point");
}

TEST_F(ScenarioFiles, SensorAndPlacementWithinSpecification) {
  expectError(mutate("noise: {pos: 0.002", "noise: {pos: 1e300"), "sensor.noise.pos", "noise:");
  expectError(mutate("rot_deg: 1.0", "rot_deg: 45"), "sensor.noise.rot_deg", "noise:");
  expectError(mutate("stand: {pos: [1.0, 0.0]", "stand: {pos: [10.0, 0.0]"), "human.stand.pos", "stand:");
  // a person may stand close (0.45 m: issue 16's case), not on the robot's base
  EXPECT_NO_THROW(parseScenario(write("close.yaml", mutate("stand: {pos: [1.0, 0.0]", "stand: {pos: [0.45, 0.0]"))));
  expectError(mutate("stand: {pos: [1.0, 0.0]", "stand: {pos: [0.3, 0.0]"), "human.stand.pos", "stand:");
  expectError(mutate("start: {pos: [0.85, 0.25, 0.10]}", "start: {pos: [0.85, 0.25, 0.10], rpy: [0, 0, 100]}"),
              "human.start.rpy[2]", "start:");
  expectError(mutate("holds_object: false", "holds_object: false\n  start_q: [2.8973, -0.785, 0, -2.356, 0, 1.571, 0.785]"),
              "robot.start_q[0]", "start_q");
}

TEST_F(ScenarioFiles, NamesAreTextAndKeysAppearOnce) {
  expectError(mutate("name: t", "name: \"a\\x01b\""), "name", "name:", "control character");
  expectError(mutate("name: t", "name: a\xff"), "name", "name:", "UTF-8");
  expectError(mutate("seed: 3", "seed: 3\nseed: 4"), "seed", "seed: 4", "duplicate");
  expectError(mutate("  mass: 0.3", "  mass: 0.3\n  mass: 0.4"), "object.mass", "mass: 0.4", "duplicate");
}

TEST_F(ScenarioFiles, ConfigThatIsNotAMapIsAnInputError) {
  // /etc/passwd parses as one YAML scalar; with `set:` it used to fault in yaml-cpp
  const std::string cfg = write("scalar.yaml", "root:x:0:0:root:/root:/bin/bash\n");
  expectError(mutate("seed: 3", "seed: 3\nconfig: " + cfg + "\nset:\n  period: 0.001"), "config", "config:",
              "not a controller config");
}

TEST_F(ScenarioFiles, ObjectMayDeclareMoreGrasps) {
  const std::string text = mutate("  free_axis: z\n", R"(  free_axis: z
  grasps:
    - {pos: [0, 0, 0.10], rpy: [3.1416, 0, 0], free_axis: z}
    - {pos: [0.0, 0.0, -0.02]}
)");
  const Scenario s = parseScenario(write("s.yaml", text));
  ASSERT_EQ(s.object.grasps.size(), 2u);
  EXPECT_EQ(s.object.grasps[0].free_axis, 2);
  EXPECT_NEAR(s.object.grasps[0].grasp.translation().z(), 0.10, 1e-12);
  EXPECT_NEAR(s.object.grasps[0].grasp.linear()(2, 2), -1.0, 1e-6);  // approach from above
  EXPECT_EQ(s.object.grasps[1].free_axis, -1);
  EXPECT_TRUE(s.object.grasps[1].grasp.linear().isIdentity());
  // the first grasp keeps its meaning
  EXPECT_NEAR(s.object.grasp.translation().z(), 0.05, 1e-12);
  // without the key: no extra grasps
  EXPECT_TRUE(parseScenario(write("t.yaml", kValid)).object.grasps.empty());
}

TEST_F(ScenarioFiles, BadGraspListsNameTheKey) {
  expectError(mutate("  free_axis: z\n", "  free_axis: z\n  grasps: {pos: [0, 0, 0]}\n"), "object.grasps", "grasps:",
              "list");
  expectError(mutate("  free_axis: z\n", "  free_axis: z\n  grasps:\n    - {pos: [0, 0, 0], free_axis: w}\n"),
              "object.grasps[0].free_axis", "free_axis: w");
  expectError(mutate("  free_axis: z\n", "  free_axis: z\n  grasps:\n    - {pos: [0, 0, 0], grip: 1}\n"),
              "object.grasps[0].grip", "grip: 1");
}

TEST_F(ScenarioFiles, EveryDeclaredGraspMustFitTheGripper) {
  // across the bottle's length (20 cm) the fingers cannot close
  expectError(mutate("  free_axis: z\n", "  free_axis: z\n  grasps:\n    - {pos: [0, 0, 0], rpy: [1.5708, 0, 0]}\n"),
              "object.grasps[0]", "shape: cylinder", "wide across the fingers");
}
