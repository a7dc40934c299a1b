#include "render/LensViews.h"

#include "camera/CellSpread.h"
#include "lens/ApertureShape.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lenslab {

LensViews::LensViews(ThinLensMap map, const FramePlan& plan)
    : map_(std::move(map)),
      fieldCurvature_(plan.fieldCurvature),
      depthMin_(plan.depthMin),
      depthMax_(plan.depthMax),
      cocMaxPx_(plan.cocMaxPx) {
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

Accumulator::CellView LensViews::cellView(const LensSample& s, const ApertureCell& cell, Channel c) const {
  const CellSpread spread = cellSpread(map_, s, c);
  // The inverse depths whose images can be seen: those of the scene's depth range where the spread
  // is no larger than the largest circle in view (the pre-pass's, when it ran) allows. The spread's
  // scale, (M₀₀ + M₁₁)/2, is affine in 1/Z.
  double lo = depthMax_ > 0.0 && std::isfinite(depthMax_) ? 1.0 / depthMax_ : spread.inverseDepthFromNdc.y;
  double hi = depthMin_ > 0.0 ? 1.0 / depthMin_ : spread.inverseDepthFromNdc.x + spread.inverseDepthFromNdc.y;
  const double scaleAtInfinity = 0.5 * (spread.atInfinity[0][0] + spread.atInfinity[1][1]);
  const double scalePerInverseDepth = 0.5 * (spread.perInverseDepth[0][0] + spread.perInverseDepth[1][1]);
  if (cocMaxPx_ > 0.0 && scalePerInverseDepth != 0.0) {
    const double largest = 0.5 * cocMaxPx_ * apertureReach(rendered().lens.aperture) + 0.5;
    const double a = (-largest - scaleAtInfinity) / scalePerInverseDepth,
                 b = (largest - scaleAtInfinity) / scalePerInverseDepth;
    lo = std::max(lo, std::min(a, b));
    hi = std::min(hi, std::max(a, b));
    if (lo > hi) lo = hi = std::clamp(-scaleAtInfinity / scalePerInverseDepth, lo, hi);
  }
  // The displacements x − y from a neighbour y to a pixel x its image covers: M(1/Z)·(q − p) for q
  // in the cell. M is affine in 1/Z, so all of them lie in the box of those at the two ends.
  glm::dvec2 least(0.0), most(0.0);
  const ApertureShape& shape = rendered().lens.aperture;
  const glm::dvec2 aperturePoint = apertureFromDisk(s.lens, shape);
  const std::vector<glm::dvec2> outline = cell.outline(16, shape);
  for (const double inverseDepth : {lo, hi}) {
    const glm::dmat2 m = spread.at(inverseDepth);
    for (const glm::dvec2& point : outline) {
      const glm::dvec2 d = m * (point - aperturePoint);
      least = glm::min(least, d);
      most = glm::max(most, d);
    }
  }
  Accumulator::CellView v;
  v.spreadAtInfinity = glm::mat2(spread.atInfinity);
  v.spreadPerInverseDepth = glm::mat2(spread.perInverseDepth);
  v.inverseDepthFromNdc = glm::vec2(spread.inverseDepthFromNdc);
  v.lensPoint = glm::vec2(aperturePoint);
  v.shape = shape;
  v.depthReference = static_cast<float>(1.0 / (0.5 * spread.inverseDepthFromNdc.x + spread.inverseDepthFromNdc.y));
  v.cell = cell;
  const auto whole = [](double d) {
    return static_cast<int>(std::clamp(d, -double(kCellFilterMaxReachPx), double(kCellFilterMaxReachPx)));
  };
  for (int r = 0; r < 2; ++r) {
    v.displacementMinPx[r] = whole(std::floor(least[r]));
    v.displacementMaxPx[r] = whole(std::ceil(most[r]));
  }
  return v;
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
