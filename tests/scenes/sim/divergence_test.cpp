// Simulator divergence (issue 16): a person's hand holding the object placed
// at an absurd but finite position (1e300 m, as a tracker glitch can) makes
// MuJoCo find a bad
// acceleration and reset the world. The simulation reports it (diverged(),
// a message naming what diverged and quoting MuJoCo) until reset(), and
// MuJoCo's own warning log (MUJOCO_LOG.TXT) is not written into the working
// folder; a MuJoCo error throws instead of ending the process.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>

#include "scenes/sim/mujoco_messages.hpp"
#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

using test::personAway;

/// Runs `body` with the working folder set to a fresh scratch folder; returns it.
template <class F>
std::filesystem::path inScratchFolder(F body) {
  std::string tmpl = (std::filesystem::temp_directory_path() / "handover_diverge_XXXXXX").string();
  const std::filesystem::path dir = mkdtemp(tmpl.data());
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  try {
    body();
  } catch (...) {
    std::filesystem::current_path(cwd);
    throw;
  }
  std::filesystem::current_path(cwd);
  return dir;
}

}  // namespace

TEST(Divergence, AbsurdPersonPoseIsReportedAndLeavesNoLog) {
  const std::filesystem::path dir = inScratchFolder([] {
    Simulation sim;
    sim.load();
    ASSERT_TRUE(sim.setHumanPoses(personAway()));
    // the person holds the object (a weld): a hand at 1e300 m drags it there
    sim.placeObject(personAway().hand * test::pose(0.0, 0.0, 0.05));
    sim.setObjectWeld(true);
    for (int i = 0; i < 100; ++i) test::holdStep(sim, test::readyPosture());
    EXPECT_FALSE(sim.diverged());
    EXPECT_EQ(sim.divergenceMessage(), "");

    HumanBodyPoses absurd = personAway();
    absurd.hand.translation().x() = 1e300;  // finite: setHumanPoses takes it
    ASSERT_TRUE(sim.setHumanPoses(absurd));
    const double t0 = sim.time();
    for (int i = 0; i < 20 && !sim.diverged(); ++i) test::holdStep(sim, test::readyPosture());
    ASSERT_TRUE(sim.diverged());
    const std::string msg = sim.divergenceMessage();
    EXPECT_NE(msg.find("diverged at t = "), std::string::npos) << msg;
    EXPECT_NE(msg.find("MuJoCo"), std::string::npos) << msg;
    EXPECT_LT(sim.time(), t0);  // MuJoCo did reset the world: the mark is needed

    // it stays marked until a reset
    ASSERT_TRUE(sim.setHumanPoses(personAway()));
    test::holdStep(sim, test::readyPosture());
    EXPECT_TRUE(sim.diverged());
    sim.reset(test::readyPosture(), 0.08);
    EXPECT_FALSE(sim.diverged());
    for (int i = 0; i < 50; ++i) test::holdStep(sim, test::readyPosture());
    EXPECT_FALSE(sim.diverged());
  });
  EXPECT_FALSE(std::filesystem::exists(dir / "MUJOCO_LOG.TXT"));
  std::filesystem::remove_all(dir);
}

TEST(Divergence, MujocoErrorsThrowInsteadOfEndingTheProcess) {
  const std::filesystem::path dir = inScratchFolder([] {
    installMujocoMessageHandlers();
    try {
      mju_error("a test error");
      FAIL() << "mju_error returned";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("MuJoCo error: a test error"), std::string::npos) << e.what();
    }
    mju_warning("a test warning");
    EXPECT_NE(std::string(lastMujocoWarning()).find("a test warning"), std::string::npos);
    clearMujocoWarning();
    EXPECT_EQ(std::string(lastMujocoWarning()), "");
  });
  EXPECT_FALSE(std::filesystem::exists(dir / "MUJOCO_LOG.TXT"));
  std::filesystem::remove_all(dir);
}

}  // namespace handover::sim
