#include "render/Renderer.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"

#include <cmath>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace lenslab {

Renderer::Renderer(const Scene& scene) : gpuScene_(scene) {}

const gl::RenderTarget& Renderer::target(std::unique_ptr<gl::RenderTarget>& slot, ImageSize size) {
  if (!slot || slot->width() != size.widthPx || slot->height() != size.heightPx)
    slot = std::make_unique<gl::RenderTarget>(size.widthPx, size.heightPx);
  return *slot;
}

void Renderer::begin(const Camera& camera, const FramePlan& plan, ImageSize size) {
  plan_ = plan;
  camera_ = plan.remap ? plan.overscan.camera : camera;
  size_ = plan.remap ? plan.overscan.size : size;
  outSize_ = size;
  done_ = 0;
  // Axial chromatic aberration: each colour has its own plane of focus, so each gets its own view.
  for (const Channel c : {Channel::Red, Channel::Green, Channel::Blue})
    channelFocusShifts_[static_cast<std::size_t>(c)] = camera_.effects.chromatic.inverseFocusShift(c);
  if (plan.remap) {
    if (!lensPass_) lensPass_ = std::make_unique<LensPass>();
    lensPass_->prepare(camera, size, plan.overscan, plan.apertureSamples > 1);
  }
  if (plan.apertureSamples <= 1) {
    // No lens: the pinhole view from the PRP, at the pixel centres.
    samples_ = {LensSample{{0.0, 0.0}, {0.0, 0.0}}};
  } else {
    samples_ = makeApertureSamples(plan.pattern, plan.apertureSamples, plan.seed);
    if (!accumulator_) accumulator_ = std::make_unique<Accumulator>();
    std::optional<Accumulator::Curvature> curvature;
    if (plan.fieldCurvature) {
      const Window& w = camera_.view.window;
      const glm::dvec2 origin = normalisedFromWindow(camera_.view, {w.umin, w.vmin});
      const glm::dvec2 step = glm::dvec2(w.width() / size_.widthPx, w.height() / size_.heightPx) / camera_.view.prp.z;
      curvature = Accumulator::Curvature{glm::vec2(origin), glm::vec2(step)};
    }
    // With distortion or lateral colour each view's samples go straight to where the lens puts
    // them, as the views are summed: no resampling of the mean afterwards.
    accumulator_->start(size_.widthPx, size_.heightPx, curvature ? &*curvature : nullptr,
                        plan.remap ? &lensPass_->gather() : nullptr);
  }
}

int Renderer::addSamples(int count) {
  const Window& w = camera_.view.window;
  const glm::dvec2 pixelSize(w.width() / size_.widthPx, w.height() / size_.heightPx);
  // Each view is one of samplesPlanned() jittered samples of every pixel: its texture lookups
  // filter over its share of the pixel (scene.frag).
  const float lodBias = -0.5f * std::log2(static_cast<float>(samplesPlanned()));
  int added = 0;
  for (; added < count && done_ < samplesPlanned(); ++added, ++done_) {
    const LensSample& s = samples_[static_cast<std::size_t>(done_)];
    // Image y runs down, v runs up: a sub-pixel offset of +y moves the sample toward −v.
    const glm::dvec2 pixelOffset(s.pixel.x * pixelSize.x, -s.pixel.y * pixelSize.y);
    const glm::dvec2 lensOffset = s.lens * camera_.apertureRadius;
    // Field curvature: this view's shift at r = 1, δ·d·κ, in pixels (Accumulator.h).
    const glm::vec2 curvatureShift(lensOffset * camera_.view.prp.z * camera_.effects.fieldCurvature.inverseFocusPerRadius2 /
                                   pixelSize);
    // The same offset in view pixels, GL orientation, for the lens gather.
    const glm::vec2 jitter(static_cast<float>(s.pixel.x), static_cast<float>(-s.pixel.y));
    const auto clip = [&](double inverseFocusShift) {
      return clipFromWorld(viewThroughLens(camera_, lensOffset, pixelOffset, inverseFocusShift));
    };
    if (samplesPlanned() == 1) {
      const gl::RenderTarget& out = plan_.remap ? target(undistorted_, size_) : target(output_, size_);
      scenePass_.draw(gpuScene_, clip(0.0), out.drawTarget(), lodBias);
    } else if (plan_.viewsPerSample == 3) {
      for (int c = 0; c < 3; ++c) {
        glm::vec3 mask(0.0f);
        mask[c] = 1.0f;
        scenePass_.draw(gpuScene_, clip(channelFocusShifts_[static_cast<std::size_t>(c)]), accumulator_->nextView(mask, curvatureShift, jitter), lodBias);
      }
    } else {
      scenePass_.draw(gpuScene_, clip(0.0), accumulator_->nextView(glm::vec3(1.0f), curvatureShift, jitter), lodBias);
    }
  }
  return added;
}

Image Renderer::resolve() {
  const gl::RenderTarget& out = resolveOnGpu();
  glFinish();
  return out.readColor();
}

Image Renderer::render(const Camera& camera, const FramePlan& plan, ImageSize size) {
  begin(camera, plan, size);
  addSamples(samplesPlanned());
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
  if (plan_.remap && samplesPlanned() == 1) {
    lensPass_->apply(target(undistorted_, size_), out);
  } else if (samplesPlanned() > 1) {  // the lens, if any, was applied as the views were summed
    accumulator_->resolve(out);
  }
  return out;
}

}  // namespace lenslab
