// VideoRecorder and OffscreenRenderer against a small box scene: real EGL
// rendering, a real ffmpeg encode, checked back with ffprobe and a decode.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/render/offscreen_renderer.hpp"
#include "app/render/video_recorder.hpp"
#include "config/input_error.hpp"
#include "tests/app/render/test_models.hpp"

namespace fs = std::filesystem;
using namespace handover::render;
using handover::render::test::DataPtr;
using handover::render::test::loadXmlString;
using handover::render::test::ModelPtr;

namespace {

// Runs a shell command, returns its stdout (binary safe).
std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return out;
  char buf[65536];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  pclose(p);
  return out;
}

fs::path tempVideo(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("handover_render_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

struct Rgb {
  int r, g, b;
};
Rgb pixel(const unsigned char* rgb, int width, int x, int y) {
  const unsigned char* p = rgb + 3 * (static_cast<size_t>(y) * width + x);
  return {p[0], p[1], p[2]};
}
bool isRed(Rgb c) { return c.r > 120 && c.r > 2 * c.g + 20 && c.r > 2 * c.b + 20; }

class VideoRecorderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = loadXmlString(handover::render::test::kBoxSceneXml);
    data_ = DataPtr(mj_makeData(model_.get()));
    mj_forward(model_.get(), data_.get());
  }
  void TearDown() override { fs::remove_all(tempVideo("x").parent_path()); }
  ModelPtr model_;
  DataPtr data_;
};

}  // namespace

TEST_F(VideoRecorderTest, OffscreenFrameShowsTheBoxUprightInTheCentre) {
  OffscreenRenderer renderer(model_.get(), {320, 240, "front", true});
  const auto& rgb = renderer.render(model_.get(), data_.get());
  ASSERT_EQ(rgb.size(), 320u * 240u * 3u);
  EXPECT_TRUE(isRed(pixel(rgb.data(), 320, 160, 120))) << "centre is not the red box";
  EXPECT_FALSE(isRed(pixel(rgb.data(), 320, 5, 5))) << "corner should be background";
  // Upright: the floor (grey) is at the bottom of the image, not the top,
  // which catches a missing vertical flip.
  const Rgb top = pixel(rgb.data(), 320, 160, 2), bottom = pixel(rgb.data(), 320, 160, 237);
  EXPECT_NE(top.r + top.g + top.b, bottom.r + bottom.g + bottom.b);
  const Rgb floor = bottom;
  EXPECT_NEAR(floor.r, floor.g, 25) << "bottom row should be the grey floor";
  EXPECT_NEAR(floor.g, floor.b, 25);
  EXPECT_GT(floor.r + floor.g + floor.b, 30) << "bottom row is black";
}

TEST_F(VideoRecorderTest, RecordsH264InSimulatedTime) {
  const fs::path file = tempVideo("box.mp4");
  VideoOptions opt;
  opt.path = file.string();
  opt.width = 320;
  opt.height = 240;
  opt.fps = 30.0;
  opt.camera = "front";
  VideoRecorder rec(model_.get(), opt);
  EXPECT_EQ(rec.cameraNote(), "camera 'front'");

  // 2 ms simulation steps; the recorder takes a frame every 1/30 s of sim time
  std::vector<double> frame_times;
  const double dt = 0.002;
  for (int step = 0; frame_times.size() < 20; ++step) {
    data_->time = step * dt;
    data_->mocap_pos[0] = 0.35 + 0.1 * data_->time;  // something moves
    mj_forward(model_.get(), data_.get());
    if (rec.wantsFrame(data_->time)) {
      rec.addFrame(model_.get(), data_.get(), "approach");
      frame_times.push_back(data_->time);
    }
    ASSERT_LT(step, 10000) << "recorder never took 20 frames";
  }
  rec.close();
  EXPECT_EQ(rec.frames(), 20);
  for (size_t k = 0; k < frame_times.size(); ++k) {
    EXPECT_GE(frame_times[k] + 1e-9, k / 30.0) << "frame " << k << " too early";
    EXPECT_LT(frame_times[k], k / 30.0 + dt) << "frame " << k << " too late";
  }

  ASSERT_TRUE(fs::exists(file));
  EXPECT_GT(fs::file_size(file), 1000u);
  const std::string probe =
      run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
          "stream=codec_name,width,height,pix_fmt,nb_read_frames,r_frame_rate -of default=nw=1 '" +
          file.string() + "'");
  EXPECT_NE(probe.find("codec_name=h264"), std::string::npos) << probe;
  EXPECT_NE(probe.find("width=320"), std::string::npos) << probe;
  EXPECT_NE(probe.find("height=240"), std::string::npos) << probe;
  EXPECT_NE(probe.find("pix_fmt=yuv420p"), std::string::npos) << probe;
  EXPECT_NE(probe.find("r_frame_rate=30/1"), std::string::npos) << probe;
  EXPECT_NE(probe.find("nb_read_frames=20\n"), std::string::npos) << probe;

  // decode frame 10 back and look at it
  const std::string frame =
      run("ffmpeg -v error -i '" + file.string() +
          "' -vf 'select=eq(n\\,10)' -vframes 1 -f rawvideo -pix_fmt rgb24 -");
  ASSERT_EQ(frame.size(), 320u * 240u * 3u);
  const auto* px = reinterpret_cast<const unsigned char*>(frame.data());
  const Rgb centre = pixel(px, 320, 160, 120);
  EXPECT_TRUE(isRed(centre)) << "decoded centre " << centre.r << "," << centre.g << "," << centre.b;
  long sum = 0;
  for (unsigned char c : frame) sum += c;
  EXPECT_GT(sum / static_cast<long>(frame.size()), 20) << "decoded frame is (almost) black";
}

TEST_F(VideoRecorderTest, RepeatsTheImageWhenSimulationSkipsFrameSlots) {
  const fs::path file = tempVideo("jump.mp4");
  VideoRecorder rec(model_.get(), {file.string(), 64, 48, 10.0, "front", false});
  data_->time = 0.0;
  rec.addFrame(model_.get(), data_.get());
  EXPECT_FALSE(rec.wantsFrame(0.05));
  EXPECT_TRUE(rec.wantsFrame(0.1));
  data_->time = 0.35;  // slots 1, 2, 3 are due
  rec.addFrame(model_.get(), data_.get());
  rec.close();
  EXPECT_EQ(rec.frames(), 4);
  EXPECT_FALSE(rec.wantsFrame(1.0)) << "closed recorder wants no frames";
  const std::string probe = run("ffprobe -v error -count_frames -show_entries stream=nb_read_frames "
                                "-of default=nw=1 '" + file.string() + "'");
  EXPECT_NE(probe.find("nb_read_frames=4"), std::string::npos) << probe;
}

TEST_F(VideoRecorderTest, MissingOverviewCameraFallsBackToTheWorkspaceView) {
  OffscreenRenderer renderer(model_.get(), {64, 48, "overview", true});
  EXPECT_NE(renderer.cameraNote().find("workspace"), std::string::npos) << renderer.cameraNote();
  EXPECT_EQ(renderer.camera().type, mjCAMERA_FREE);
}

TEST_F(VideoRecorderTest, BadOptionsAreInputErrors) {
  auto make = [&](VideoOptions o) { VideoRecorder r(model_.get(), o); };
  const std::string path = tempVideo("bad.mp4").string();
  EXPECT_THROW(make({path, 321, 240}), handover::InputError);
  EXPECT_THROW(make({path, 320, 240, 0.0}), handover::InputError);
  EXPECT_THROW(make({"", 320, 240}), handover::InputError);
  try {
    make({path, 320, 240, 30.0, "no_such_camera"});
    FAIL() << "unknown camera accepted";
  } catch (const handover::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("front"), std::string::npos) << e.what();
  }
}

TEST_F(VideoRecorderTest, MissingFfmpegIsAClearError) {
  VideoOptions o{tempVideo("x.mp4").string(), 64, 48};
  o.ffmpeg = "ffmpeg-that-does-not-exist";
  try {
    VideoRecorder r(model_.get(), o);
    FAIL() << "no error without ffmpeg";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not found on PATH"), std::string::npos) << e.what();
  }
}

TEST_F(VideoRecorderTest, FfmpegFailureReportsItsStderr) {
  VideoOptions o{"/nonexistent_dir/sub/out.mp4", 64, 48, 30.0, "front"};
  VideoRecorder rec(model_.get(), o);
  try {
    for (int i = 0; i < 50; ++i) {  // ffmpeg may die before or after reading
      data_->time = i / 30.0;
      rec.addFrame(model_.get(), data_.get());
    }
    rec.close();
    FAIL() << "writing into a missing directory succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nonexistent_dir"), std::string::npos) << e.what();
  }
}
