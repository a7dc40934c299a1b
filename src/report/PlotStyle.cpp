#include "report/PlotStyle.h"

#include "io/ImageFile.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace lenslab {
namespace {

glm::vec3 linearFromSrgbHex(unsigned hex) {
  const auto channel = [&](int shift) { return linearFromSrgb(static_cast<float>((hex >> shift) & 0xFF) / 255.0f); };
  return {channel(16), channel(8), channel(0)};
}

// n points on a circle of `radius`, the first at `startDegrees` (0 = +x), counter-clockwise.
std::vector<glm::dvec2> regular(int n, double radius, double startDegrees) {
  std::vector<glm::dvec2> v;
  for (int i = 0; i < n; ++i) {
    const double a = glm::radians(startDegrees + 360.0 * i / n);
    v.push_back(radius * glm::dvec2(std::cos(a), std::sin(a)));
  }
  return v;
}

// The plus sign: arms reaching 1.2 from the centre, 0.45 each side of their centre line (wide
// enough for a hollow one to show its inside).
std::vector<glm::dvec2> plus() {
  const double w = 0.45, l = 1.2;
  return {{w, -l}, {w, -w}, {l, -w}, {l, w}, {w, w}, {w, l}, {-w, l}, {-w, w}, {-l, w}, {-l, -w}, {-w, -w}, {-w, -l}};
}

}  // namespace

SeriesStyle seriesStyle(int index) {
  assert(index >= 0);
  static const std::array<unsigned, kPlotColours> tolMuted = {0x332288, 0x999933, 0x88CCEE, 0xCC6677, 0x117733,
                                                              0xAA4499, 0x44AA99, 0x882255, 0xDDCC77};
  const int round = index / kPlotColours;
  return {linearFromSrgbHex(tolMuted[index % kPlotColours]), static_cast<MarkerShape>((index + round) % kMarkerShapes)};
}

glm::vec3 referenceLineColour() { return linearFromSrgbHex(0x555555); }

std::vector<glm::dvec2> markerPolygon(MarkerShape shape) {
  switch (shape) {
    case MarkerShape::Circle: return regular(24, 1.0, 0.0);
    case MarkerShape::Square: return regular(4, 1.2, 45.0);
    case MarkerShape::TriangleUp: return regular(3, 1.3, 90.0);
    case MarkerShape::Diamond: return {{0.0, -1.3}, {0.9, 0.0}, {0.0, 1.3}, {-0.9, 0.0}};
    case MarkerShape::TriangleDown: return regular(3, 1.3, -90.0);
    case MarkerShape::Plus: return plus();
    case MarkerShape::Cross: {
      std::vector<glm::dvec2> v = plus();
      const double c = std::sqrt(0.5);
      for (glm::dvec2& p : v) p = {c * (p.x - p.y), c * (p.x + p.y)};
      return v;
    }
    case MarkerShape::Star: {
      std::vector<glm::dvec2> v;
      for (int i = 0; i < 10; ++i) {
        const double a = glm::radians(90.0 + 36.0 * i), r = i % 2 == 0 ? 1.35 : 0.55;
        v.push_back(r * glm::dvec2(std::cos(a), std::sin(a)));
      }
      return v;
    }
    case MarkerShape::TriangleRight: return regular(3, 1.3, 0.0);
  }
  return {};
}

}  // namespace lenslab
