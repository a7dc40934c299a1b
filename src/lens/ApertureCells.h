#pragma once
// The aperture cut into N cells of equal area, one view each: the cell a view stands for when it
// is filtered by its cell's image (render/Accumulator.h, the cell filter).
//
// A point at depth Z seen from aperture point p lands, seen from another point q of the thin lens,
// at its image position plus M(Z)·(q − p): the lecture's circle of confusion is the aperture scaled
// by M, which is affine in the aperture position. So over one cell the point is smeared into the
// cell's shape, scaled by M and placed with p on the point's image; summed over the N cells, the
// copies tile the whole circle of confusion.
//
// Cells are rings of sectors, equal in area (the ring radii √(cells inside / N)): ring i of k holds
// about (2i + 1)/k² of the cells, so each cell is about as wide as it is deep. Membership is a
// radius test and two cross products (no angle), which a shader does for every neighbour it reads.
// Points are on the unit disk (lens/AperturePattern.h's LensSample.lens), before the shape map.
#include "lens/AperturePattern.h"
#include "lens/ApertureShape.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <numbers>
#include <vector>

namespace lenslab {

struct ApertureCell {
  // A sector of a ring ('rings')…
  double innerRadius = 0.0;  // of the unit disk
  double outerRadius = 1.0;
  double startAngle = 0.0;  // radians, anticlockwise from +x
  double sweepAngle = 0.0;  // radians; 2π: the whole ring
  // … or a box of the concentric map's square ('sobol': an elementary box of its (0, 2)-net).
  bool square = false;
  glm::dvec2 squareMin{0.0}, squareMax{1.0};

  bool contains(glm::dvec2 diskPoint) const;
  // Points of its boundary, `perSide` along each of its four sides: on the unit disk, or carried by
  // `shape`'s map onto the aperture (lens/ApertureShape.h; the map keeps areas, so the cell's
  // image there has the same area).
  std::vector<glm::dvec2> outline(int perSide, const ApertureShape& shape = {}) const;
  // The rectangle with the cell's area, centroid and second moments: centre + s·axis0 + t·axis1
  // for s, t in [−1, 1] (half-axes, on the unit disk, or of the cell's image on the aperture of
  // `shape`). A small cell image is measured as this rectangle's image (a parallelogram), whose
  // exact overlap with each pixel is cheap; over any grid of pixels its overlaps sum to its area.
  struct Rectangle {
    glm::dvec2 centre{0.0}, axis0{0.0}, axis1{0.0};
  };
  Rectangle momentRectangle(const ApertureShape& shape = {}) const;
  double area() const {  // of the unit disk (the map preserves area: π per unit of the square)
    if (square) return std::numbers::pi * (squareMax.x - squareMin.x) * (squareMax.y - squareMin.y);
    return 0.5 * sweepAngle * (outerRadius * outerRadius - innerRadius * innerRadius);
  }
};

// The cells of `count` views and a point jittered in each (uniform in area), in a random order;
// the pixel offsets are the Sobol' pixel stream's. A ring holds one cell only when count is 1 or
// 2 (the whole disk, or two half-disks): every sector is at most half a turn.
struct CellSamples {
  std::vector<LensSample> samples;
  std::vector<ApertureCell> cells;  // cells[i] is the one samples[i] lies in
};
// 'rings' for any count; 'sobol' (the pattern's own points: one in each 2^a × 2^b box of the
// concentric square, a + b = log2 count) for a power of two. Other patterns have no cells.
CellSamples makeCellSamples(AperturePattern pattern, int count, std::uint32_t seed);
bool hasCells(AperturePattern pattern, int count);

// The farthest the cell filter reaches for a neighbour's image, in pixels: a larger image is cut
// there. It is also the most margin the views are rendered with.
constexpr int kCellFilterMaxReachPx = 32;

}  // namespace lenslab
