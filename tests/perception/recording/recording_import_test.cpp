// Recordings written in foreign conventions (up axis, units, quaternion
// order, bone axes, wrist origin, mirrored, one file or many) must import to
// the same motion written in ours. The writers below undo each convention
// with literal matrices, independently of the importer's code.
#include "perception/recording/recording_import.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

#include "config/input_error.hpp"

namespace fs = std::filesystem;
using namespace handover;
using namespace handover::perception;
using namespace handover::perception::recording;

namespace {

constexpr double kRate = 100.0;  // Hz of the synthetic recordings

Eigen::Isometry3d pose(const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = p;
  return T;
}

Eigen::Matrix3d rot(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// Matrix from its columns.
Eigen::Matrix3d cols(const Eigen::Vector3d& x, const Eigen::Vector3d& y, const Eigen::Vector3d& z) {
  Eigen::Matrix3d M;
  M << x, y, z;
  return M;
}

/// The motion in our convention: hand (grip point), forearm, upper arm, object.
struct Frame {
  Eigen::Isometry3d hand, forearm, upper_arm, object;
};

std::vector<Frame> ourMotion(int n) {
  std::vector<Frame> out;
  for (int k = 0; k < n; ++k) {
    const double t = k / kRate;
    Frame f;
    f.hand = pose({0.6 + 0.1 * std::sin(t), 0.1 * std::cos(1.3 * t), 0.3 + 0.05 * std::sin(2 * t)},
                  rot(0.4 * std::sin(t), {1, 2, 3}) * rot(0.3, {0, 0, 1}));
    f.forearm = pose({0.85, 0.15 + 0.02 * t, 0.25}, rot(1.2 + 0.2 * t, {0, 1, 0.2}));
    f.upper_arm = pose({1.0, 0.2, 0.55 - 0.01 * t}, rot(2.8 - 0.1 * t, {0.1, 1, 0}));
    f.object = pose({0.5 + 0.1 * std::sin(t), 0.1 * std::cos(1.3 * t), 0.32}, rot(0.2 + t, {-1, 0.5, 2}));
    out.push_back(f);
  }
  return out;
}

/// How a foreign recording is written. All matrices are literal.
struct Convention {
  std::string name;
  Eigen::Matrix3d up_to_ours = Eigen::Matrix3d::Identity();  ///< the recording's axes in a z-up frame
  Eigen::Isometry3d place = Eigen::Isometry3d::Identity();   ///< z-up frame in our world
  double metres_per_unit = 1.0;
  bool scalar_first = true;
  Eigen::Matrix3d bone = Eigen::Matrix3d::Identity();   ///< our bone frame in the recorded bone frame
  Eigen::Matrix3d hand = Eigen::Matrix3d::Identity();   ///< our hand frame in the recorded hand frame
  Eigen::Vector3d grip = Eigen::Vector3d::Zero();       ///< wrist to grip point, recorded hand frame, m
  Eigen::Matrix3d object = Eigen::Matrix3d::Identity(); ///< our object frame in the recorded object frame
  bool mirror = false;  ///< the recording holds the left/right-swapped motion
  bool one_file = false;
};

/// The recorded pose (recording world, its units) of a body whose pose in our world is `ours`.
Eigen::Isometry3d recorded(const Convention& c, const Eigen::Isometry3d& ours, const Eigen::Matrix3d& axes,
                           const Eigen::Vector3d& origin_to_ours = Eigen::Vector3d::Zero()) {
  Eigen::Isometry3d w = ours;
  if (c.mirror) {
    const Eigen::Matrix3d S = Eigen::Vector3d(1, -1, 1).asDiagonal();
    w = pose(S * ours.translation(), S * ours.linear() * S);
  }
  const Eigen::Isometry3d world_T_rec = pose(c.place.translation(), c.place.linear() * c.up_to_ours);
  Eigen::Isometry3d rec = world_T_rec.inverse() * w;
  rec.linear() = rec.linear() * axes.transpose();
  rec.translation() -= rec.linear() * origin_to_ours;
  rec.translation() /= c.metres_per_unit;
  return rec;
}

std::string tempDir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("handover_rec_" + std::to_string(::getpid()) + "_" + name);
  fs::create_directories(p);
  return p.string();
}

std::string quatCells(const Eigen::Matrix3d& R, bool scalar_first) {
  const Eigen::Quaterniond q(R);
  char b[200];
  if (scalar_first) std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g,%.17g", q.w(), q.x(), q.y(), q.z());
  else std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g,%.17g", q.x(), q.y(), q.z(), q.w());
  return b;
}

std::string posCells(const Eigen::Vector3d& p) {
  char b[120];
  std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g", p.x(), p.y(), p.z());
  return b;
}

/// Writes the motion in convention `c` into `dir`; returns the body part of
/// the mapping (the rest is added by each test).
std::string writeRecording(const Convention& c, const std::vector<Frame>& motion, const std::string& dir) {
  const char* bodies[4] = {"hand", "forearm", "upper_arm", "object"};
  auto rec = [&](const Frame& f, int b) {
    switch (b) {
      case 0: return recorded(c, f.hand, c.hand, c.grip);
      case 1: return recorded(c, f.forearm, c.bone);
      case 2: return recorded(c, f.upper_arm, c.bone);
      default: return recorded(c, f.object, c.object);
    }
  };
  const std::string qn = c.scalar_first ? "qw,qx,qy,qz" : "qx,qy,qz,qw";
  if (c.one_file) {
    std::ofstream out(dir + "/all.csv");
    out << "time";
    for (const char* b : bodies) {
      out << "," << b << "_x," << b << "_y," << b << "_z";
      for (const char* q : {"_q0", "_q1", "_q2", "_q3"}) out << "," << b << q;
    }
    out << "\n";
    for (std::size_t k = 0; k < motion.size(); ++k) {
      out << k / kRate;
      for (int b = 0; b < 4; ++b) {
        const Eigen::Isometry3d r = rec(motion[k], b);
        out << "," << posCells(r.translation()) << "," << quatCells(r.linear(), c.scalar_first);
      }
      out << "\n";
    }
    return "";
  }
  for (int b = 0; b < 4; ++b) {
    std::ofstream out(dir + "/" + bodies[b] + ".csv");
    out << "x,y,z," << qn << "\n";
    for (const Frame& f : motion) {
      const Eigen::Isometry3d r = rec(f, b);
      out << posCells(r.translation()) << "," << quatCells(r.linear(), c.scalar_first) << "\n";
    }
  }
  return "";
}

void expectPose(const Pose& got, const Eigen::Isometry3d& want, const std::string& what) {
  EXPECT_LT((got.position - want.translation()).norm(), 1e-9) << what;
  EXPECT_LT((got.orientation.toRotationMatrix() - want.linear()).norm(), 1e-9) << what;
}

const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();

/// The mapping text that describes convention `c` for the per-body files.
std::string filesMapping(const std::string& units, const std::string& up, const std::string& quat,
                         const std::string& bone_axis, const std::string& hand_axes, const std::string& object_axis,
                         const std::string& place, const std::string& extra = "") {
  const std::string q = quat == "wxyz" ? "[qw, qx, qy, qz]" : "[qx, qy, qz, qw]";
  return "rate_hz: 100\nunits: " + units + "\nup: " + up + "\nquaternion: " + quat +
         "\ncolumns: {position: [x, y, z], quaternion: " + q + "}\n" + "hand: {file: hand.csv, " + hand_axes +
         "}\nforearm: {file: forearm.csv, long_axis: " + bone_axis + "}\nupper_arm: {file: upper_arm.csv, long_axis: " +
         bone_axis + "}\nobject: {file: object.csv, long_axis: " + object_axis + "}\nplace: " + place + "\n" + extra;
}

void expectMotion(const ImportedRecording& got, const std::vector<Frame>& want) {
  ASSERT_EQ(got.samples.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    const PoseSample& s = got.samples[k];
    EXPECT_NEAR(s.stamp, k / kRate, 1e-12);
    ASSERT_TRUE(s.has_object);
    expectPose(s.hand, want[k].hand, "hand " + std::to_string(k));
    expectPose(s.forearm, want[k].forearm, "forearm " + std::to_string(k));
    expectPose(s.upper_arm, want[k].upper_arm, "upper_arm " + std::to_string(k));
    expectPose(s.object, want[k].object, "object " + std::to_string(k));
  }
}

}  // namespace

TEST(RecordingImport, OurOwnConventionImportsUnchanged) {
  const auto motion = ourMotion(50);
  Convention c;  // z up, m, w first, bones along z, hand x from the fingers, z out of the back
  const std::string dir = tempDir("ours");
  writeRecording(c, motion, dir);
  const auto m = parseRecordingMapping(
      filesMapping("m", "z", "wxyz", "z", "long_axis: -x, back_axis: z", "z", "{transform: {}}"), "ours.yaml", dir);
  expectMotion(importRecording(m, dir), motion);
}

TEST(RecordingImport, YUpMillimetresScalarLastBonesAlongMinusXWristOrigin) {
  const auto motion = ourMotion(60);
  Convention c;
  c.up_to_ours = cols(X, Z, -Y);  // the recording's y is our up: (x, y, z) -> (x, -z, y)
  c.place = pose({0.3, -0.2, 0.1}, rot(0.7, Z));
  c.metres_per_unit = 0.001;
  c.scalar_first = false;
  c.bone = cols(Y, -Z, -X);   // our z along the recorded -x, our x the recorded y
  c.hand = cols(X, -Z, Y);    // our x = -(-x) (fingers to wrist), our z = the recorded y (back of the hand)
  c.grip = 0.08 * -X;         // grip point 8 cm from the wrist along the bone
  c.object = cols(Y, Z, X);   // the object's long axis is its recorded x
  const std::string dir = tempDir("yup");
  writeRecording(c, motion, dir);
  const auto m = parseRecordingMapping(
      filesMapping("mm", "y", "xyzw", "-x", "long_axis: -x, back_axis: y, grip: 0.08", "x",
                   "{transform: {pos: [0.3, -0.2, 0.1], rpy: [0, 0, 0.7]}}"),
      "yup.yaml", dir);
  expectMotion(importRecording(m, dir), motion);
}

TEST(RecordingImport, MirroredCentimetresScalarFirstBonesAlongY) {
  const auto motion = ourMotion(40);
  Convention c;
  c.up_to_ours = cols(X, Z, -Y);
  c.metres_per_unit = 0.01;
  c.mirror = true;             // a left arm recorded; we replay it as a right one
  c.bone = cols(Z, X, Y);      // our z along the recorded y, our x the recorded z
  c.hand = cols(-Y, -X, -Z);   // fingers along +y, back of the hand along -z
  c.object = cols(X, Y, Z);
  const std::string dir = tempDir("mirror");
  writeRecording(c, motion, dir);
  const auto m = parseRecordingMapping(
      filesMapping("cm", "y", "wxyz", "y", "long_axis: y, back_axis: -z", "z", "{transform: {}}", "mirror: true\n"),
      "mirror.yaml", dir);
  expectMotion(importRecording(m, dir), motion);
}

TEST(RecordingImport, OneFileWithTimeColumnWindowSpeedAndHeldEnd) {
  const auto motion = ourMotion(100);
  Convention c;
  c.one_file = true;
  c.scalar_first = false;
  const std::string dir = tempDir("onefile");
  writeRecording(c, motion, dir);
  std::string text =
      "time_column: time\nunits: m\nup: z\nquaternion: xyzw\nfile: all.csv\n"
      "hand: {columns: {position: [hand_x, hand_y, hand_z], quaternion: [hand_q0, hand_q1, hand_q2, hand_q3]},"
      " long_axis: -x, back_axis: z}\n";
  for (const char* b : {"forearm", "upper_arm", "object"}) {
    const std::string s(b);
    text += s + ": {columns: {position: [" + s + "_x, " + s + "_y, " + s + "_z], quaternion: [" + s + "_q0, " + s +
            "_q1, " + s + "_q2, " + s + "_q3]}, long_axis: z}\n";
  }
  text += "place: {transform: {}}\nwindow: {start: 0.2, end: 0.6}\nspeed: 0.8\nhold_end: 0.5\n";
  const auto got = importRecording(parseRecordingMapping(text, "onefile.yaml", dir), dir);

  // rows 20..60 of the recording, slowed down, then the last one held for 0.5 s at the slowed spacing
  const std::size_t rows = 41;
  const double dt = 0.01 / 0.8;
  ASSERT_EQ(got.recorded_rows, rows);
  ASSERT_EQ(got.samples.size(), rows + static_cast<std::size_t>(std::floor(0.5 / dt + 1e-9)));
  for (std::size_t i = 0; i < got.samples.size(); ++i) {
    const Frame& f = motion[20 + std::min(i, rows - 1)];
    EXPECT_NEAR(got.samples[i].stamp, i * dt, 1e-9);
    expectPose(got.samples[i].hand, f.hand, "hand " + std::to_string(i));
    expectPose(got.samples[i].object, f.object, "object " + std::to_string(i));
  }
}

TEST(RecordingImport, ObjectInTheHandFollowsTheHand) {
  const auto motion = ourMotion(20);
  Convention c;
  const std::string dir = tempDir("inhand");
  writeRecording(c, motion, dir);
  std::string text = filesMapping("m", "z", "wxyz", "z", "long_axis: -x, back_axis: z", "z", "{transform: {}}");
  const std::string tracked = "object: {file: object.csv, long_axis: z}";
  text.replace(text.find(tracked), tracked.size(), "object: {in_hand: {pos: [0, 0, 0.05]}}");
  const auto got = importRecording(parseRecordingMapping(text, "inhand.yaml", dir), dir);
  for (std::size_t k = 0; k < motion.size(); ++k) {
    const Eigen::Isometry3d want = motion[k].hand * pose({0, 0, 0.05}, Eigen::Matrix3d::Identity());
    expectPose(got.samples[k].object, want, "object " + std::to_string(k));
  }
}

TEST(RecordingImport, ReceiverPlacedAtTheRobotGiverAcrossTheTable) {
  // y-up recording; the receiver's hip circles around (1, 2) (horizontal x, -z), the giver's is 1.3 m away
  const std::string dir = tempDir("place");
  const auto motion = ourMotion(30);
  Convention c;
  c.up_to_ours = cols(X, Z, -Y);
  writeRecording(c, motion, dir);
  std::ofstream r(dir + "/receiver.csv"), g(dir + "/giver.csv");
  r.precision(17);
  g.precision(17);
  r << "x,y,z,qw,qx,qy,qz\n";
  g << "x,y,z,qw,qx,qy,qz\n";
  const double heading = 0.4;  // receiver-to-giver direction in the recording's horizontal plane (x, -z)
  for (int k = 0; k < 30; ++k) {
    const double a = 2 * M_PI * k / 30;
    // recorded (x, y, z): horizontal (x, -z) -> z = -horizontal y; the floor is at y = 0.1
    const Eigen::Vector2d rh(1.0 + 0.01 * std::cos(a), 2.0 + 0.01 * std::sin(a));
    const Eigen::Vector2d gh = Eigen::Vector2d(1.0, 2.0) + 1.3 * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    r << rh.x() << ",1.0," << -rh.y() << ",1,0,0,0\n";
    g << gh.x() << ",1.0," << -gh.y() << ",1,0,0,0\n";
  }
  r.close();
  g.close();
  const auto m = parseRecordingMapping(
      filesMapping("m", "y", "wxyz", "z", "long_axis: -x, back_axis: z", "z",
                   "{receiver: {file: receiver.csv}, giver: {file: giver.csv}, floor: 0.1}"),
      "place.yaml", dir);
  const ImportedRecording got = importRecording(m, dir);
  const Eigen::Isometry3d& T = got.world_T_recording;
  // the receiver's mean on the origin, on our floor height; the giver straight along +x
  const Eigen::Vector3d receiver = T * Eigen::Vector3d(1.0, 0.1, -2.0);
  const Eigen::Vector3d giver = T * Eigen::Vector3d(1.0 + 1.3 * std::cos(heading), 0.1, -(2.0 + 1.3 * std::sin(heading)));
  EXPECT_LT(receiver.head<2>().norm(), 1e-9);
  EXPECT_NEAR(receiver.z(), kFloorHeight, 1e-9);
  EXPECT_NEAR(giver.x(), 1.3, 1e-9);
  EXPECT_NEAR(giver.y(), 0.0, 1e-9);
  // and the poses are those of that transform
  const Eigen::Isometry3d hand_rec = recorded(c, motion[5].hand, c.hand);
  EXPECT_LT((got.samples[5].hand.position - (T * hand_rec).translation()).norm(), 1e-9);
}

TEST(RecordingImport, BadInputNamesTheFileAndWhatIsWrong) {
  const auto motion = ourMotion(10);
  Convention c;
  const std::string dir = tempDir("bad");
  writeRecording(c, motion, dir);
  const std::string good = filesMapping("m", "z", "wxyz", "z", "long_axis: -x, back_axis: z", "z", "{transform: {}}");

  // unknown key: file, key and line
  try {
    parseRecordingMapping(good + "spead: 2\n", "bad.yaml", dir);
    ADD_FAILURE() << "unknown key accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spead"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(":11"), std::string::npos) << e.what();
  }
  // a bad axis
  EXPECT_THROW(parseRecordingMapping(filesMapping("m", "w", "wxyz", "z", "long_axis: -x, back_axis: z", "z",
                                                  "{transform: {}}"),
                                     "bad.yaml", dir),
               InputError);
  // hand axes that are not perpendicular
  EXPECT_THROW(parseRecordingMapping(filesMapping("m", "z", "wxyz", "z", "long_axis: -x, back_axis: x", "z",
                                                  "{transform: {}}"),
                                     "bad.yaml", dir),
               InputError);
  // a column that is not in the file: names the file and the column
  std::string text = good;
  text.replace(text.find("[qw, qx, qy, qz]"), 16, "[qw, qx, qy, qq]");
  try {
    importRecording(parseRecordingMapping(text, "bad.yaml", dir), dir);
    ADD_FAILURE() << "missing column accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hand.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'qq'"), std::string::npos) << e.what();
  }
  // the wrong quaternion order on a non-unit reading is caught by its norm
  std::ofstream(dir + "/forearm.csv") << "x,y,z,qw,qx,qy,qz\n0,0,0,2,0,0,0\n";
  EXPECT_THROW(importRecording(parseRecordingMapping(good, "bad.yaml", dir), dir), InputError);
  // a missing data folder
  EXPECT_THROW(importRecording(parseRecordingMapping(good, "bad.yaml", dir), dir + "/nope"), InputError);
}
