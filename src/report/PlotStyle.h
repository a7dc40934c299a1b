#pragma once
// How the plot tells its series apart: a colour and a marker shape each. The colours are Paul
// Tol's "muted" qualitative scheme (personal.sron.nl/~pault), nine colours chosen to stay distinct
// for colour-blind readers, ordered here so that the first few are the furthest apart (CIELAB):
// indigo, olive, cyan, rose, green, purple, teal, wine, sand. The scheme is given in sRGB; the plot
// is a linear image that the PNG writer encodes to sRGB (io/ImageFile.h), so the colours are
// decoded to linear here and come out in the file as Tol gives them.
#include <glm/glm.hpp>

#include <vector>

namespace lenslab {

enum class MarkerShape { Circle, Square, TriangleUp, Diamond, TriangleDown, Plus, Cross, Star, TriangleRight };
inline constexpr int kPlotColours = 9;
inline constexpr int kMarkerShapes = 9;

struct SeriesStyle {
  glm::vec3 colour;  // linear
  MarkerShape marker;
};

// The style of a plot's series number `index` (0, 1, ...): nine colours and nine shapes, so the
// first nine differ in both; past nine the colours repeat, each time with the shapes shifted by
// one, so no two of the first 81 series look alike.
SeriesStyle seriesStyle(int index);

// The dashed reference line's colour (linear): a neutral grey, apart from every series colour.
glm::vec3 referenceLineColour();

// A marker's outline as a polygon (counter-clockwise, y up) around the origin, about one unit in
// radius; the circle is a 24-gon.
std::vector<glm::dvec2> markerPolygon(MarkerShape shape);

}  // namespace lenslab
