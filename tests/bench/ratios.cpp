// Cost ratios of the frame machinery, measured interleaved in one run (A B A B …, the median of
// the per-pair ratios), so that a busy machine slows both sides of each ratio alike:
//   accumulation   a thin-lens frame of --views views (begin, the views, the sum resolved on the
//                  GPU) ÷ as many bare scene passes into one target             goal ≤ 1.05
//   pinhole plan   a pinhole frame as the renderer plans it (one plain pass, resolved on the GPU)
//                  ÷ one bare scene pass                                   goal ≤ 1.02
//   pre-pass       the visible-blur pre-pass (pinhole depth at ~320 px, read back, dilated)
//                  ÷ the thin-lens frame                                   goal ≤ 0.05
//   adaptive 40 dB a per-tile frame to 40 dB (pre-pass included, read back)
//                  ÷ a 64-view uniform frame, read back (about 40 dB on this scene: sweep)
//   16 boxes       8 views added into a sum, scissored to 16 strips covering half the frame
//                  ÷ the same views scissored to one box over the same half: the cost of a
//                  scissored pass of its own (Renderer's kPixelsPerDrawBox)
// Every side ends in glFinish (or a read-back), so GPU work is counted. After the accumulation
// ratio: the thin-lens frame's time, views and triangles per second, and what a view costs the
// accumulator (Accumulator::viewCost). --breakdown measures the parts of a frame instead.
// Run: build/tests/lenslab_ratios [--scene F --camera F --size WxH --views N] [--backend=egl]
//      [--pairs N] [--only NAME] [--breakdown]      (bench_options.h; default rows, 1280x720, 64)
#include "camera/DepthRange.h"
#include "camera/Projection.h"
#include "gl/Framebuffer.h"
#include "gl/GlContext.h"
#include "io/CameraJson.h"
#include "plan/FramePlan.h"
#include "render/Accumulator.h"
#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "render/ScenePass.h"
#include "render/VisibleBlurPass.h"
#include "scene/GltfLoader.h"
#include "bench_options.h"

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

std::string gOnly;  // --only NAME[,NAME…]: those ratios alone (prefixes of their names)

bool selected(const std::string& name) {
  if (gOnly.empty()) return true;
  std::size_t from = 0;
  while (from <= gOnly.size()) {
    const std::size_t comma = std::min(gOnly.find(',', from), gOnly.size());
    if (name.rfind(gOnly.substr(from, comma - from), 0) == 0) return true;
    from = comma + 1;
  }
  return false;
}

// Returns side B's median time in seconds (0 when skipped by --only).
double ratio(const char* name, int pairs, const std::function<void()>& a, const std::function<void()>& b,
             const char* goal) {
  if (!selected(name)) return 0.0;
  a();
  b();  // warm: shaders compiled, memory touched
  std::vector<double> ta, tb, r;
  for (int i = 0; i < pairs; ++i) {
    ta.push_back(timed(a));
    tb.push_back(timed(b));
    r.push_back(tb.back() / ta.back());
  }
  std::printf("%-16s median ratio %.3f (goal %s)   median A %.2f ms, B %.2f ms   ratios %.3f to %.3f over %d pairs\n",
              name, median(r), goal, 1e3 * median(ta), 1e3 * median(tb), *std::min_element(r.begin(), r.end()),
              *std::max_element(r.begin(), r.end()), pairs);
  return median(tb);
}

// Each part of a 64-view frame against 64 bare passes, interleaved; every view is the pinhole view
// (the parts' costs, not the image, are measured). Then the scissored passes, parts likewise.
void breakdownOf(const Scene& scene, const GpuScene& gpuScene, const ScenePass& scenePass, const glm::dmat4& clip,
                 ImageSize size, int pairs) {
  gl::RenderTarget target(size.widthPx, size.heightPx), out(size.widthPx, size.heightPx);
  const glm::vec3 bg = scene.lighting.background;
  Accumulator layered, added;
  layered.setLayered(true);
  const auto bare = [&] {
    for (int i = 0; i < 64; ++i) scenePass.draw(gpuScene, clip, target.drawTarget());
    glFinish();
  };
  const auto frame = [&](Accumulator& sum, bool draw) {
    sum.start(size.widthPx, size.heightPx);
    for (int i = 0; i < 64; ++i) {
      const Accumulator::View v = sum.nextView(bg);
      if (draw) scenePass.draw(gpuScene, clip, v.target, 0.0f, nullptr, v.addWeight ? &*v.addWeight : nullptr);
    }
    sum.resolve(out);
    glFinish();
  };
  // Eight layers of their own, drawn in turn: the layered path without its sum.
  gl::TextureArray layers = gl::TextureArray::create();
  glTextureStorage3D(layers.id(), 1, GL_RGBA32F, size.widthPx, size.heightPx, 8);
  gl::Texture depth = gl::Texture::create();
  glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, size.widthPx, size.heightPx);
  std::vector<gl::Framebuffer> layerTargets;
  for (int l = 0; l < 8; ++l) {
    layerTargets.push_back(gl::Framebuffer::create());
    glNamedFramebufferTextureLayer(layerTargets.back().id(), GL_COLOR_ATTACHMENT0, layers.id(), 0, l);
    glNamedFramebufferTexture(layerTargets.back().id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
  }
  const auto clears = [&](const std::vector<PixelBox>* boxes, int passes) {
    const float colour[] = {bg.r, bg.g, bg.b, 0.0f}, far = 0.0f;
    target.bind();
    for (int i = 0; i < passes; ++i)
      for (std::size_t b = 0; b < (boxes ? boxes->size() : 1); ++b) {
        if (boxes) {
          glEnable(GL_SCISSOR_TEST);
          glScissor((*boxes)[b].x, (*boxes)[b].y, (*boxes)[b].width, (*boxes)[b].height);
        }
        glClearBufferfv(GL_COLOR, 0, colour);
        glClearBufferfv(GL_DEPTH, 0, &far);
      }
    glDisable(GL_SCISSOR_TEST);
    glFinish();
  };
  std::printf("parts of a 64-view frame, each ÷ 64 bare passes (the same pinhole view every time):\n");
  ratio(
      "layered frame", pairs, bare, [&] { frame(layered, true); },
      "the layered path: views in layers, summed 8 at a time");
  ratio(
      "layer passes", pairs, bare,
      [&] {
        for (int i = 0; i < 64; ++i)
          scenePass.draw(gpuScene, clip,
                         {layerTargets[static_cast<std::size_t>(i % 8)].id(), size.widthPx, size.heightPx});
        glFinish();
      },
      "the layers' passes alone: framebuffer switches, layer writes");
  ratio(
      "batch sums", pairs, bare, [&] { frame(layered, false); }, "the 8 batch sums and the resolve alone");
  ratio(
      "clears", pairs, bare, [&] { clears(nullptr, 64); }, "64 colour + depth clears alone");
  ratio(
      "added frame", pairs, bare, [&] { frame(added, true); }, "views added into the sum");
  std::vector<PixelBox> strips, half{{0, 0, size.widthPx / 2, size.heightPx}};
  for (int i = 0; i < 16; ++i) strips.push_back({i * size.widthPx / 16, 0, size.widthPx / 32, size.heightPx});
  std::printf("8 views in 16 strips ÷ 8 views in one box over the same pixels:\n");
  const auto boxed = [&](const std::vector<PixelBox>& boxes) {
    for (int i = 0; i < 8; ++i) scenePass.draw(gpuScene, clip, target.drawTarget(), 0.0f, &boxes);
    glFinish();
  };
  ratio(
      "16 boxes plain", pairs, [&] { boxed(half); }, [&] { boxed(strips); }, "plain passes");
  ratio(
      "16 boxes clears", pairs, [&] { clears(&half, 8); }, [&] { clears(&strips, 8); }, "their clears alone");
  const auto addedBoxes = [&](const std::vector<PixelBox>& boxes) {
    added.start(size.widthPx, size.heightPx);
    added.setRegion(&boxes);
    for (int i = 0; i < 8; ++i) {
      const Accumulator::View v = added.nextView(bg);
      scenePass.draw(gpuScene, clip, v.target, 0.0f, &boxes, &*v.addWeight);
    }
    added.resolve(out);
    glFinish();
  };
  ratio(
      "16 boxes added", pairs, [&] { addedBoxes(half); }, [&] { addedBoxes(strips); },
      "added views, as per-tile budgets draw them");
  // The same pixels in strips on llvmpipe's 64-px bins: whether a box costs per pass or per bin it cuts.
  std::vector<PixelBox> alignedStrips;
  for (int i = 0; i < 10; ++i) alignedStrips.push_back({i * 128, 0, 64, size.heightPx});
  ratio(
      "10 aligned added", pairs, [&] { addedBoxes(half); }, [&] { addedBoxes(alignedStrips); },
      "10 strips on whole 64-px bins");
}

}  // namespace
}  // namespace lenslab

int main(int argc, char** argv) {
  using namespace lenslab;
  bench::Options options;
  try {
    options = bench::parseOptions(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lenslab_ratios: %s\n", e.what());
    return 2;
  }
  int pairs = 15;
  bool breakdown = false;  // --breakdown: where a view's cost goes, part by part, instead of the ratios
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--pairs") == 0 && i + 1 < argc) pairs = std::max(1, std::atoi(argv[++i]));
    if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) gOnly = argv[++i];
    if (std::strcmp(argv[i], "--breakdown") == 0) breakdown = true;
  }
  const auto context = createHeadlessContext(options.backend);
  const Scene scene = loadGltf(options.scenePath);
  const Camera camera = withDepthRangeFitted(loadCameraJson(options.cameraPath).camera, scene.bounds);
  Camera pinhole = camera;
  pinhole.lens.apertureRadius = 0.0;
  const ImageSize size{options.widthPx, options.heightPx};
  const int views = options.views;
  const double triangles = bench::trianglesOf(scene);
  std::printf("lenslab_ratios: %s, %dx%d, %s (%.0f triangles) with %s, %d views\n", context->renderer().c_str(),
              size.widthPx, size.heightPx, options.scenePath.c_str(), triangles, options.cameraPath.c_str(), views);

  Renderer renderer(scene);
  GpuScene gpuScene(scene);
  ScenePass scenePass;
  gl::RenderTarget target(size.widthPx, size.heightPx);
  const glm::dmat4 clip = clipFromWorld(camera.view);

  const FramePlan frame64 =
      makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Concentric, views, views, 1});
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

  if (breakdown) {
    breakdownOf(scene, gpuScene, scenePass, clip, size, pairs);
    return 0;
  }
  const double frameSeconds = ratio(
      "accumulation", pairs, [&] { bare(views); }, [&] { frame(camera, frame64); }, "<= 1.05");
  if (frameSeconds > 0.0) {
    Accumulator probe;  // as the renderer's for this scene and camera (render/Renderer.cpp drawSample)
    probe.setLayered(Accumulator::layersAreCheaper(triangles, static_cast<double>(size.widthPx) * size.heightPx));
    probe.start(size.widthPx, size.heightPx);
    const Accumulator::ViewCost cost = probe.viewCost();
    std::printf(
        "  thin-lens frame %.1f ms: %.1f views/s, %.3g triangles/s; a view: %.3g scene passes, %.3g full-screen "
        "passes, %.1f bytes/pixel of the accumulator's own (%.1f MB)\n",
        1e3 * frameSeconds, views / frameSeconds, views * triangles / frameSeconds, cost.scenePasses,
        cost.fullScreenPasses, cost.bytesPerPixel, cost.bytesPerPixel * size.widthPx * size.heightPx / 1e6);
  }
  ratio(
      "pinhole plan", pairs * 4, [&] { bare(1); }, [&] { frame(pinhole, pinholePlan); }, "<= 1.02");
  ratio(
      "pre-pass", pairs, [&] { frame(camera, frame64); }, [&] { (void)measureVisibleBlur(renderer, camera, size); },
      "<= 0.05");
  std::vector<PixelBox> strips, half{{0, 0, size.widthPx / 2, size.heightPx}};
  for (int i = 0; i < 16; ++i) strips.push_back({i * size.widthPx / 16, 0, size.widthPx / 32, size.heightPx});
  Accumulator boxedSum;
  // As the per-tile budgets draw: the region set, each view added under the boxes.
  const auto boxed = [&](const std::vector<PixelBox>& boxes) {
    boxedSum.start(size.widthPx, size.heightPx);
    boxedSum.setRegion(&boxes);
    for (int i = 0; i < 8; ++i) {
      const Accumulator::View v = boxedSum.nextView(scene.lighting.background);
      scenePass.draw(gpuScene, clip, v.target, 0.0f, &boxes, v.addWeight ? &*v.addWeight : nullptr);
    }
    (void)boxedSum.sumTexture();  // the background added
    glFinish();
  };
  ratio(
      "16 boxes", pairs, [&] { boxed(half); }, [&] { boxed(strips); }, "1 = no cost per box");
  PlanOptions to40{AperturePattern::Sobol, 0, 256, 1};
  to40.targetPsnrDb = 40.0;
  ratio(
      "adaptive 40 dB", pairs, [&] { (void)renderer.render(camera, frame64, size); },
      [&] {
        const VisibleBlur visible = measureVisibleBlur(renderer, camera, size);
        (void)renderer.render(camera, makeFramePlan(scene, camera, size, to40, &visible), size);
      },
      "< 1: faster");
  return 0;
}
