// Cost ratios of the frame machinery, measured interleaved in one run (A B A B …, the median of
// the per-pair ratios), so that a busy machine slows both sides of each ratio alike:
//   accumulation   a 64-view thin-lens frame (begin, 64 views, the sum resolved on the GPU)
//                  ÷ 64 bare scene passes into one target                  goal ≤ 1.05
//   pinhole plan   a pinhole frame as the renderer plans it (one plain pass, resolved on the GPU)
//                  ÷ one bare scene pass                                   goal ≤ 1.02
//   pre-pass       the visible-blur pre-pass (pinhole depth at ~320 px, read back, dilated)
//                  ÷ the 64-view frame                                     goal ≤ 0.05
//   adaptive 40 dB a per-tile frame to 40 dB (pre-pass included, read back)
//                  ÷ a 64-view uniform frame, read back (about 40 dB on this scene: sweep)
//   16 boxes       8 scene passes scissored to 16 strips covering half the frame
//                  ÷ 8 passes scissored to one box over the same half: the cost of a scissored
//                  pass of its own (Renderer's kPixelsPerDrawBox)
// Every side ends in glFinish (or a read-back), so GPU work is counted. 1280×720, rows with
// camera-dof.json. Run: build/tests/lenslab_ratios [--backend=egl] [--pairs N]
#include "camera/DepthRange.h"
#include "camera/Projection.h"
#include "gl/Framebuffer.h"
#include "gl/GlContext.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"
#include "render/VisibleBlurPass.h"
#include "scene/GltfLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace lenslab {
namespace {

double timed(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string gOnly;  // --only NAME: that ratio alone (a prefix of its name)

void ratio(const char* name, int pairs, const std::function<void()>& a, const std::function<void()>& b, const char* goal) {
  if (!gOnly.empty() && std::string(name).rfind(gOnly, 0) != 0) return;
  a();
  b();  // warm: shaders compiled, memory touched
  std::vector<double> ta, tb, r;
  for (int i = 0; i < pairs; ++i) {
    ta.push_back(timed(a));
    tb.push_back(timed(b));
    r.push_back(tb.back() / ta.back());
  }
  std::printf("%-16s median ratio %.3f (goal %s)   median A %.2f ms, B %.2f ms   ratios %.3f to %.3f over %d pairs\n", name,
              median(r), goal, 1e3 * median(ta), 1e3 * median(tb), *std::min_element(r.begin(), r.end()),
              *std::max_element(r.begin(), r.end()), pairs);
}

std::string assetDir() {
  const char* env = std::getenv("LENSLAB_ASSET_DIR");
  return env && *env ? env : LENSLAB_BENCH_ASSET_DIR;
}

}  // namespace
}  // namespace lenslab

int main(int argc, char** argv) {
  using namespace lenslab;
  Backend backend = Backend::OSMesa;
  int pairs = 15;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--backend=egl") == 0) backend = Backend::Egl;
    if (std::strcmp(argv[i], "--pairs") == 0 && i + 1 < argc) pairs = std::max(1, std::atoi(argv[++i]));
    if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) gOnly = argv[++i];
  }
  const auto context = createHeadlessContext(backend);
  const Scene scene = loadGltf(assetDir() + "/rows/rows.gltf");
  const Camera camera = withDepthRangeFitted(loadCameraJson(assetDir() + "/rows/camera-dof.json").camera, scene.bounds);
  Camera pinhole = camera;
  pinhole.apertureRadius = 0.0;
  const ImageSize size{1280, 720};
  std::printf("lenslab_ratios: %s, %dx%d, rows with camera-dof.json\n", context->renderer().c_str(), size.widthPx, size.heightPx);

  Renderer renderer(scene);
  GpuScene gpuScene(scene);
  ScenePass scenePass;
  gl::RenderTarget target(size.widthPx, size.heightPx);
  const glm::dmat4 clip = clipFromWorld(camera.view);

  const FramePlan frame64 = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, 64, 64, 1});
  const FramePlan pinholePlan = makeFramePlan(scene, pinhole, size);
  const auto bare = [&](int n) {
    for (int i = 0; i < n; ++i) scenePass.draw(gpuScene, clip, target.drawTarget());
    glFinish();
  };
  const auto frame = [&](const Camera& c, const FramePlan& plan) {
    renderer.begin(c, plan, size);
    renderer.addSamples(renderer.samplesPlanned());
    renderer.resolveOnGpu();
    glFinish();
  };

  ratio("accumulation", pairs, [&] { bare(64); }, [&] { frame(camera, frame64); }, "<= 1.05");
  ratio("pinhole plan", pairs * 4, [&] { bare(1); }, [&] { frame(pinhole, pinholePlan); }, "<= 1.02");
  ratio("pre-pass", pairs, [&] { frame(camera, frame64); }, [&] { (void)measureVisibleBlur(renderer, camera, size); }, "<= 0.05");
  std::vector<PixelBox> strips, half{{0, 0, size.widthPx / 2, size.heightPx}};
  for (int i = 0; i < 16; ++i) strips.push_back({i * size.widthPx / 16, 0, size.widthPx / 32, size.heightPx});
  const auto boxed = [&](const std::vector<PixelBox>& boxes) {
    for (int i = 0; i < 8; ++i) scenePass.draw(gpuScene, clip, target.drawTarget(), 0.0f, &boxes);
    glFinish();
  };
  ratio("16 boxes", pairs, [&] { boxed(half); }, [&] { boxed(strips); }, "1 = no cost per box");
  PlanOptions to40{AperturePattern::Sobol, 0, 256, 1};
  to40.targetPsnrDb = 40.0;
  ratio("adaptive 40 dB", pairs, [&] { (void)renderer.render(camera, frame64, size); },
        [&] {
          const VisibleBlur visible = measureVisibleBlur(renderer, camera, size);
          (void)renderer.render(camera, makeFramePlan(scene, camera, size, to40, &visible), size);
        },
        "< 1: faster");
  return 0;
}
