#pragma once
// The shape of the aperture: what an out-of-focus highlight looks like. The lecture's thin lens has
// a round aperture; a real lens stops down with an iris of N straight (or curved) blades, which
// makes the aperture a polygon, and an anamorphic lens squeezes it into an oval.
//
// The samples stay where the aperture patterns put them (lens/AperturePattern.h: points on the
// unit disk, stratified); apertureFromDisk carries each to the shape by one area-preserving map,
// continuous inside each blade's sector, so equal areas of the disk stay equal areas of the shape
// and strata stay compact. Both renderers take their aperture points through it (Lens::lensOffset),
// so they converge to the same image.
//
// Lens coordinates are the view's u (image right) and v (image up). A point beyond the plane of
// focus is blurred into the aperture's shape as it is; a point nearer than it, into the shape
// turned by 180 degrees (its rays cross before the plane of focus).
//
// The shape has the area of the round aperture it replaces (π·R² for the aperture radius R): the
// f-number keeps saying how much light comes through, and only the blur's outline changes.
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct ApertureShape {
  int blades = 0;                  // 0: a circle; else 3 … kMaxBlades, a regular polygon
  double rotationDeg = 0.0;        // the polygon turned anticlockwise from a vertex straight up (image x right, y up)
  double roundness = 0.0;          // 0: straight blades (a polygon) … 1: a circle
  double anamorphicSqueeze = 1.0;  // > 0: the shape taller than wide by this ratio (2: a 2x anamorphic lens's ovals)

  static constexpr int kMaxBlades = 64;

  // A circle: the map is the identity and nothing else changes.
  bool isRound() const { return (blades == 0 || roundness >= 1.0) && anamorphicSqueeze == 1.0; }
  bool operator==(const ApertureShape&) const = default;
};

// What is wrong with a shape: the field (as a camera file names it: "blades", "rotation_deg",
// "roundness", "anamorphic_squeeze") and the rest of the sentence ("is 2; give 0 (a circle) or 3
// to 64 blades").
struct ApertureProblem {
  std::string field;
  std::string message;
};
std::optional<ApertureProblem> apertureShapeProblem(const ApertureShape& shape);

// The aperture point, in units of the aperture radius, for a point of the unit disk.
// Inside the sector of one blade (half-angle α = π/N about the blade's normal), the disk's polar
// angle is remapped so that equal angles of the disk become equal areas of the sector, and the
// radius is scaled by the sector's boundary R(θ): area ½·R(θ)²·dθ·r² pairs with ½·dφ·r², so
// uniform on the disk is uniform on the shape. R(θ) blends the straight blade, cos α / cos θ, with
// the circle by the roundness; the whole is scaled to the disk's area, then squeezed.
glm::dvec2 apertureFromDisk(glm::dvec2 unitDisk, const ApertureShape& shape);

// Its inverse: the point of the unit disk that apertureFromDisk carries to `aperture` (units of the
// aperture radius). Closed form: unsqueezed, the polar angle in its blade's sector gives that
// sector's area up to it, which is the disk's angle; the radius over the boundary R(θ) is the
// disk's radius. The cell filter asks it where a point of the shape lies in the disk's cells.
glm::dvec2 diskFromAperture(glm::dvec2 aperture, const ApertureShape& shape);

// The numbers that define both maps, for a shader that undoes the map (accumulate/cell_filter.frag):
// the sector boundary R(θ) = straight / cos θ + round, θ from the blade's normal within ±halfAngle;
// blade k's normal at firstNormal + 2·halfAngle·k; the polygon scaled by `scale` to the disk's
// area; then x divided and y multiplied by squeezeRoot. blades 0: a circle (only the squeeze).
// twiceArea: ∫₀^halfAngle R² dθ, twice the area of half a sector.
struct ApertureSectors {
  int blades = 0;
  double firstNormalRad = 0.0, halfAngleRad = 0.0, straight = 0.0, round = 1.0, scale = 1.0, squeezeRoot = 1.0;
  double twiceArea = 1.0;
};
ApertureSectors apertureSectors(const ApertureShape& shape);

// The largest distance from the centre of any aperture point, in units of the aperture radius
// (1 for a circle): how far the circle of confusion of a shaped aperture reaches.
double apertureReach(const ApertureShape& shape);

// The shape's outline, anticlockwise, `pointsPerSide` points per blade (a circle: that many in all),
// in units of the aperture radius: for tests and drawings.
std::vector<glm::dvec2> apertureOutline(const ApertureShape& shape, int pointsPerSide);

// Where the blades meet (the polygon's vertices; on a rounded shape, the corners between the
// arcs), in units of the aperture radius; empty for a circle.
std::vector<glm::dvec2> apertureVertices(const ApertureShape& shape);

// One line for messages and --stats: "circle", "6 blades, rotated 15 deg, roundness 0.3, squeeze 2".
std::string describeAperture(const ApertureShape& shape);

}  // namespace lenslab
