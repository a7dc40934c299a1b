// Cost of thin-lens accumulation (default: 1280×720, the bundled rows scene, 64 views):
//   BM_ScenePass        one bare scene pass (draw + glFinish), the unit of work
//   BM_Accumulate/N     N aperture views added into the sum (+ glFinish); N = 16 and --views.
//                       Counters: views and triangles per second, and what a view costs the
//                       accumulator (Accumulator::viewCost: scene passes, full-screen passes and
//                       bytes per view)
// The accumulation overhead is BM_Accumulate/N ÷ (N × BM_ScenePass); lenslab_ratios measures it
// interleaved, which a busy machine needs.
//   BM_LensFrame/E      a whole 16-sample frame (begin, samples, resolve with read-back) with lens
//                       effect set E: 0 none, 1 all zero (must cost what 0 costs), 2 distortion +
//                       lateral colour (the lens pass), 3 axial colour (three views per sample),
//                       4 field curvature (the warped sum), 5 all of them (from camera-lens.json)
//   BM_LensTables       building the lens pass's lookup tables (CPU, Newton), 3 channels
// Run:  build/tests/lenslab_bench [--scene F --camera F --size WxH --views N] [--backend=egl]
//       (bench_options.h; OSMesa by default), plus Google Benchmark's flags (--benchmark_filter=…)
#include "camera/ImageMap.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "gl/GlContext.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "render/Accumulator.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"
#include "scene/GltfLoader.h"

#include "bench_options.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace lenslab {
namespace {

bench::Options gOptions;
ImageSize kSize{1280, 720};

struct Fixture {
  std::unique_ptr<GlContext> context;
  Scene scene;
  Camera camera;
  std::unique_ptr<Renderer> renderer;
};

using bench::assetDir;

Fixture& fixture() {
  static Fixture f = [] {
    Fixture x;
    x.context = createHeadlessContext(gOptions.backend);
    x.scene = loadGltf(gOptions.scenePath);
    x.camera = loadCameraJson(gOptions.cameraPath).camera;
    x.renderer = std::make_unique<Renderer>(x.scene);
    return x;
  }();
  return f;
}

void BM_ScenePass(benchmark::State& state) {
  Fixture& f = fixture();
  state.SetLabel(f.context->renderer());
  FramePlan plan = makeFramePlan(f.scene, f.camera, kSize, PlanOptions{AperturePattern::Concentric, 1, 1, 1});
  Camera pinhole = f.camera;
  pinhole.lens.apertureRadius = 0.0;
  f.renderer->begin(pinhole, plan, kSize);
  for (auto _ : state) {
    f.renderer->begin(pinhole, plan, kSize);
    f.renderer->addSamples(1);
    glFinish();
  }
}

void BM_Accumulate(benchmark::State& state) {
  Fixture& f = fixture();
  const int n = static_cast<int>(state.range(0));
  const FramePlan plan = makeFramePlan(f.scene, f.camera, kSize, PlanOptions{AperturePattern::Concentric, n, n, 1});
  for (auto _ : state) {
    f.renderer->begin(f.camera, plan, kSize);
    f.renderer->addSamples(n);
    glFinish();
  }
  state.counters["ms_per_sample"] = benchmark::Counter(
      static_cast<double>(n) * 1e-3, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["views_per_s"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles_per_s"] = benchmark::Counter(static_cast<double>(n) * bench::trianglesOf(f.scene),
                                                         benchmark::Counter::kIsIterationInvariantRate);
  Accumulator probe;  // as the renderer's for this scene and camera (render/Renderer.cpp drawSample)
  probe.setLayered(
      Accumulator::layersAreCheaper(bench::trianglesOf(f.scene), static_cast<double>(kSize.widthPx) * kSize.heightPx));
  probe.start(kSize.widthPx, kSize.heightPx);
  const Accumulator::ViewCost cost = probe.viewCost();
  state.counters["scene_passes_per_view"] = cost.scenePasses;
  state.counters["fullscreen_passes_per_view"] = cost.fullScreenPasses;
  state.counters["accumulator_MB_per_view"] = cost.bytesPerPixel * kSize.widthPx * kSize.heightPx / 1e6;
}

Camera withEffects(const Camera& base, int set) {
  Camera c = base;
  const LensEffects all = loadCameraJson(assetDir() + "/rows/camera-lens.json").camera.lens.effects;
  c.lens.effects = {};
  if (set == 2) {
    c.lens.effects.distortion = all.distortion;
    c.lens.effects.chromatic.lateralRed = all.chromatic.lateralRed;
    c.lens.effects.chromatic.lateralBlue = all.chromatic.lateralBlue;
  } else if (set == 3) {
    c.lens.effects.chromatic.inverseFocusShiftRed = all.chromatic.inverseFocusShiftRed;
    c.lens.effects.chromatic.inverseFocusShiftBlue = all.chromatic.inverseFocusShiftBlue;
  } else if (set == 4) {
    c.lens.effects.fieldCurvature = all.fieldCurvature;
  } else if (set == 5) {
    c.lens.effects = all;
  }
  return c;
}

void BM_LensFrame(benchmark::State& state) {
  Fixture& f = fixture();
  const Camera camera = withEffects(f.camera, static_cast<int>(state.range(0)));
  const FramePlan plan = makeFramePlan(f.scene, camera, kSize, PlanOptions{AperturePattern::Concentric, 16, 16, 1});
  std::string passes;
  for (const PlannedPass& p : plan.passes) {
    passes += (passes.empty() ? "" : " ") + p.name;
    for (const std::string& v : p.variants) passes += "+" + v;
  }
  state.SetLabel(passes);
  f.renderer->render(camera, plan, kSize);  // tables and variants built outside the timing
  for (auto _ : state) benchmark::DoNotOptimize(f.renderer->render(camera, plan, kSize));
}

void BM_LensTables(benchmark::State& state) {
  const Camera camera = withEffects(fixture().camera, 2);
  const ThinLensMap map = ThinLensMap(camera, kSize).overscanned();
  for (auto _ : state) benchmark::DoNotOptimize(map.remapTable());
}

BENCHMARK(BM_LensFrame)->DenseRange(0, 5)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_LensTables)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_ScenePass)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

}  // namespace
}  // namespace lenslab

int main(int argc, char** argv) {
  using namespace lenslab;
  try {
    gOptions = bench::parseOptions(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lenslab_bench: %s\n", e.what());
    return 2;
  }
  kSize = {gOptions.widthPx, gOptions.heightPx};
  benchmark::RegisterBenchmark("BM_Accumulate", BM_Accumulate)
      ->Arg(16)
      ->Arg(gOptions.views)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(3.0)
      ->UseRealTime();
  std::printf("scene %s (%.0f triangles), camera %s, %dx%d\n", gOptions.scenePath.c_str(),
              bench::trianglesOf(loadGltf(gOptions.scenePath)), gOptions.cameraPath.c_str(), kSize.widthPx,
              kSize.heightPx);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
