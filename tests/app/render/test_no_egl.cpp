// Without a usable EGL vendor the recorder must refuse with a clear message,
// not crash. Its own binary: libglvnd reads the vendor list once per process.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "app/render/video_recorder.hpp"
#include "tests/app/render/test_models.hpp"

TEST(VideoRecorderWithoutEgl, SaysThereIsNoEglDisplay) {
  // point libglvnd at a vendor file that does not exist: no EGL driver at all
  setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/handover_no_vendor.json", 1);
  auto model = handover::render::test::loadXmlString(handover::render::test::kBoxSceneXml);
  try {
    handover::render::VideoRecorder rec(model.get(), {"/tmp/handover_no_egl.mp4", 64, 48});
    FAIL() << "recorder started without EGL";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("no EGL display: ", 0), 0u) << e.what();
  }
}
