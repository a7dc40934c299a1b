#pragma once
// How far a thin-lens view's point moves in the image as the aperture point moves: the lecture's
// circle of confusion per unit of aperture, for the cell filter (render/Accumulator.h).
//
// A view from aperture point p keeps its window on the plane of focus (distance z_f), so a point at
// depth Z lands at window position X·z_f/Z + p·(1 − z_f/Z): moving p by δ moves it by δ·(1 − z_f/Z),
// zero on the plane of focus and affine in 1/Z. In the render's pixels, per unit of the aperture
// point (lens/ApertureShape.h's apertureFromDisk: after the shape's map, the anamorphic squeeze
// included; the aperture radius is in M), that is a 2 × 2 matrix M(1/Z) = atInfinity +
// perInverseDepth / Z. Pure C++, no GL.
#include "camera/ImageMap.h"

#include <glm/glm.hpp>

namespace lenslab {

struct CellSpread {
  glm::dmat2 atInfinity{0.0};           // render pixels (GL orientation: x right, y up) per unit of aperture
  glm::dmat2 perInverseDepth{0.0};      // plus this times 1/Z (Z: world units from the PRP along −n)
  glm::dvec2 inverseDepthFromNdc{0.0};  // 1/Z = x·z_ndc + y for the render's reverse-Z depth

  glm::dmat2 at(double inverseDepth) const { return atInfinity + inverseDepth * perInverseDepth; }
};

// The spread of the view of sample `s`, channel `c` (its focus), measured on the view's own
// clipFromWorld (central differences in the lens point at two depths), so it is what the raster
// draws. Perspective projections only.
CellSpread cellSpread(const ThinLensMap& map, const LensSample& s, Channel c);

}  // namespace lenslab
