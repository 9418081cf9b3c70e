// BodyDrag without a window: mjv_ perturbation is CPU-only.
#include <gtest/gtest.h>

#include <cmath>

#include "app/render/body_drag.hpp"
#include "tests/app/render/test_models.hpp"

using namespace handover::render;
using handover::render::test::DataPtr;
using handover::render::test::loadXmlString;
using handover::render::test::ModelPtr;

namespace {

class BodyDragTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = loadXmlString(handover::render::test::kBoxSceneXml);
    m_ = model_.get();
    data_ = DataPtr(mj_makeData(m_));
    d_ = data_.get();
    mj_forward(m_, d_);
    mjv_defaultOption(&opt_);
    mjv_defaultScene(&scene_);
    mjv_makeScene(m_, &scene_, 500);
    mjv_defaultCamera(&cam_);
    cam_.type = mjCAMERA_FIXED;  // "front": looks along +y, x to the right, z up
    cam_.fixedcamid = mj_name2id(m_, mjOBJ_CAMERA, "front");
    mjv_updateScene(m_, d_, &opt_, nullptr, &cam_, mjCAT_ALL, &scene_);
    hand_ = mj_name2id(m_, mjOBJ_BODY, "hand");
    ball_ = mj_name2id(m_, mjOBJ_BODY, "ball");
  }
  void TearDown() override { mjv_freeScene(&scene_); }

  ModelPtr model_;
  DataPtr data_;
  mjModel* m_;
  mjData* d_;
  mjvOption opt_;
  mjvScene scene_;
  mjvCamera cam_;
  int hand_, ball_;
};

double angleBetween(const mjtNum a[4], const mjtNum b[4]) {
  const double dot = std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return 2.0 * std::acos(std::min(1.0, dot));
}

}  // namespace

TEST_F(BodyDragTest, TranslatingAMocapBodyMovesItWithTheMouse) {
  BodyDrag drag;
  drag.select(m_, d_, hand_);
  ASSERT_EQ(drag.selected(), hand_);
  ASSERT_TRUE(drag.begin(m_, d_, &scene_, mjPERT_TRANSLATE));
  ASSERT_TRUE(drag.held().has_value());
  EXPECT_EQ(drag.held()->name, "hand");
  EXPECT_TRUE(drag.held()->dragging);
  const mjtNum start[3] = {d_->xpos[3 * hand_], d_->xpos[3 * hand_ + 1], d_->xpos[3 * hand_ + 2]};

  // mouse to the right in the camera's vertical plane: +x in the world
  drag.move(m_, d_, &scene_, mjMOUSE_MOVE_V, 0.1, 0.0);
  const DraggedPose p1 = *drag.held();
  EXPECT_GT(p1.pos[0] - start[0], 0.02);
  EXPECT_NEAR(p1.pos[1], start[1], 1e-9) << "vertical-plane motion left the plane";
  EXPECT_NEAR(p1.pos[2], start[2], 1e-9);
  EXPECT_LT(angleBetween(p1.quat, d_->xquat + 4 * hand_), 1e-9) << "translation rotated the body";

  // mouse up: +z
  drag.move(m_, d_, &scene_, mjMOUSE_MOVE_V, 0.0, -0.1);
  const DraggedPose p2 = *drag.held();
  EXPECT_GT(std::fabs(p2.pos[2] - p1.pos[2]), 0.02);
  EXPECT_NEAR(p2.pos[0], p1.pos[0], 1e-9);

  // the pose lands in mjData, and kinematics put the body there
  drag.apply(m_, d_);
  mj_kinematics(m_, d_);
  const int mocap = m_->body_mocapid[hand_];
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(d_->mocap_pos[3 * mocap + i], p2.pos[i]);
    EXPECT_NEAR(d_->xpos[3 * hand_ + i], p2.pos[i], 1e-12);
  }

  // released: still held (the caller keeps using it) until handed back
  drag.end(m_, d_);
  ASSERT_TRUE(drag.held().has_value());
  EXPECT_FALSE(drag.held()->dragging);
  drag.releaseHeld();
  EXPECT_FALSE(drag.held().has_value());
}

TEST_F(BodyDragTest, RotatingAMocapBodyTurnsItRigidlyAboutTheReference) {
  BodyDrag drag;
  drag.select(m_, d_, hand_);
  ASSERT_TRUE(drag.begin(m_, d_, &scene_, mjPERT_ROTATE));
  const mjtNum* q0 = d_->xquat + 4 * hand_;
  const mjvPerturb& pert = drag.perturb();
  const double arm = std::hypot(std::hypot(d_->xpos[3 * hand_] - pert.refpos[0],
                                           d_->xpos[3 * hand_ + 1] - pert.refpos[1]),
                                d_->xpos[3 * hand_ + 2] - pert.refpos[2]);
  drag.move(m_, d_, &scene_, mjMOUSE_ROTATE_V, 0.2, 0.0);
  const DraggedPose p = *drag.held();
  EXPECT_GT(angleBetween(p.quat, q0), 0.1) << "no rotation";
  EXPECT_NEAR(std::sqrt(p.quat[0] * p.quat[0] + p.quat[1] * p.quat[1] + p.quat[2] * p.quat[2] +
                        p.quat[3] * p.quat[3]), 1.0, 1e-12);
  const double arm_after = std::hypot(std::hypot(p.pos[0] - pert.refpos[0], p.pos[1] - pert.refpos[1]),
                                      p.pos[2] - pert.refpos[2]);
  EXPECT_NEAR(arm_after, arm, 1e-9) << "the body did not turn rigidly about the reference point";
}

TEST_F(BodyDragTest, DraggingADynamicBodyAppliesAndThenRemovesAForce) {
  BodyDrag drag;
  drag.select(m_, d_, ball_);
  ASSERT_TRUE(drag.begin(m_, d_, &scene_, mjPERT_TRANSLATE));
  EXPECT_FALSE(drag.held().has_value()) << "only mocap bodies are held";
  drag.move(m_, d_, &scene_, mjMOUSE_MOVE_V, 0.1, 0.0);
  drag.apply(m_, d_);
  EXPECT_GT(d_->xfrc_applied[6 * ball_], 0.0) << "no pull toward +x";
  drag.end(m_, d_);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(d_->xfrc_applied[6 * ball_ + i], 0.0);
}

TEST_F(BodyDragTest, NothingSelectedMeansNoDrag) {
  BodyDrag drag;
  EXPECT_FALSE(drag.begin(m_, d_, &scene_, mjPERT_TRANSLATE));
  drag.select(m_, d_, 0);  // the world cannot be dragged
  EXPECT_EQ(drag.selected(), 0);
  EXPECT_FALSE(drag.begin(m_, d_, &scene_, mjPERT_TRANSLATE));
}
