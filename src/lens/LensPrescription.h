#pragma once
// A lens prescription: the surfaces of a real lens design, from the scene side to the film, as
// lens design books and patents list them and as pbrt-v4's lens files write them. Pure data and
// parsing (std only), no GL.
//
// The file: one row per surface, numbers separated by white space, '#' starts a comment.
//   radius_mm  thickness_mm  index  aperture_mm  [abbe]
// - radius_mm: the surface's radius of curvature, positive when its centre lies on the film side
//   (a surface convex toward the scene); 0 marks the aperture stop (exactly one row); `inf` a
//   plane surface.
// - thickness_mm: the axial distance from this surface to the next (for the last row, to where
//   the film sits when the lens is focused at infinity may be left 0: focusing places the film).
// - index: the refractive index at the d line (587.6 nm) of the medium after the surface, on its
//   film side; 0 or 1 for air (pbrt's files write 0 on the stop row).
// - aperture_mm: the surface's clear diameter; at the stop, the stop's full-open diameter.
// - abbe (optional): the Abbe number V_d of that medium, for dispersion; 0 or absent for none.
//   Either every glass row gives one or none does.
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

struct LensSurface {
  double radiusMm = 0.0;     // 0: the aperture stop; ±inf: a plane
  double thicknessMm = 0.0;  // to the next surface, along the axis
  double indexAfter = 1.0;   // n_d of the medium on the film side (1 for air)
  double apertureMm = 0.0;   // clear diameter
  double abbeAfter = 0.0;    // V_d of the medium on the film side; 0 when not given or air
  int line = 0;              // in the file, for messages
  bool isStop() const { return radiusMm == 0.0; }
  bool isPlane() const;
  // 1 / radius (0 for a plane or the stop), in 1/mm.
  double curvaturePerMm() const;
  // The surface's axial offset from its vertex at height r (mm; 0 for a plane or the stop).
  double sagMm(double r) const;
};

struct LensPrescription {
  std::string source;                 // the file, for messages
  std::vector<std::string> comments;  // its comment lines, without '#' (the design's source)
  std::vector<LensSurface> surfaces;  // scene side first
  // The refractive index in front of surface i (the scene side): air before the first.
  double indexBefore(std::size_t i) const { return i == 0 ? 1.0 : surfaces[i - 1].indexAfter; }
  std::size_t stopIndex() const;  // the row with radius 0
  bool hasDispersion() const;     // every glass row gives an Abbe number
  // Axial position of surface i's vertex, the first at 0, growing toward the film (mm).
  double vertexMm(std::size_t i) const;
  // From the first vertex to the last (the lens's length, without the last row's thickness).
  double lengthMm() const { return surfaces.empty() ? 0.0 : vertexMm(surfaces.size() - 1); }
};

// What a file may hold: thickness and aperture up to 10 m (a camera lens is millimetres long; past
// this the sums along the axis lose their digits), |radius| up to 10 km (a nearly flat surface;
// `inf` is a plane), and this many surface rows (the analysis traces every row for every ray: a
// 1000-row file took minutes).
constexpr double kMaxLensLengthMm = 1e4;
constexpr double kMaxLensRadiusMm = 1e7;
constexpr int kMaxLensSurfaces = 128;

// Reads a prescription from `text` (`source` names it in messages). A bad row is refused with
// one line naming the source, the row (its line) and the column, and what would be valid.
LensPrescription parseLensPrescription(std::string_view text, const std::string& source);

}  // namespace lenslab
