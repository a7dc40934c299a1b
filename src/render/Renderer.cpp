#include "render/Renderer.h"

#include "camera/Projection.h"

#include <algorithm>
#include <stdexcept>

namespace lenslab {

Renderer::Renderer(const Scene& scene) : gpuScene_(scene) {}

const gl::RenderTarget& Renderer::target(std::unique_ptr<gl::RenderTarget>& slot, ImageSize size) {
  if (!slot || slot->width() != size.widthPx || slot->height() != size.heightPx)
    slot = std::make_unique<gl::RenderTarget>(size.widthPx, size.heightPx);
  return *slot;
}

void Renderer::begin(const Camera& camera, const FramePlan& plan, ImageSize size) {
  camera_ = camera;
  size_ = size;
  done_ = 0;
  if (plan.apertureSamples <= 1) {
    // No lens: the pinhole view from the PRP, at the pixel centres.
    samples_ = {LensSample{{0.0, 0.0}, {0.0, 0.0}}};
  } else {
    samples_ = makeApertureSamples(plan.pattern, plan.apertureSamples, plan.seed);
    if (!accumulator_) accumulator_ = std::make_unique<Accumulator>();
    accumulator_->start(size.widthPx, size.heightPx);
  }
}

int Renderer::addSamples(int count) {
  const Window& w = camera_.view.window;
  const glm::dvec2 pixelSize(w.width() / size_.widthPx, w.height() / size_.heightPx);
  int added = 0;
  for (; added < count && done_ < samplesPlanned(); ++added, ++done_) {
    const LensSample& s = samples_[static_cast<std::size_t>(done_)];
    // Image y runs down, v runs up: a sub-pixel offset of +y moves the sample toward −v.
    const glm::dvec2 pixelOffset(s.pixel.x * pixelSize.x, -s.pixel.y * pixelSize.y);
    const ViewSpec view = viewThroughLens(camera_, s.lens * camera_.apertureRadius, pixelOffset);
    const glm::dmat4 clip = clipFromWorld(view);
    if (samplesPlanned() == 1) scenePass_.draw(gpuScene_, clip, target(output_, size_).drawTarget());
    else scenePass_.draw(gpuScene_, clip, accumulator_->nextView());
  }
  return added;
}

Image Renderer::resolve() {
  if (done_ == 0) throw std::logic_error("Renderer::resolve before any sample");
  const gl::RenderTarget& out = target(output_, size_);
  if (samplesPlanned() > 1) accumulator_->resolve(out);
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
  if (done_ == 0) throw std::logic_error("Renderer::resolveOnGpu before any sample");
  const gl::RenderTarget& out = target(output_, size_);
  if (samplesPlanned() > 1) accumulator_->resolve(out);
  return out;
}

}  // namespace lenslab
