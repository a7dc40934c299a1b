#pragma once
// A small log–log line plot drawn straight into an image (no plotting library on the machine):
// axes with decade ticks and labels, one coloured polyline with markers per series, a legend.
#include "core/Image.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace lenslab {

struct PlotSeries {
  std::string name;
  glm::vec3 color;  // linear
  std::vector<glm::dvec2> points;  // (x, y), both > 0
};

Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, int widthPx = 960, int heightPx = 640);

// Draws `text` (ASCII; letters shown in capitals) with a 5×7 pixel font scaled by `scale`.
void drawText(Image& image, int x, int y, const std::string& text, const glm::vec3& color, int scale = 2);

}  // namespace lenslab
