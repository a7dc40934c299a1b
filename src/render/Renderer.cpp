#include "render/Renderer.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "scene/BlendOrder.h"

#include <cmath>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace lenslab {
namespace {

// The background the accumulator adds for all views at once: the scene's constant colour; none
// with an environment, which each view draws itself (ScenePass), its directions its own.
glm::vec3 constantBackground(const Scene& scene) {
  return scene.environment ? glm::vec3(0.0f) : scene.lighting.background;
}

}  // namespace

Renderer::Renderer(const Scene& scene) : gpuScene_(scene) {}

const gl::RenderTarget& Renderer::target(std::unique_ptr<gl::RenderTarget>& slot, ImageSize size) {
  if (!slot || slot->width() != size.widthPx || slot->height() != size.heightPx) {
    slot.reset();  // freed before the new one is made: a tiled render's tiles differ in size
    slot = std::make_unique<gl::RenderTarget>(size.widthPx, size.heightPx);
  }
  return *slot;
}

void Renderer::begin(const Camera& camera, const FramePlan& plan, ImageSize size,
                     const LensPass::TableProgress& tables) {
  plan_ = plan;
  // The plan's overscan is for the camera it was made for; a plan reused for another camera
  // without the lens pass (a sweep's ablations) renders that camera's own image.
  views_.emplace(
      ThinLensMap(camera, size, plan.remap || plan.cellFilter ? plan.overscan : Overscan{camera, size, {0, 0}}), plan);
  size_ = views_->map().overscan().size;
  outSize_ = size;
  done_ = 0;
  // With distortion or lateral colour the lens gather masks each view's samples at their own
  // undistorted rays (gather_lens.frag, BARREL); a parallel projection has no directions to clip.
  if (camera.lens.hasBarrel() && camera.view.projection != Projection::Perspective)
    throw InputError(cat(camera.source,
                         ": the lens barrel (cat's-eye vignetting) needs a perspective projection; remove \"barrel\""));
  if (plan.vignetting && !vignettePass_) vignettePass_ = std::make_unique<VignettePass>();
  if (plan.remap) {
    if (!lensPass_) lensPass_ = std::make_unique<LensPass>();
    lensPass_->prepare(views_->map(), plan.apertureSamples > 1, tables);
  }
  // The accumulator outlives frames: a frame without the cell filter turns it off.
  if (accumulator_) accumulator_->setCellFilter(false);
  adaptive_ = plan.adaptive.has_value();
  if (adaptive_) {
    beginAdaptive();
    return;
  }
  if (plan.apertureSamples <= 1) {
    // No lens: the pinhole view from the PRP, at the pixel centres.
    samples_ = {LensSample{{0.0, 0.0}, {0.0, 0.0}}};
  } else {
    if (plan.cellFilter) {
      CellSamples cells = makeCellSamples(plan.pattern, plan.apertureSamples, plan.seed);
      samples_ = std::move(cells.samples);
      cells_ = std::move(cells.cells);
    } else {
      samples_ = makeApertureSamples(plan.pattern, plan.apertureSamples, plan.seed);
      cells_.clear();
    }
    if (!accumulator_) accumulator_ = std::make_unique<Accumulator>();
    accumulator_->setCellFilter(plan.cellFilter, plan.overscan.padPx);
    const std::optional<Accumulator::Curvature> curvature = views_->curvatureWarp();
    // With distortion or lateral colour each view's samples go straight to where the lens puts
    // them, as the views are summed: no resampling of the mean afterwards.
    const std::optional<Accumulator::Barrel> barrel = views_->barrelMask();
    accumulator_->setExpectedViews(plan.apertureSamples);
    accumulator_->start(size_.widthPx, size_.heightPx, curvature ? &*curvature : nullptr,
                        plan.remap ? &lensPass_->gather() : nullptr, barrel ? &*barrel : nullptr);
  }
}

void Renderer::drawSample(const std::vector<SamplePart>& parts, Accumulator& sum, float lodBias) {
  const LensViews& views = *views_;
  // The field-curvature shift and the sub-pixel offset are the view's, so a view with either is
  // drawn whole from one sample (one part).
  const LensSample& first = parts.front().sample;
  // Views are added straight into the sum unless the scene's geometry costs more than a layer.
  double triangles = 0.0;
  for (const Instance& instance : gpuScene_.scene().instances)
    triangles +=
        static_cast<double>(gpuScene_.scene().meshes[static_cast<std::size_t>(instance.mesh)].indices.size() / 3);
  // A scene with alphaMode BLEND always: an added view keeps one fragment per pixel, and blend
  // surfaces need every one over what lies behind (ScenePass::drawBlended).
  sum.setLayered(anyBlended(gpuScene_.scene()) ||
                 Accumulator::layersAreCheaper(triangles, static_cast<double>(size_.widthPx) * size_.heightPx));
  const ApertureCell* cell = parts.front().cell;
  for (const LensViews::ChannelView& channel : views.channelViews()) {
    const std::optional<Accumulator::CellView> cellView =
        cell ? std::optional(views.cellView(first, *cell, channel.channel)) : std::nullopt;
    const Accumulator::View view = sum.nextView(
        constantBackground(gpuScene_.scene()), channel.mask, views.curvatureShiftPx(first), LensViews::jitterPx(first),
        views.barrelLens(first, channel.channel), cellView ? &*cellView : nullptr);
    for (const SamplePart& part : parts)
      scenePass_.draw(gpuScene_, views.clipFromWorld(part.sample, channel.channel), view.target, lodBias, part.boxes,
                      view.addWeight ? &*view.addWeight : nullptr);
  }
}

int Renderer::addSamples(int count) {
  if (adaptive_) throw std::logic_error("Renderer::addSamples on a per-tile plan: use step()");
  // Each view is one of samplesPlanned() jittered samples of every pixel: its texture lookups
  // filter over its share of the pixel (scene.frag).
  const float lodBias = -0.5f * std::log2(static_cast<float>(samplesPlanned()));
  int added = 0;
  for (; added < count && done_ < samplesPlanned(); ++added, ++done_) {
    const LensSample& s = samples_[static_cast<std::size_t>(done_)];
    if (samplesPlanned() == 1) {
      // A single view is the image itself unless a pass follows it (the lens, the vignetting).
      const gl::RenderTarget& out = plan_.remap        ? target(undistorted_, size_)
                                    : plan_.vignetting ? target(unvignetted_, size_)
                                                       : target(output_, size_);
      scenePass_.draw(gpuScene_, views_->clipFromWorld(s, Channel::Green), out.drawTarget(), lodBias);
    } else {
      drawSample({{s, nullptr, cells_.empty() ? nullptr : &cells_[static_cast<std::size_t>(done_)]}}, *accumulator_,
                 lodBias);
    }
  }
  return added;
}

Image Renderer::resolve() {
  const gl::RenderTarget& out = resolveOnGpu();
  glFinish();
  return out.readColor();
}

void Renderer::complete(const std::function<void()>& afterBatch) {
  if (adaptive_) {
    while (step())
      if (afterBatch) afterBatch();
    return;
  }
  const int batch = std::max(1, plan_.apertureSamples / 50);
  while (done_ < samplesPlanned()) {
    addSamples(batch);
    if (afterBatch) afterBatch();
  }
}

Renderer::Progress Renderer::progress() const {
  if (adaptive_) {
    // A tile at the target can go on again when its neighbours' estimates (pooled with its own)
    // rise; the count shown is the most that have been at the target, so that progress never falls.
    const FrameEstimate e = estimate();
    tilesAtTargetShown_ = std::max(tilesAtTargetShown_, e.tiles - e.tilesActive);
    return {tilesAtTargetShown_, e.tiles};
  }
  return {done_, samplesPlanned()};
}

int Renderer::progressTotal(const FramePlan& plan, ImageSize size) {
  return plan.adaptive ? makeTileGrid(size, plan.adaptive->tileSizePx).count() : std::max(plan.apertureSamples, 1);
}

Image Renderer::render(const Camera& camera, const FramePlan& plan, ImageSize size) {
  begin(camera, plan, size);
  complete();
  return resolve();
}

const gl::RenderTarget& Renderer::renderPinhole(const Camera& camera, ImageSize size) {
  const gl::RenderTarget& v = target(view_, size);
  scenePass_.draw(gpuScene_, clipFromWorld(camera.view), v.drawTarget());
  glFinish();
  return v;
}

std::vector<float> Renderer::pinholeDepth(const Camera& camera, ImageSize size) {
  return renderPinhole(camera, size).readDepth();
}

const gl::RenderTarget& Renderer::resolveOnGpu() {
  if (done_ == 0) throw std::logic_error("Renderer::resolve before any sample");
  const gl::RenderTarget& out = target(output_, outSize_);
  const VignetteGain gain = vignetteGainFor(views_->map().camera(), outSize_);
  // A resolve of many views is the frame's last pass and multiplies the gain in itself.
  if (!adaptive_ && samplesPlanned() > 1) {  // the lens, if any, was applied as the views were summed
    accumulator_->resolve(out, plan_.vignetting ? &gain : nullptr);
    return out;
  }
  // Else the vignetting pass follows, reading a target of its own: each resolve then applies the
  // gain once, however often a progressive frame is resolved.
  const gl::RenderTarget& resolved = plan_.vignetting ? target(unvignetted_, outSize_) : out;
  if (adaptive_) {
    const gl::Program& program = streamsProgram(false);
    bindStreams();
    resolved.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glProgramUniform1i(program.id(), 0, grid_.tileSizePx);
    fullScreen_.draw(program);
  } else if (plan_.remap) {
    lensPass_->apply(target(undistorted_, size_), resolved);
  }  // else a single view drawn straight into `resolved` (addSamples)
  if (plan_.vignetting) vignettePass_->apply(gain, resolved, out);
  return out;
}

}  // namespace lenslab
