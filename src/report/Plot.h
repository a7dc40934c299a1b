#pragma once
// A log–log line plot for the sweep report, drawn with OpenImageIO (lines, boxes, and text in a
// TrueType font: DejaVu Sans from Debian's fonts-dejavu-core): axes fitted to the data with their
// ticks (report/LogAxis.h), one polyline with markers per series, each in its own colour and
// marker shape (report/PlotStyle.h), an optional dashed horizontal reference line, a legend.
#include "core/Image.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct PlotSeries {
  std::string name;
  // (x, y) in the series' own order (the sweep's: growing sample count); a point with x or y
  // not above 0 cannot be placed on log axes and is left out.
  std::vector<glm::dvec2> points;
};

// A horizontal dashed line across the plot at y (> 0), named in the legend: a level the series
// are read against, such as the reference's own noise.
struct HorizontalLine {
  double y = 0.0;
  std::string label;
};

// Series i is drawn in seriesStyle(i). Its line joins only the points pointsOnTheLine keeps; the
// others are drawn as hollow markers, and the legend says so. The axes span the points and the
// line. Throws std::runtime_error when no TrueType font can be found (see plotFontPath).
Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, const std::optional<HorizontalLine>& level = std::nullopt, int widthPx = 960,
                 int heightPx = 640);

// Which points of a series its line joins, so that the line never runs back along x: a point is
// left off when a later point of the series has a smaller x. In the sweep x is seconds, and a
// shared machine can only add time to a run (other work preempts it; nothing makes it faster), so
// of two runs timed out of order it is the earlier, smaller budget's time that is inflated: the
// later, faster timing is kept on the line and the inflated one is drawn apart. Points that cannot
// be placed (x or y not above 0) are false too.
std::vector<bool> pointsOnTheLine(const std::vector<glm::dvec2>& points);

// The font the plot writes with: LENSLAB_PLOT_FONT if set, else DejaVu Sans where Debian puts it;
// empty when neither exists.
std::string plotFontPath();

}  // namespace lenslab
