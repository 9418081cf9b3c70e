// Frame cost of headless rendering at 640x480 (EGL, software or GPU GL):
// the handover scene when it loads, else the small test box scene.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "app/render/offscreen_renderer.hpp"
#include "app/render/video_recorder.hpp"
#include "tests/app/render/test_models.hpp"

using namespace handover::render;
namespace fs = std::filesystem;

namespace {

struct Scene {
  test::ModelPtr model;
  mjData* data = nullptr;
  std::string name;
  Scene() {
    const std::string path = std::string(HANDOVER_SOURCE_DIR) + "/scenes/handover_scene.xml";
    char err[1000] = "";
    mjModel* m = fs::exists(path) ? mj_loadXML(path.c_str(), nullptr, err, sizeof err) : nullptr;
    if (m != nullptr) {
      model.reset(m);
      name = "handover_scene";
    } else {
      model = test::loadXmlString(test::kBoxSceneXml);
      name = "box_scene";
    }
    data = mj_makeData(model.get());
    mj_forward(model.get(), data);
  }
  ~Scene() { mj_deleteData(data); }
};

Scene& scene() {
  static Scene s;
  return s;
}

void renderFrame(benchmark::State& state, bool fast, int width = 640, int height = 480) {
  Scene& s = scene();
  OffscreenRenderer renderer(s.model.get(), {width, height, "overview", fast});
  for (auto _ : state) {
    const auto& rgb = renderer.render(s.model.get(), s.data, "time\nstate", "1.00 s\napproach");
    benchmark::DoNotOptimize(rgb.data());
  }
  state.SetLabel(s.name + ", " + renderer.glDescription());
}

void BM_Render640x480_Fast(benchmark::State& state) { renderFrame(state, true); }
void BM_Render640x480_ShadowsMultisampling(benchmark::State& state) { renderFrame(state, false); }
void BM_Render320x240_Fast(benchmark::State& state) { renderFrame(state, true, 320, 240); }

// render + flip + pipe into ffmpeg (x264 veryfast runs in parallel in its own process)
void BM_RecordFrame640x480(benchmark::State& state) {
  Scene& s = scene();
  const fs::path file = fs::temp_directory_path() / ("handover_bench_" + std::to_string(getpid()) + ".mp4");
  VideoRecorder rec(s.model.get(), {file.string(), 640, 480, 30.0, "overview", true});
  double t = 0.0;
  for (auto _ : state) {
    s.data->time = t;
    rec.addFrame(s.model.get(), s.data, "approach");
    t += 1.0 / 30.0;
  }
  rec.close();
  fs::remove(file);
  state.SetLabel(s.name);
}

}  // namespace

BENCHMARK(BM_Render640x480_Fast)->Unit(benchmark::kMillisecond)->Iterations(60);
BENCHMARK(BM_Render640x480_ShadowsMultisampling)->Unit(benchmark::kMillisecond)->Iterations(30);
BENCHMARK(BM_Render320x240_Fast)->Unit(benchmark::kMillisecond)->Iterations(60);
BENCHMARK(BM_RecordFrame640x480)->Unit(benchmark::kMillisecond)->Iterations(60);
