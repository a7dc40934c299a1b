#include "render/LensViews.h"

#include <utility>

namespace lenslab {

LensViews::LensViews(ThinLensMap map, const FramePlan& plan)
    : map_(std::move(map)), fieldCurvature_(plan.fieldCurvature) {
  // Axial chromatic aberration: each colour has its own plane of focus, so each gets its own view.
  if (plan.viewsPerSample == 3) {
    for (int c = 0; c < 3; ++c) {
      ChannelView v{glm::vec3(0.0f), static_cast<Channel>(c)};
      v.mask[c] = 1.0f;
      channels_.push_back(v);
    }
  } else {
    channels_.push_back(ChannelView{});
  }
}

Accumulator::Curvature LensViews::normalisedPixels() const {
  return Accumulator::Curvature{glm::vec2(map_.normalisedAtRenderCorner()), glm::vec2(map_.normalisedPerRenderPixel())};
}

std::optional<Accumulator::Barrel> LensViews::barrelMask() const {
  if (!rendered().lens.hasBarrel()) return std::nullopt;
  const Accumulator::Curvature pixels = normalisedPixels();
  return Accumulator::Barrel{pixels.normalisedAtOrigin, pixels.normalisedPerPixel,
                             static_cast<float>(rendered().lens.barrel.distance / rendered().lens.barrel.radius)};
}

std::optional<Accumulator::Curvature> LensViews::curvatureWarp() const {
  if (!fieldCurvature_) return std::nullopt;
  return normalisedPixels();
}

glm::vec2 LensViews::curvatureShiftPx(const LensSample& s) const {
  const Camera& camera = rendered();
  const Window& w = camera.view.window;
  const ImageSize size = map_.overscan().size;
  const glm::dvec2 pixelSize(w.width() / size.widthPx, w.height() / size.heightPx);
  const Lens& lens = camera.lens;
  return glm::vec2(lens.lensOffset(s.lens) * camera.view.prp.z * lens.effects.fieldCurvature.inverseFocusPerRadius2 /
                   pixelSize);
}

glm::vec2 LensViews::barrelLens(const LensSample& s, Channel c) const {
  const Camera& camera = rendered();
  const Lens& lens = camera.lens;
  if (!lens.hasBarrel()) return glm::vec2(0.0f);
  const double shift = lens.effects.chromatic.inverseFocusShift(c);
  return glm::vec2(lens.lensOffset(s.lens) * (1.0 - lens.barrel.distance * (camera.inverseFocusDistance() + shift)) /
                   lens.barrel.radius);
}

}  // namespace lenslab
