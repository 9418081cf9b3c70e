// config/grasp_selection.yaml: the shipped file loads, values are read, bad
// input is an InputError naming the file and the key.
#include <gtest/gtest.h>

#include <cmath>

#include "config/input_error.hpp"
#include "control/grasp/grasp_selection_config.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace handover::control::grasp {
namespace {

GraspSelectionConfig fromText(const std::string& text) {
  return graspSelectionConfigFrom(YamlReader::loadString(text, "test.yaml"));
}

// the message of the InputError thrown by parsing `text`
std::string errorOf(const std::string& text) {
  try {
    fromText(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GraspSelectionConfig, ShippedFileLoadsWithSeedsInsideTheLimits) {
  const Model& model = testing::panda();
  const GraspSelectionConfig& c = testing::shippedConfig();
  EXPECT_EQ(c.frame, "tcp");
  EXPECT_GE(c.seeds.size(), 3u);
  for (const Vector7& q : c.seeds) {
    EXPECT_TRUE((q.array() >= model.q_min.array()).all() && (q.array() <= model.q_max.array()).all()) << q.transpose();
  }
  EXPECT_NEAR(c.candidates.free_axis_step, 30.0 * M_PI / 180.0, 1e-12);
  EXPECT_GT(c.hysteresis, 0.0);
  EXPECT_FALSE(c.upright.position_offsets.empty());
}

TEST(GraspSelectionConfig, ReadsEveryGroup) {
  const GraspSelectionConfig c = fromText(R"(
frame: hand
ik: {max_iterations: 12, position_tolerance: 2.0e-4, orientation_tolerance_deg: 0.1, nullspace_max_step: 0.02,
     seeds: [[0, 0, 0, -1, 0, 1, 0]]}
candidates: {free_axis_step_deg: 45, parallel_gripper_twin: false, pre_grasp_standoff: 0.05}
score: {joint_margin: 3.0, margin_ref: 0.4, motion: 0.0}
hysteresis: 0.3
keep_tolerance: {position: 0.002, orientation_deg: 0.2}
table: {height: 0.1, clearance: 0.05}
cold_solves_per_update: 5
branch_solves_per_update: 0
upright: {yaw_step_deg: 20, tilt_tolerance_deg: 5, position_offsets: [[0, 0, 0], [0, 0, 0.1]]}
presentation_tilt_deg: 20
)");
  EXPECT_EQ(c.frame, "hand");
  EXPECT_EQ(c.ik.max_iterations, 12);
  EXPECT_DOUBLE_EQ(c.ik.position_tolerance, 2.0e-4);
  EXPECT_NEAR(c.ik.orientation_tolerance, 0.1 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(c.ik.nullspace_max_step, 0.02);
  ASSERT_EQ(c.seeds.size(), 1u);
  EXPECT_DOUBLE_EQ(c.seeds[0][3], -1.0);
  EXPECT_NEAR(c.candidates.free_axis_step, M_PI / 4, 1e-12);
  EXPECT_FALSE(c.candidates.parallel_gripper_twin);
  EXPECT_DOUBLE_EQ(c.candidates.pre_grasp_standoff, 0.05);
  EXPECT_DOUBLE_EQ(c.score.joint_margin, 3.0);
  EXPECT_DOUBLE_EQ(c.score.margin_ref, 0.4);
  EXPECT_DOUBLE_EQ(c.score.motion, 0.0);
  EXPECT_DOUBLE_EQ(c.hysteresis, 0.3);
  EXPECT_DOUBLE_EQ(c.keep_tolerance.position, 0.002);
  EXPECT_NEAR(c.keep_tolerance.orientation, 0.2 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(c.table_height, 0.1);
  EXPECT_DOUBLE_EQ(c.table_clearance, 0.05);
  EXPECT_EQ(c.cold_solves_per_update, 5);
  EXPECT_EQ(c.branch_solves_per_update, 0);
  EXPECT_NEAR(c.upright.tilt_tolerance, 5.0 * M_PI / 180.0, 1e-12);
  ASSERT_EQ(c.upright.position_offsets.size(), 2u);
  EXPECT_DOUBLE_EQ(c.upright.position_offsets[1].z(), 0.1);
  EXPECT_NEAR(c.presentation_tilt, 20.0 * M_PI / 180.0, 1e-12);
}

TEST(GraspSelectionConfig, RejectsBadInputNamingFileAndKey) {
  const std::string unknown = errorOf("score: {joint_margins: 1.0}\n");
  EXPECT_NE(unknown.find("test.yaml"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("joint_margins"), std::string::npos) << unknown;
  EXPECT_NE(errorOf("ik: {position_tolerance: -1.0e-4}\n").find("ik.position_tolerance"), std::string::npos);
  EXPECT_NE(errorOf("candidates: {free_axis_step_deg: 0}\n").find("free_axis_step_deg"), std::string::npos);
  EXPECT_NE(errorOf("ik: {seeds: [[0, 0, 0]]}\n").find("ik.seeds"), std::string::npos);
  EXPECT_NE(errorOf("hysteresis: lots\n").find("hysteresis"), std::string::npos);
  EXPECT_NE(errorOf("keep_tolerance: {position: 0.5}\n").find("keep_tolerance.position"), std::string::npos);
  EXPECT_NE(errorOf("keep_tolerance: {distance: 0.005}\n").find("distance"), std::string::npos);
  EXPECT_NE(errorOf("upright: {position_offsets: []}\n").find("position_offsets"), std::string::npos);
  EXPECT_NE(errorOf("branch_solves_per_update: -1\n").find("branch_solves_per_update"), std::string::npos);
  EXPECT_NE(errorOf("presentation_tilt_deg: 90\n").find("presentation_tilt_deg"), std::string::npos);
}

}  // namespace
}  // namespace handover::control::grasp
