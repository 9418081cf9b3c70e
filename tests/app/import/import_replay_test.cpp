// A person recorded in a y-up world with scalar-last quaternions, the object
// tracked as its own body: imported through a mapping file alone and
// replayed in the simulator, the robot takes the object; hand_still_to_grasp
// is measured from the recorded hand (which settles later than the
// scenario's scripted one would).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/import/import_recording.hpp"
#include "app/run/run_scenario.hpp"
#include "perception/csv_pose_source.hpp"
#include "perception/recording/recording_mapping.hpp"
#include "scenes/human/two_link_arm.hpp"
#include "scenes/scenario/scenario_parser.hpp"

namespace fs = std::filesystem;
using namespace handover;

namespace {

constexpr double kRate = 120.0;
constexpr double kReachEnd = 2.6;  // s: the recorded hand settles here (the script's reach ends at 1.6 s)

double minimumJerk(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
}

/// A line "x,y,z,qx,qy,qz,qw" of a y-up recording for a pose in our (z-up) world.
std::string yUpRow(const Eigen::Isometry3d& ours) {
  // ours = U * recorded with U: (x, y, z) -> (x, -z, y)
  Eigen::Matrix3d U;
  U << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const Eigen::Vector3d p = U.transpose() * ours.translation();
  const Eigen::Quaterniond q(U.transpose() * ours.linear());
  char b[300];
  std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", p.x(), p.y(), p.z(), q.x(), q.y(), q.z(),
                q.w());
  return b;
}

}  // namespace

TEST(ImportReplay, SyntheticRecordingThroughAMappingIsTakenByTheRobot) {
  const fs::path dir = fs::temp_directory_path() / ("handover_import_" + std::to_string(::getpid()));
  fs::create_directories(dir);

  // the person of scenes/scenarios/default.yaml, reaching more slowly: hand, arm and bottle
  const Eigen::Vector3d from(0.85, 0.25, 0.10), to(0.55, 0.05, 0.30), shoulder(1.0, 0.2, 0.68);
  std::ofstream hand(dir / "hand.csv"), fore(dir / "forearm.csv"), upper(dir / "upper.csv"), obj(dir / "bottle.csv");
  for (auto* f : {&hand, &fore, &upper, &obj}) *f << "px,py,pz,qx,qy,qz,qw\n";
  for (int k = 0; k <= static_cast<int>(3.0 * kRate); ++k) {
    const double t = k / kRate;
    Eigen::Isometry3d h = Eigen::Isometry3d::Identity();
    h.translation() = from + minimumJerk((t - 0.4) / (kReachEnd - 0.4)) * (to - from);
    const human::ArmPlacement arm =
        human::placeArm(shoulder, h.translation(), human::ArmLengths{}, Eigen::Vector3d(0.2, 1.0, -1.0));
    Eigen::Isometry3d o = h;
    o.translation() += Eigen::Vector3d(0.0, 0.0, 0.04);
    hand << yUpRow(h) << "\n";
    fore << yUpRow(arm.forearm) << "\n";
    upper << yUpRow(arm.upper_arm) << "\n";
    obj << yUpRow(o) << "\n";
  }
  for (auto* f : {&hand, &fore, &upper, &obj}) f->close();
  std::ofstream(dir / "map.yaml") << "rate_hz: 120\nunits: m\nup: y\nquaternion: xyzw\n"
                                     "columns: {position: [px, py, pz], quaternion: [qx, qy, qz, qw]}\n"
                                     "hand: {file: hand.csv, long_axis: -x, back_axis: z}\n"
                                     "forearm: {file: forearm.csv, long_axis: z}\n"
                                     "upper_arm: {file: upper.csv, long_axis: z}\n"
                                     "object: {file: bottle.csv, long_axis: z}\n"
                                     "place: {transform: {}}\nhold_end: 8.0\n";

  app::ImportOptions io;
  io.mapping = (dir / "map.yaml").string();
  io.data_dir = dir.string();
  io.out = (dir / "tracked.csv").string();
  const std::string report = app::importRecordingToCsv(io);
  EXPECT_NE(report.find("tracked"), std::string::npos) << report;
  const std::vector<perception::PoseSample> samples = perception::readPoseCsv(io.out);
  ASSERT_FALSE(samples.empty());
  EXPECT_TRUE(samples.front().has_object);
  EXPECT_LT((samples.back().hand.position - to).norm(), 1e-9);

  const scenario::Scenario sc = scenario::parseScenario(std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/default.yaml");
  app::RunOptions ro;
  ro.plots = false;
  ro.tracker = "csv:" + io.out;
  const app::RunSummary r = app::runScenario(sc, ro);
  EXPECT_EQ(r.outcome, "success") << app::formatSummary(r);
  EXPECT_EQ(r.human_contacts, 0);
  ASSERT_TRUE(r.time_to_grasp && r.hand_still_to_grasp) << app::formatSummary(r);
  // the tracked hand comes to rest just before kReachEnd (speed below 5 cm/s, sensed through a 50 ms filter)
  const double rest = *r.time_to_grasp - *r.hand_still_to_grasp;
  EXPECT_GT(rest, kReachEnd - 0.35) << app::formatSummary(r);
  EXPECT_LT(rest, kReachEnd + 0.1) << app::formatSummary(r);
  fs::remove_all(dir);
}

TEST(ImportReplay, ShippedMappingParses) {
  const auto m = perception::recording::loadRecordingMapping(std::string(HANDOVER_SOURCE_DIR) +
                                                             "/scenes/recordings/kth_handover.yaml");
  EXPECT_TRUE(m.object.tracked);
  EXPECT_FALSE(m.scalar_first);
  for (const char* s : {"kth_take_above", "kth_take_side", "kth_take_above_left", "kth_take_side_left"}) {
    EXPECT_NO_THROW(scenario::parseScenario(std::string(HANDOVER_SOURCE_DIR) + "/scenes/recordings/" + s + ".yaml"))
        << s;
  }
}
