#include "camera/CellSpread.h"

#include "camera/Projection.h"

#include <stdexcept>

namespace lenslab {
namespace {

// Render pixels (GL orientation) where `clipFromWorld` puts `world`.
glm::dvec2 renderPixel(const glm::dmat4& clipFromWorld, const glm::dvec3& world, ImageSize size) {
  const glm::dvec4 clip = clipFromWorld * glm::dvec4(world, 1.0);
  return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(size.widthPx, size.heightPx);
}

}  // namespace

CellSpread cellSpread(const ThinLensMap& map, const LensSample& s, Channel c) {
  const ViewSpec& spec = map.overscan().camera.view;
  if (spec.projection != Projection::Perspective)
    throw std::logic_error("cellSpread: the cell filter needs a perspective projection");
  const ImageSize size = map.overscan().size;
  // Two points on the centre view's axis, at reverse-Z depths 1/2 and 1/8 (any two would do).
  const glm::dmat4 centreFromWorld = glm::inverse(map.clipFromWorld(LensSample{{0.0, 0.0}, s.pixel}, c));
  const double ndc[2] = {0.5, 0.125};
  glm::dmat2 spread[2];
  double inverseDepth[2];
  // Steps of the aperture point (lens/ApertureShape.h: after the shape's map, whose cells are
  // curved and which is not affine in the disk's point), taken back to the disk the samples live on.
  const ApertureShape& shape = map.overscan().camera.lens.aperture;
  const glm::dvec2 aperturePoint = apertureFromDisk(s.lens, shape);
  constexpr double kStep = 1e-3;  // of the aperture; the image is affine in it, so any step is exact
  for (int k = 0; k < 2; ++k) {
    const glm::dvec4 h = centreFromWorld * glm::dvec4(0.0, 0.0, ndc[k], 1.0);
    const glm::dvec3 world = glm::dvec3(h) / h.w;
    inverseDepth[k] = 1.0 / depthFromReverseZ(spec, ndc[k]);
    for (int axis = 0; axis < 2; ++axis) {
      glm::dvec2 step(0.0);
      step[axis] = kStep;
      LensSample plus = s, minus = s;
      plus.lens = diskFromAperture(aperturePoint + step, shape);
      minus.lens = diskFromAperture(aperturePoint - step, shape);
      spread[k][axis] = (renderPixel(map.clipFromWorld(plus, c), world, size) -
                         renderPixel(map.clipFromWorld(minus, c), world, size)) /
                        (2.0 * kStep);
    }
  }
  CellSpread out;
  out.perInverseDepth = (spread[0] - spread[1]) / (inverseDepth[0] - inverseDepth[1]);
  out.atInfinity = spread[0] - inverseDepth[0] * out.perInverseDepth;
  // 1/Z is affine in z_ndc for a perspective projection (camera/Projection.h).
  const double slope = (inverseDepth[0] - inverseDepth[1]) / (ndc[0] - ndc[1]);
  out.inverseDepthFromNdc = {slope, inverseDepth[0] - slope * ndc[0]};
  return out;
}

}  // namespace lenslab
