#include "perception/csv_pose_source.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "config/input_error.hpp"
#include "perception/pose_codec.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "tests/support/temp_path.hpp"

namespace fs = std::filesystem;
using namespace handover;
using namespace handover::perception;

namespace {

std::vector<PoseSample> noisySamples() {
  SensorSettings cfg;
  cfg.noise_pos = 0.003;
  cfg.noise_rot_deg = 2.0;
  SimulatedPoseSensor s(cfg, 9);
  std::vector<PoseSample> out;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 0.001;
    io::HumanBodyPoses b;
    b.hand.translation() = Eigen::Vector3d(0.5 + 0.1 * t, 0.05, 0.3);
    b.hand.linear() = Eigen::AngleAxisd(t, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    s.observe(t, b);
    PoseSample p;
    while (s.poll(t, p)) out.push_back(p);
  }
  return out;
}

void expectSame(const Pose& a, const Pose& b) {
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.orientation.coeffs(), b.orientation.coeffs());
}

}  // namespace

TEST(CsvPoseSource, RoundTripIsExact) {
  const auto written = noisySamples();
  ASSERT_GT(written.size(), 50u);
  const std::string path = handover::test::uniqueTempPath("roundtrip.csv");
  writePoseCsv(path, written);
  const auto read = readPoseCsv(path);
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].stamp, written[i].stamp);
    expectSame(read[i].hand, written[i].hand);
    expectSame(read[i].forearm, written[i].forearm);
    expectSame(read[i].upper_arm, written[i].upper_arm);
  }
  // replay delivers them at their stamps (shifted), in order
  CsvPoseSource src(path, 2.0);
  PoseSample p;
  EXPECT_FALSE(src.poll(2.0 + written[0].stamp - 1e-3, p));
  EXPECT_TRUE(src.poll(2.0 + written[0].stamp, p));
  EXPECT_DOUBLE_EQ(p.stamp, written[0].stamp + 2.0);
  int n = 1;
  while (src.poll(100.0, p)) ++n;
  EXPECT_EQ(n, static_cast<int>(written.size()));
  fs::remove(path);
}

TEST(CsvPoseSource, BadFilesNameFileAndLine) {
  const std::string path = handover::test::uniqueTempPath("bad.csv");
  const std::string row = "0.5,0.5,0,0.3,1,0,0,0,0.7,0,0.3,1,0,0,0,0.9,0,0.5,1,0,0,0";
  auto expectBad = [&](const std::string& text, const std::string& where, const std::string& what) {
    std::ofstream(path) << text;
    try {
      readPoseCsv(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(path + where), std::string::npos) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  const std::string header = std::string(poseCsvHeader()) + "\n";
  expectBad("t,x\n" + row + "\n", ":1:", "header");
  expectBad(header + row + "\n0.6,1,2\n", ":3:", "too few");
  expectBad(header + row + ",7\n", ":2:", "too many");
  expectBad(header + "0.5,nan,0,0.3,1,0,0,0,0.7,0,0.3,1,0,0,0,0.9,0,0.5,1,0,0,0\n", ":2:", "finite");
  expectBad(header + "0.5,0.5,0,0.3,2,0,0,0,0.7,0,0.3,1,0,0,0,0.9,0,0.5,1,0,0,0\n", ":2:", "unit length");
  expectBad(header + row + "\n0.4" + row.substr(3) + "\n", ":3:", "goes back");
  expectBad(header + "0.5,a,0,0.3,1,0,0,0,0.7,0,0.3,1,0,0,0,0.9,0,0.5,1,0,0,0\n", ":2:", "not a number");
  EXPECT_THROW(readPoseCsv(handover::test::uniqueTempPath("absent.csv")), InputError);
  fs::remove(path);
}

namespace {
std::string oneRow() {
  char line[kMaxEncodedSample];
  PoseSample s;
  s.stamp = 0.5;
  encodeSample(s, ',', line, sizeof line);
  return line;
}
}  // namespace

// spreadsheet exports start with a UTF-8 byte-order mark: skipped, not "expected the header"
TEST(CsvPoseSource, ByteOrderMarkIsSkipped) {
  const std::string text = std::string("\xEF\xBB\xBF") + poseCsvHeader() + "\r\n" + oneRow() + "\r\n";
  const auto samples = parsePoseCsv(text, "bom.csv");
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_DOUBLE_EQ(samples[0].stamp, 0.5);
}

TEST(CsvPoseSource, OversizeLinesAndEndlessFilesAreRefused) {
  const std::string text = std::string(poseCsvHeader()) + "\n" + std::string(100000, '1') + "\n";
  try {
    parsePoseCsv(text, "long.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("long.csv:2: line longer"), std::string::npos) << e.what();
  }
  try {
    readPoseCsv("/dev/zero");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/dev/zero:", 0), 0u) << e.what();
  }
}

TEST(PoseDatagram, DecodesTheStreamFormatAndNamesEachRejection) {
  PoseSample s;
  const std::string good = "hpose " + oneRow();
  EXPECT_EQ(decodeDatagram(good.data(), good.size(), s), nullptr);
  EXPECT_DOUBLE_EQ(s.stamp, 0.5);
  const std::string prefix = "hpos " + oneRow();
  EXPECT_NE(decodeDatagram(prefix.data(), prefix.size(), s), nullptr);
  const std::string nul = std::string("hpose \0", 7) + oneRow();
  EXPECT_STREQ(decodeDatagram(nul.data(), nul.size(), s), "datagram contains a NUL byte");
  EXPECT_STREQ(decodeDatagram(good.data(), kMaxDatagram, s), "datagram too long");
  EXPECT_NE(decodeDatagram("hpose", 5, s), nullptr);
  EXPECT_NE(decodeDatagram("", 0, s), nullptr);
}

// The longest line the writer can produce (object columns, every number
// negative with 17 significant digits and an exponent) is read back: what
// `handover import` writes, `run --tracker csv:` accepts.
TEST(CsvPoseSource, LongestLinesWithTheObjectRoundTrip) {
  PoseSample s;
  s.stamp = 1234.5678901234567;
  const Eigen::Quaterniond q = Eigen::Quaterniond(-0.12345678901234567, -0.23456789012345678, -0.34567890123456789,
                                                  -0.45678901234567891).normalized();
  const Eigen::Vector3d p(-1.2345678901234567e-5, -0.12345678901234567, -1.2345678901234567);
  for (Pose* pose : {&s.hand, &s.forearm, &s.upper_arm, &s.object}) {
    pose->position = p;
    pose->orientation = q;
  }
  s.has_object = true;
  const std::string path = handover::test::uniqueTempPath("longest.csv");
  writePoseCsv(path, {s, s});
  const auto read = readPoseCsv(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_TRUE(read[0].has_object);
  expectSame(read[0].object, s.object);
  fs::remove(path);
}
