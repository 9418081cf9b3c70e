// Candidate enumeration: the free axis is covered, twins are half turns about
// the approach axis, and the pre-grasp stands off along -z.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "control/grasp/grasp_candidates.hpp"
#include "tests/support/units.hpp"

namespace handover::control::grasp {
namespace {

using handover::test::kDeg;

GraspSpec sideGraspAboutZ() {
  GraspSpec s;
  s.placement.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  s.placement.translation() = Vector3(-0.01, 0.0, 0.02);  // off the axis: the turn must carry it
  s.has_free_axis = true;
  s.free_axis = Vector3::UnitZ();
  return s;
}

TEST(GraspCandidates, CoverTheFreeAxisWithTwins) {
  CandidateOptions o;
  o.free_axis_step = 30.0 * kDeg;
  const GraspSpec spec = sideGraspAboutZ();
  const std::vector<GraspCandidate> c = enumerateGraspCandidates({spec}, o);
  ASSERT_EQ(c.size(), 24u);
  std::set<long> turns_deg;
  for (const GraspCandidate& g : c) {
    turns_deg.insert(std::lround(g.turn / kDeg));
    // a turn about the object's z through its origin: approach stays horizontal,
    // the grasp point stays at its height and distance from the axis
    const Vector3 p = g.in_object.translation();
    EXPECT_NEAR(p.z(), 0.02, 1e-12);
    EXPECT_NEAR(p.head<2>().norm(), 0.01, 1e-12);
    EXPECT_NEAR(g.in_object.linear().col(2).z(), 0.0, 1e-12);
    const Matrix3 expected = Eigen::AngleAxisd(g.turn, Vector3::UnitZ()).toRotationMatrix() * spec.placement.linear() *
                             (g.twin ? Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix() : Matrix3::Identity());
    EXPECT_LT((g.in_object.linear() - expected).norm(), 1e-12);
  }
  EXPECT_EQ(turns_deg.size(), 12u);
  EXPECT_EQ(*turns_deg.begin(), 0);
  EXPECT_EQ(*turns_deg.rbegin(), 330);
  // every turn appears once plain and once as a twin, the twin right after it
  for (std::size_t i = 0; i < c.size(); i += 2) {
    EXPECT_FALSE(c[i].twin);
    EXPECT_TRUE(c[i + 1].twin);
    EXPECT_EQ(c[i].turn, c[i + 1].turn);
    // same approach axis and grasp point, fingers reversed
    EXPECT_LT((c[i].in_object.translation() - c[i + 1].in_object.translation()).norm(), 1e-12);
    EXPECT_LT((c[i].in_object.linear().col(2) - c[i + 1].in_object.linear().col(2)).norm(), 1e-12);
    EXPECT_LT((c[i].in_object.linear().col(1) + c[i + 1].in_object.linear().col(1)).norm(), 1e-12);
  }
}

TEST(GraspCandidates, WithoutAFreeAxisOnlyTheGraspAndItsTwin) {
  GraspSpec spec = sideGraspAboutZ();
  spec.has_free_axis = false;
  const std::vector<GraspCandidate> c = enumerateGraspCandidates({spec}, CandidateOptions());
  ASSERT_EQ(c.size(), 2u);
  EXPECT_LT((c[0].in_object.matrix() - spec.placement.matrix()).norm(), 1e-12);
  CandidateOptions no_twin;
  no_twin.parallel_gripper_twin = false;
  EXPECT_EQ(enumerateGraspCandidates({spec}, no_twin).size(), 1u);
}

TEST(GraspCandidates, TwinsAlongTheAxisAreNotCountedTwice) {
  // top grasp of a bottle: approach along -z of the object, through its axis
  GraspSpec top;
  top.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  top.placement.translation() = Vector3(0.0, 0.0, 0.08);
  top.has_free_axis = true;
  CandidateOptions o;
  o.free_axis_step = 30.0 * kDeg;
  const std::vector<GraspCandidate> c = enumerateGraspCandidates({top}, o);
  EXPECT_EQ(c.size(), 12u);  // the twin of turn k is turn k + 6
  // an odd number of turns does not contain the half turn: twins come back
  o.free_axis_step = 360.0 / 7.0 * kDeg;
  EXPECT_EQ(enumerateGraspCandidates({top}, o).size(), 14u);
}

TEST(GraspCandidates, SeveralDeclaredGraspsAreAllExpanded) {
  GraspSpec a = sideGraspAboutZ();
  GraspSpec b;
  b.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  const std::vector<GraspCandidate> c = enumerateGraspCandidates({a, b}, CandidateOptions());
  ASSERT_EQ(c.size(), 26u);
  EXPECT_EQ(c.front().spec, 0);
  EXPECT_EQ(c.back().spec, 1);
}

TEST(GraspCandidates, PosedInTheWorldWithAStandoff) {
  const GraspSpec spec = sideGraspAboutZ();
  const std::vector<GraspCandidate> c = enumerateGraspCandidates({spec}, CandidateOptions());
  Isometry X_obj = Isometry::Identity();
  X_obj.linear() = Eigen::AngleAxisd(0.7, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  X_obj.translation() = Vector3(0.5, -0.1, 0.3);
  for (const GraspCandidate& g : c) {
    const Isometry X = graspInWorld(X_obj, g);
    EXPECT_LT((X.matrix() - (X_obj * g.in_object).matrix()).norm(), 1e-12);
    const Isometry pre = preGraspOf(X, 0.1);
    EXPECT_LT((pre.linear() - X.linear()).norm(), 1e-12);
    EXPECT_LT((X.translation() - pre.translation() - 0.1 * X.linear().col(2)).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace handover::control::grasp
