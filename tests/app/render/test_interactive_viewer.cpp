// ViewerWindow in a private Xvfb server: open, draw, select with mjv_select,
// drag the mocap "hand", pace to real time, share the thread with an EGL
// VideoRecorder, close.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "app/render/interactive_viewer.hpp"
#include "app/render/video_recorder.hpp"
#include "tests/app/render/test_models.hpp"
#include "tests/app/render/xvfb_display.hpp"

namespace fs = std::filesystem;
using namespace handover::render;
using handover::render::test::DataPtr;
using handover::render::test::loadXmlString;
using handover::render::test::ModelPtr;
using handover::render::test::XvfbDisplay;

namespace {

ViewerOptions smallWindow() {
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.camera = "front";
  o.realtime = false;
  return o;
}

class ViewerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { xvfb_ = std::make_unique<XvfbDisplay>(); }
  static void TearDownTestSuite() { xvfb_.reset(); }
  void SetUp() override {
    if (xvfb_->missing()) GTEST_SKIP() << xvfb_->error();
    ASSERT_TRUE(xvfb_->error().empty()) << xvfb_->error();
    model_ = loadXmlString(handover::render::test::kBoxSceneXml);
    m_ = model_.get();
    data_ = DataPtr(mj_makeData(m_));
    d_ = data_.get();
    mj_forward(m_, d_);
  }
  static std::unique_ptr<XvfbDisplay> xvfb_;
  ModelPtr model_;
  DataPtr data_;
  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
};
std::unique_ptr<XvfbDisplay> ViewerTest::xvfb_;

}  // namespace

TEST(ViewerNoDisplay, SaysToUseVideoInstead) {
  const char* old = std::getenv("DISPLAY");
  const std::string saved = old ? old : "";
  unsetenv("DISPLAY");
  ModelPtr model = loadXmlString(handover::render::test::kBoxSceneXml);
  try {
    ViewerWindow viewer(model.get(), smallWindow());
    FAIL() << "a viewer opened without a display";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--view needs a display; use --video for headless runs"),
              std::string::npos)
        << e.what();
  }
  if (old) setenv("DISPLAY", saved.c_str(), 1);
}

TEST_F(ViewerTest, DrawsSelectsAndDragsTheHand) {
  ViewerWindow viewer(m_, smallWindow());
  for (int i = 0; i < 3; ++i) {
    d_->time = i * 0.02;
    EXPECT_TRUE(viewer.frame(m_, d_, "idle"));
  }

  // the red box fills the centre of the "front" view
  EXPECT_EQ(viewer.selectAt(m_, d_, 0.5, 0.5), mj_name2id(m_, mjOBJ_BODY, "box"));
  EXPECT_EQ(viewer.selectAt(m_, d_, 0.5, 0.98), -1) << "sky selected something";

  // grab the hand and pull it 'right' in the view plane
  const int hand = mj_name2id(m_, mjOBJ_BODY, "hand");
  const int mocap = m_->body_mocapid[hand];
  const double x0 = d_->mocap_pos[3 * mocap], z0 = d_->mocap_pos[3 * mocap + 2];
  viewer.drag().select(m_, d_, hand);
  ASSERT_TRUE(viewer.drag().begin(m_, d_, &viewer.scene(), mjPERT_TRANSLATE));
  viewer.drag().move(m_, d_, &viewer.scene(), mjMOUSE_MOVE_V, 0.1, 0.0);
  ASSERT_TRUE(viewer.frame(m_, d_, "drag"));  // frame() writes the drag into mjData
  ASSERT_TRUE(viewer.draggedPose().has_value());
  const DraggedPose& pose = *viewer.draggedPose();
  EXPECT_EQ(pose.name, "hand");
  EXPECT_GT(d_->mocap_pos[3 * mocap] - x0, 0.02);
  EXPECT_NEAR(d_->mocap_pos[3 * mocap + 2], z0, 1e-9);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(d_->mocap_pos[3 * mocap + i], pose.pos[i]);

  // the app overwrites the mocap body each step; frame() restores the held pose
  d_->mocap_pos[3 * mocap] = x0;
  viewer.drag().end(m_, d_);
  ASSERT_TRUE(viewer.frame(m_, d_, "held"));
  EXPECT_DOUBLE_EQ(d_->mocap_pos[3 * mocap], pose.pos[0]);

  viewer.requestClose();
  EXPECT_FALSE(viewer.frame(m_, d_, "closing"));
}

TEST_F(ViewerTest, DoubleClickAndCtrlRightDragMoveTheHandLikeAUser) {
  ViewerWindow viewer(m_, smallWindow());  // 320x240, camera "front" (fovy 45, 1 m from the scene)
  ASSERT_TRUE(viewer.frame(m_, d_));
  int calls = 0;
  bool last_dragging = true;
  viewer.onDrag([&](const DraggedPose& p) {
    ++calls;
    last_dragging = p.dragging;
  });

  // The hand's sphere centre (0.37, 0, 0.3) is 1 m in front of the camera and
  // 0.37 m to the right: x = 160 + 160 * 0.37 / (tan(22.5 deg) * 320/240) = 267 px.
  const double hx = 160 + 160 * 0.37 / (std::tan(22.5 * M_PI / 180) * 320.0 / 240.0), hy = 120;
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true, 0, hx, hy, 10.00);
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false, 0, hx, hy, 10.05);
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true, 0, hx, hy, 10.15);  // double-click
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false, 0, hx, hy, 10.20);
  const int hand = mj_name2id(m_, mjOBJ_BODY, "hand");
  ASSERT_EQ(viewer.drag().selected(), hand) << "double-click did not select the hand";

  // ctrl + right drag 24 px to the right and 24 px up
  const int mocap = m_->body_mocapid[hand];
  const double x0 = d_->mocap_pos[3 * mocap], y0 = d_->mocap_pos[3 * mocap + 1], z0 = d_->mocap_pos[3 * mocap + 2];
  viewer.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, true, GLFW_MOD_CONTROL, hx, hy, 11.0);
  for (int i = 1; i <= 4; ++i) viewer.mouseMove(hx + 6 * i, hy - 6 * i);
  viewer.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, false, GLFW_MOD_CONTROL, hx + 24, hy - 24, 11.5);
  ASSERT_TRUE(viewer.frame(m_, d_));

  ASSERT_TRUE(viewer.draggedPose().has_value());
  EXPECT_GT(d_->mocap_pos[3 * mocap] - x0, 0.01) << "not moved right";
  EXPECT_GT(d_->mocap_pos[3 * mocap + 2] - z0, 0.01) << "not moved up";
  EXPECT_NEAR(d_->mocap_pos[3 * mocap + 1], y0, 1e-9) << "left the camera's plane";
  EXPECT_GE(calls, 6) << "onDrag: press, 4 moves, release";
  EXPECT_FALSE(last_dragging) << "the last callback is the release";

  // a plain left drag orbits the camera and leaves the hand alone
  const DraggedPose before = *viewer.draggedPose();
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true, 0, 100, 100, 12.0);
  viewer.mouseMove(140, 100);
  viewer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false, 0, 140, 100, 12.2);
  EXPECT_EQ(viewer.camera().type, mjCAMERA_FREE) << "orbiting should leave the fixed camera";
  EXPECT_DOUBLE_EQ(viewer.draggedPose()->pos[0], before.pos[0]);
  ASSERT_TRUE(viewer.frame(m_, d_));
}

TEST_F(ViewerTest, RealtimePacingWaitsForTheWallClock) {
  ViewerOptions o = smallWindow();
  o.realtime = true;
  ViewerWindow viewer(m_, o);
  d_->time = 0.0;
  viewer.frame(m_, d_);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 1; i <= 20; ++i) {  // 0.2 s of simulated time
    d_->time = i * 0.01;
    viewer.frame(m_, d_);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(wall, 0.17) << "frame() ran ahead of real time";

  // half speed: 0.09 s of simulation after the re-anchor takes 0.18 s (minus the 2 ms slack)
  viewer.setSpeed(0.5);
  const auto slow_start = std::chrono::steady_clock::now();
  for (int i = 21; i <= 30; ++i) {
    d_->time = i * 0.01;
    viewer.frame(m_, d_);
  }
  const double slow = std::chrono::duration<double>(std::chrono::steady_clock::now() - slow_start).count();
  EXPECT_GE(slow, 0.16) << "slow motion was not slower";
}

TEST_F(ViewerTest, ShareTheThreadWithAnEglVideoRecorder) {
  const fs::path file = fs::temp_directory_path() / ("handover_viewer_video_" + std::to_string(getpid()) + ".mp4");
  {
    ViewerWindow viewer(m_, smallWindow());
    VideoRecorder recorder(m_, {file.string(), 160, 120, 30.0, "front", false});
    for (int i = 0; i < 5; ++i) {
      d_->time = i / 30.0;
      ASSERT_TRUE(viewer.frame(m_, d_));
      ASSERT_TRUE(recorder.wantsFrame(d_->time));
      recorder.addFrame(m_, d_);
    }
    recorder.close();
    EXPECT_EQ(recorder.frames(), 5);
  }
  FILE* p = popen(("ffmpeg -v error -i '" + file.string() +
                   "' -vframes 1 -f rawvideo -pix_fmt rgb24 -").c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string frame;
  char buf[65536];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) frame.append(buf, n);
  pclose(p);
  fs::remove(file);
  ASSERT_EQ(frame.size(), 160u * 120u * 3u);
  const auto* c = reinterpret_cast<const unsigned char*>(frame.data()) + 3 * (60 * 160 + 80);
  EXPECT_GT(c[0], 120);
  EXPECT_LT(c[1], c[0] / 2) << "centre is not the red box";
}
