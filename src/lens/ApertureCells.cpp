#include "lens/ApertureCells.h"

#include "lens/SobolSequence.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace lenslab {
namespace {

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Cells in ring i: the rounded share (2i + 1)/k² of `count`, taken cumulatively so they add up.
std::vector<int> cellsPerRing(int count) {
  const int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(count / 4.0))));
  std::vector<int> perRing;
  int before = 0;
  for (int i = 0; i < rings; ++i) {
    const double share = static_cast<double>((i + 1) * (i + 1)) / (rings * rings);
    const int upTo = i + 1 == rings ? count : static_cast<int>(std::lround(count * share));
    if (upTo > before) perRing.push_back(upTo - before);
    before = std::max(before, upTo);
  }
  return perRing;
}

}  // namespace

bool ApertureCell::contains(glm::dvec2 p) const {
  if (square) {
    const glm::dvec2 u = concentricSquare(p);
    return glm::length(p) <= 1.0 && u.x >= squareMin.x && u.x < squareMax.x && u.y >= squareMin.y && u.y < squareMax.y;
  }
  const double r2 = glm::dot(p, p);
  if (r2 < innerRadius * innerRadius || r2 >= outerRadius * outerRadius) return false;
  if (sweepAngle >= 2.0 * std::numbers::pi) return true;
  const glm::dvec2 first(std::cos(startAngle), std::sin(startAngle));
  const glm::dvec2 last(std::cos(startAngle + sweepAngle), std::sin(startAngle + sweepAngle));
  // A sector of at most half a turn: anticlockwise of its first edge, clockwise of its last.
  return cross(first, p) >= 0.0 && cross(p, last) > 0.0;
}

std::vector<glm::dvec2> ApertureCell::outline(int perSide, const ApertureShape& shape) const {
  std::vector<glm::dvec2> points;
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < perSide; ++i) {
      const double t = static_cast<double>(i) / perSide;
      // The four sides anticlockwise, as fractions (s, t) of the cell's two coordinates.
      const glm::dvec2 st = side == 0   ? glm::dvec2(t, 0.0)
                            : side == 1 ? glm::dvec2(1.0, t)
                            : side == 2 ? glm::dvec2(1.0 - t, 1.0)
                                        : glm::dvec2(0.0, 1.0 - t);
      if (square) {
        points.push_back(apertureFromDisk(concentricDisk(squareMin + st * (squareMax - squareMin)), shape));
      } else {
        const double angle = startAngle + st.x * sweepAngle;
        const double radius = innerRadius + st.y * (outerRadius - innerRadius);
        points.push_back(apertureFromDisk(radius * glm::dvec2(std::cos(angle), std::sin(angle)), shape));
      }
    }
  return points;
}

ApertureCell::Rectangle ApertureCell::momentRectangle(const ApertureShape& shape) const {
  // The outline as a polygon: its area, centroid and second moments (Green's theorem), then the
  // rectangle along the covariance's eigenvectors with the same variances (h²/3 per half-length
  // h), scaled to the cell's exact area. (On a shaped aperture the outline's sides are curves,
  // and cross the seams between blades: 32 points a side follow them.)
  const std::vector<glm::dvec2> polygon = outline(32, shape);
  double a = 0.0;
  glm::dvec2 first(0.0);
  double xx = 0.0, xy = 0.0, yy = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    const double w = p.x * q.y - q.x * p.y;
    a += w;
    first += w * (p + q);
    xx += w * (p.x * p.x + p.x * q.x + q.x * q.x);
    yy += w * (p.y * p.y + p.y * q.y + q.y * q.y);
    xy += w * (p.x * q.y + 2.0 * p.x * p.y + 2.0 * q.x * q.y + q.x * p.y);
  }
  a *= 0.5;
  Rectangle r;
  if (std::abs(a) < 1e-300) return r;
  r.centre = first / (6.0 * a);
  const double cxx = xx / (12.0 * a) - r.centre.x * r.centre.x, cyy = yy / (12.0 * a) - r.centre.y * r.centre.y;
  const double cxy = xy / (24.0 * a) - r.centre.x * r.centre.y;
  // Eigen-decomposition of [[cxx, cxy], [cxy, cyy]].
  const double mean = 0.5 * (cxx + cyy), spread = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
  const double l0 = std::max(mean + spread, 0.0), l1 = std::max(mean - spread, 0.0);
  const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  const glm::dvec2 e0(std::cos(angle), std::sin(angle)), e1(-e0.y, e0.x);
  double h0 = std::sqrt(3.0 * l0), h1 = std::sqrt(3.0 * l1);
  const double scale = h0 * h1 > 0.0 ? std::sqrt(area() / (4.0 * h0 * h1)) : 1.0;
  r.axis0 = scale * h0 * e0;
  r.axis1 = scale * h1 * e1;
  return r;
}

bool hasCells(AperturePattern pattern, int count) {
  return pattern == AperturePattern::Rings ||
         (pattern == AperturePattern::Sobol && count >= 1 && (count & (count - 1)) == 0);
}

namespace {

// The pattern's own N points (AperturePattern's Sobol), each with its elementary box: 2^a columns
// by 2^b rows of the concentric square, a the larger half of log2 N.
CellSamples sobolCells(int count, std::uint32_t seed) {
  int bits = 0;
  while ((1 << bits) < count) ++bits;
  const int columns = 1 << ((bits + 1) / 2), rows = 1 << (bits / 2);
  CellSamples out;
  out.samples = makeApertureSamples(AperturePattern::Sobol, count, seed);
  for (const LensSample& s : out.samples) {
    const glm::dvec2 u = concentricSquare(s.lens);
    const glm::dvec2 cell = glm::floor(glm::clamp(u, 0.0, 1.0 - 1e-12) * glm::dvec2(columns, rows));
    ApertureCell c;
    c.square = true;
    c.squareMin = cell / glm::dvec2(columns, rows);
    c.squareMax = (cell + 1.0) / glm::dvec2(columns, rows);
    out.cells.push_back(c);
  }
  return out;
}

CellSamples ringCells(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ApertureCell> cells;
  const std::vector<int> perRing = cellsPerRing(count);
  int inside = 0;
  for (int n : perRing) {
    const double inner = std::sqrt(static_cast<double>(inside) / count);
    inside += n;
    const double outer = std::sqrt(static_cast<double>(inside) / count);
    // Each ring turned by its own random offset, so that sector edges do not line up across rings.
    const double sweep = 2.0 * std::numbers::pi / n;
    const double turn = sweep * unit(rng);
    for (int j = 0; j < n; ++j) cells.push_back({inner, outer, turn + j * sweep, sweep});
  }
  // In a random order, so that the views of a progressive frame do not fill the rings one by one.
  std::shuffle(cells.begin(), cells.end(), rng);
  CellSamples out;
  const std::uint32_t scramble = sobolStreamSeed(seed, 0);
  for (int i = 0; i < count; ++i) {
    const ApertureCell& c = cells[static_cast<std::size_t>(i)];
    // Uniform in area within the cell: r² uniform between the radii, the angle uniform.
    const double r = std::sqrt(c.innerRadius * c.innerRadius +
                               unit(rng) * (c.outerRadius * c.outerRadius - c.innerRadius * c.innerRadius));
    const double angle = c.startAngle + unit(rng) * c.sweepAngle;
    const LensSample pixelSample = sobolPoint(static_cast<std::uint32_t>(i), scramble);
    out.samples.push_back({r * glm::dvec2(std::cos(angle), std::sin(angle)), pixelSample.pixel});
  }
  out.cells = std::move(cells);
  return out;
}

}  // namespace

CellSamples makeCellSamples(AperturePattern pattern, int count, std::uint32_t seed) {
  if (!hasCells(pattern, count)) throw std::logic_error("makeCellSamples: the pattern has no cells for this count");
  return pattern == AperturePattern::Sobol ? sobolCells(count, seed) : ringCells(std::max(count, 1), seed);
}

}  // namespace lenslab
