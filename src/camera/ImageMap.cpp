#include "camera/ImageMap.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/LensBarrel.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace lenslab {
namespace {

// The camera's lens effects besides vignetting (which moves no ray: it scales the pixel's light).
bool effectsMoveRays(const LensEffects& effects) {
  LensEffects moving = effects;
  moving.vignetting = {};
  return !moving.isZero();
}

Camera withoutEffects(Camera camera) {
  camera.lens.effects = {};
  return camera;
}

}  // namespace

ThinLensMap::ThinLensMap(const Camera& camera, ImageSize size)
    : ThinLensMap(camera, size, Overscan{camera, size, {0, 0}}) {}

ThinLensMap::ThinLensMap(const Camera& camera, ImageSize size, Overscan overscan)
    : ImageMap(camera, size),
      overscan_(std::move(overscan)),
      rayCamera_(withoutEffects(camera)),
      movesRays_(effectsMoveRays(camera.lens.effects)),
      // Three rays per sample when the channels differ (lateral or axial colour), else one for all.
      rayChannels_(camera.lens.effects.chromatic.hasLateral() || camera.lens.effects.chromatic.hasAxial() ? 3 : 1) {}

ThinLensMap ThinLensMap::truePerspective(const Camera& camera, ImageSize size) {
  return ThinLensMap(withoutEffects(camera), size);
}

glm::dvec2 ThinLensMap::windowFromPixel(glm::dvec2 pixel) const {
  return lenslab::windowFromPixel(camera_.view.window, pixel, size_.widthPx, size_.heightPx);
}

glm::dvec2 ThinLensMap::pixelFromWindow(glm::dvec2 uv) const {
  return lenslab::pixelFromWindow(camera_.view.window, uv, size_.widthPx, size_.heightPx);
}

glm::dvec2 ThinLensMap::normalisedFromPixel(glm::dvec2 pixel) const {
  return normalisedFromWindow(camera_.view, windowFromPixel(pixel));
}

glm::dvec2 ThinLensMap::pixelFromNormalised(glm::dvec2 normalised) const {
  return pixelFromWindow(windowFromNormalised(camera_.view, normalised));
}

glm::dvec2 ThinLensMap::undistortNormalised(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const {
  const auto undistorted = camera_.lens.effects.undistortChannel(c, distorted, guess);
  if (!undistorted) {
    // The inverse follows the branch that contains the centre (continuation, LensEffects.cpp), so it
    // fails only where that branch folds; validateLensEffects refuses folds inside the image, so
    // this is a point the lens cannot show.
    throw InputError(
        cat(camera_.source, ": distortion: no true position on the lens's branch lands at normalised (", distorted.x,
            ", ", distorted.y,
            ") (the distortion folds before it); use weaker distortion coefficients or a narrower field of view"));
  }
  return *undistorted;
}

ChannelSample ThinLensMap::undistorted(Channel c, glm::dvec2 pixel, std::optional<glm::dvec2> guess) const {
  const glm::dvec2 distorted = normalisedFromPixel(pixel);
  ChannelSample s;
  s.normalised =
      camera_.lens.effects.needsRemap() ? undistortNormalised(c, distorted, guess.value_or(distorted)) : distorted;
  s.pixel = pixelFromNormalised(s.normalised);
  s.inverseFocusShift = camera_.lens.effects.inverseFocusShift(c, s.normalised);
  return s;
}

std::optional<CameraRay> ThinLensMap::start(glm::dvec2 pixel, int channel) const {
  if (!movesRays_) return std::nullopt;
  CameraRay r;
  r.channel = channel;
  r.normalised = undistorted(static_cast<Channel>(channel), pixel).normalised;
  return r;
}

glm::dvec2 ThinLensMap::renderPixelFromOutput(glm::dvec2 pixel) const {
  const glm::dvec2 truth = camera_.lens.effects.needsRemap() ? undistorted(Channel::Green, pixel).pixel : pixel;
  return truth + glm::dvec2(overscan_.padPx);
}

std::optional<glm::dvec2> ThinLensMap::pixelOfPoint(const glm::dvec3& world) const {
  const ViewSpec& view = camera_.view;
  const ViewBasis b = viewBasis(view);
  const glm::dvec3 q = world - prpWorld(view);
  const double depth = -glm::dot(q, b.n);  // along the view direction, −n
  if (!(depth > 0.0)) return std::nullopt;
  // The view plane (n = 0, the VRP's) lies PRP.n in front of the PRP: similar triangles.
  const double scale = view.prp.z / depth;
  const glm::dvec2 window(view.prp.x + glm::dot(q, b.u) * scale, view.prp.y + glm::dot(q, b.v) * scale);
  return pixelFromNormalised(camera_.lens.effects.distortChannel(Channel::Green, normalisedFromWindow(view, window)));
}

glm::dvec2 ThinLensMap::outputFromRenderPixel(glm::dvec2 renderPixel) const {
  const Overscan& o = overscan_;
  const glm::dvec2 n = normalisedFromWindow(
      o.camera.view, lenslab::windowFromPixel(o.camera.view.window, renderPixel, o.size.widthPx, o.size.heightPx));
  return pixelFromNormalised(camera_.lens.effects.distortChannel(Channel::Green, n));
}

glm::dmat4 ThinLensMap::clipFromWorld(const LensSample& s, Channel c) const {
  const Camera& rendered = overscan_.camera;
  const Window& w = rendered.view.window;
  const glm::dvec2 pixelSize(w.width() / overscan_.size.widthPx, w.height() / overscan_.size.heightPx);
  // Image y runs down, v runs up: a sub-pixel offset of +y moves the sample toward −v.
  const glm::dvec2 pixelOffset(s.pixel.x * pixelSize.x, -s.pixel.y * pixelSize.y);
  // Axial chromatic aberration: each colour has its own plane of focus (green's is the camera's).
  const double shift = rendered.lens.effects.chromatic.inverseFocusShift(c);
  return lenslab::clipFromWorld(viewThroughLens(rendered, rendered.lens.lensOffset(s.lens), pixelOffset, shift));
}

glm::dvec2 ThinLensMap::normalisedAtRenderCorner() const {
  const Window& w = overscan_.camera.view.window;
  return normalisedFromWindow(overscan_.camera.view, {w.umin, w.vmin});
}

glm::dvec2 ThinLensMap::normalisedPerRenderPixel() const {
  const Window& w = overscan_.camera.view.window;
  return glm::dvec2(w.width() / overscan_.size.widthPx, w.height() / overscan_.size.heightPx) /
         overscan_.camera.view.prp.z;
}

double ThinLensMap::gainAt(glm::dvec2 pixel) const {
  // Vignetting scales the pixel's light by the gain at its own place on the film (distorted
  // coordinates: the output grid is the film).
  if (camera_.lens.effects.vignetting.isZero()) return 1.0;
  const glm::dvec2 n = normalisedFromPixel(pixel);
  return camera_.lens.effects.vignetting.gain(glm::dot(n, n));
}

std::optional<CameraRay> ThinLensMap::centreRay(glm::dvec2 pixel) const {
  std::optional<CameraRay> r = ray(pixel, {0.0, 0.0}, 1);
  if (r) r->blocked = false;
  return r;
}

RealLensMap::RealLensMap(LensCamera lens, const Camera& placed, ImageSize size, std::optional<Camera> fittedCamera)
    : ImageMap(placed, size), lens_(std::move(lens)) {
  if (fittedCamera) fitted_ = std::make_shared<const ThinLensMap>(*fittedCamera, size);
}

const ThinLensMap& RealLensMap::fitted() const {
  if (!fitted_) throw std::logic_error("RealLensMap::fitted on a map built without the fitted camera");
  return *fitted_;
}

std::optional<CameraRay> RealLensMap::ray(glm::dvec2 pixel, glm::dvec2 lens, int channel,
                                          const CameraRay* /*near*/) const {
  const std::optional<LensCamera::WorldRay> w = lens_.ray(pixel, size_.widthPx, size_.heightPx, lens, channel);
  if (!w) return std::nullopt;  // stopped by a rim or the stop
  CameraRay r;
  r.ray = Ray{w->origin, w->direction, 0.0, std::numeric_limits<double>::infinity()};
  r.weight = w->weight;
  r.pixel = pixel;
  r.lensPoint = lens;
  r.channel = channel;
  return r;
}

Ray RealLensMap::footprintRay(const CameraRay& r, glm::dvec2 offsetPx) const {
  const std::optional<LensCamera::WorldRay> n =
      lens_.ray(r.pixel + offsetPx, size_.widthPx, size_.heightPx, r.lensPoint, r.channel);
  // A neighbour the lens stops: no footprint that way.
  return n ? Ray{n->origin, n->direction, 0.0, std::numeric_limits<double>::infinity()} : r.ray;
}

std::optional<CameraRay> RealLensMap::centreRay(glm::dvec2 pixel) const {
  std::call_once(centreRays_->once, [&] { centreRays_->rays = std::make_unique<CentreRays>(lens_); });
  const std::optional<LensCamera::WorldRay> w = centreRays_->rays->at(pixel, size_.widthPx, size_.heightPx);
  if (!w) return std::nullopt;
  CameraRay r;
  r.ray = Ray{w->origin, w->direction, 0.0, std::numeric_limits<double>::infinity()};
  r.weight = w->weight;
  r.pixel = pixel;
  r.lensPoint = {0.5, 0.5};
  r.channel = 1;
  return r;
}

}  // namespace lenslab
