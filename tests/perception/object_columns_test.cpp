#include "perception/object_columns.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "config/input_error.hpp"
#include "perception/csv_pose_source.hpp"
#include "tests/support/temp_path.hpp"

using namespace handover;
using namespace handover::perception;

namespace {

PoseSample sample(double t, bool with_object) {
  PoseSample s;
  s.stamp = t;
  s.hand.position = {0.5 + t, 0.1, 0.3};
  s.hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3 + t, Eigen::Vector3d(1, 2, 3).normalized()));
  s.forearm.position = {0.8, 0.1, 0.3};
  s.upper_arm.position = {1.0, 0.2, 0.6};
  s.has_object = with_object;
  s.object.position = {0.45 + t, 0.05, 1.0 / 3.0};
  s.object.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7 - t, Eigen::Vector3d(-1, 0.5, 2).normalized()));
  return s;
}

}  // namespace

TEST(ObjectColumns, CsvRoundTripKeepsTheObject) {
  std::vector<PoseSample> in = {sample(0.0, true), sample(0.01, true), sample(0.02, true)};
  const std::string path = handover::test::uniqueTempPath("rt.csv");
  writePoseCsv(path, in);
  std::ifstream f(path);
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header, poseCsvHeaderWithObject());
  const std::vector<PoseSample> out = readPoseCsv(path);
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_TRUE(out[i].has_object);
    EXPECT_EQ(out[i].object.position, in[i].object.position);
    // positions bit for bit; a quaternion is renormalised on reading when its norm is not exactly 1
    EXPECT_LT((out[i].object.orientation.coeffs() - in[i].object.orientation.coeffs()).norm(), 1e-15);
    EXPECT_EQ(out[i].hand.position, in[i].hand.position);
  }
}

TEST(ObjectColumns, ArmOnlyFilesStayArmOnly) {
  const std::string path = handover::test::uniqueTempPath("arm.csv");
  writePoseCsv(path, {sample(0.0, false), sample(0.01, true)});  // not every sample has it
  std::ifstream f(path);
  std::string header;
  std::getline(f, header);
  EXPECT_EQ(header, poseCsvHeader());
  for (const PoseSample& s : readPoseCsv(path)) EXPECT_FALSE(s.has_object);
}

TEST(ObjectColumns, RejectsBadObjectFields) {
  Pose o;
  const std::string arm = "0,1,2,3,1,0,0,0,4,5,6,1,0,0,0,7,8,9,1,0,0,0";
  std::string line = arm + ",0.1,0.2,0.3,1,0,0,0";
  EXPECT_EQ(takeObjectColumns(line, ',', o), nullptr);
  EXPECT_EQ(line, arm);
  EXPECT_EQ(o.position, Eigen::Vector3d(0.1, 0.2, 0.3));
  for (const std::string bad : {",0.1,0.2,0.3,1,0,0", ",0.1,0.2,0.3,1,0,0,0,5", ",0.1,x,0.3,1,0,0,0",
                                ",0.1,0.2,0.3,2,0,0,0", ",0.1,0.2,inf,1,0,0,0", ""}) {
    std::string l = arm + bad;
    EXPECT_NE(takeObjectColumns(l, ',', o), nullptr) << bad;
  }
  // a file with the object header and a short row names the line
  const std::string path = handover::test::uniqueTempPath("bad.csv");
  std::ofstream(path) << poseCsvHeaderWithObject() << "\n" << arm << ",0.1,0.2\n";
  try {
    readPoseCsv(path);
    ADD_FAILURE() << "short row accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":2:"), std::string::npos) << e.what();
  }
}
