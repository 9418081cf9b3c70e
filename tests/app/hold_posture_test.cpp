// The hold job: our model's gravity keeps the simulated arm in the ready
// posture (TCP within 1 mm for 5 s); bad files are InputErrors naming them.
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "app/hold_posture.hpp"
#include "config/input_error.hpp"
#include "tests/support/temp_path.hpp"

namespace handover::app {
namespace {

TEST(HoldPosture, ReadyPostureHeldWithinOneMillimetreForFiveSeconds) {
  HoldOptions o;
  o.duration = 5.0;
  const HoldSummary s = holdPosture(o);
  EXPECT_NEAR(s.simulated_time, 5.0, 1e-9);
  EXPECT_EQ(s.steps, 5000);
  EXPECT_LT(s.max_tcp_drift, 1e-3);
  EXPECT_LT(s.max_joint_error, 5e-3);
  EXPECT_GT(s.realtime_factor, 0.0);
}

TEST(HoldPosture, WithoutGravityCompensationTheArmSags) {
  // the same loop with a wrong model (gravity off in the PD) must fail the
  // 1 mm bound: the check above is not vacuous
  HoldOptions o;
  o.duration = 1.0;
  o.kp *= 0.05;  // soft PD: gravity must come from the model
  o.kd *= 0.2;
  const HoldSummary with_model = holdPosture(o);
  EXPECT_LT(with_model.max_tcp_drift, 1e-3);
  // a URDF whose masses are halved: g(q) is wrong, the soft arm drifts
  std::ifstream in(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t pos = 0;
  int changed = 0;
  while ((pos = urdf.find("<mass value=\"", pos)) != std::string::npos) {
    pos += 13;
    const std::size_t end = urdf.find('"', pos);
    const double m = std::stod(urdf.substr(pos, end - pos));
    urdf.replace(pos, end - pos, std::to_string(0.5 * m));
    ++changed;
  }
  ASSERT_GT(changed, 7);
  const std::string path = handover::test::uniqueTempPath("panda_half_mass.urdf");
  {
    std::ofstream out(path);
    out << urdf;
  }
  o.urdf = path;
  const HoldSummary wrong = holdPosture(o);
  std::remove(path.c_str());
  EXPECT_GT(wrong.max_tcp_drift, 5e-3);
}

TEST(HoldPosture, MissingUrdfNamesTheFile) {
  HoldOptions o;
  o.urdf = "/nonexistent/robot.urdf";
  try {
    holdPosture(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/robot.urdf"), std::string::npos) << e.what();
  }
}

TEST(HoldPosture, MissingSceneNamesTheFile) {
  HoldOptions o;
  o.sim.scene_path = "/nonexistent/scene.xml";
  try {
    holdPosture(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.xml"), std::string::npos) << e.what();
  }
}

TEST(HoldPosture, NonPositiveDurationIsRejected) {
  HoldOptions o;
  o.duration = -1.0;
  EXPECT_THROW(holdPosture(o), InputError);
}

}  // namespace
}  // namespace handover::app
