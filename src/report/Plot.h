#pragma once
// A log–log line plot for the sweep report, drawn with OpenImageIO (lines, boxes, and text in a
// TrueType font: DejaVu Sans from Debian's fonts-dejavu-core): axes with decade ticks and labels,
// one coloured polyline with markers per series, a legend.
#include "core/Image.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace lenslab {

struct PlotSeries {
  std::string name;
  glm::vec3 color;                 // linear
  std::vector<glm::dvec2> points;  // (x, y), both > 0
};

// Throws std::runtime_error when no TrueType font can be found (see plotFontPath).
Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, int widthPx = 960, int heightPx = 640);

// The font the plot writes with: LENSLAB_PLOT_FONT if set, else DejaVu Sans where Debian puts it;
// empty when neither exists.
std::string plotFontPath();

}  // namespace lenslab
