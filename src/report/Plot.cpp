#include "report/Plot.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace lenslab {
namespace {

std::string decadeLabel(int exponent) {
  std::ostringstream s;
  if (exponent >= -2 && exponent <= 3)
    s << std::pow(10.0, exponent);
  else
    s << "1e" << exponent;
  return s.str();
}

// OpenImageIO draws in the image's own values: colours are linear, as the image is.
std::vector<float> rgba(const glm::vec3& c) { return {c.r, c.g, c.b, 1.0f}; }

}  // namespace

std::string plotFontPath() {
  if (const char* env = std::getenv("LENSLAB_PLOT_FONT"); env && *env) return env;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
    if (std::filesystem::exists(path)) return path;
  return {};
}

Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, int widthPx, int heightPx) {
  const std::string font = plotFontPath();
  if (font.empty())
    throw std::runtime_error("no font for the plot: install fonts-dejavu-core or set LENSLAB_PLOT_FONT to a .ttf file");
  Image image(widthPx, heightPx);
  OIIO::ImageBuf canvas(OIIO::ImageSpec(widthPx, heightPx, 4, OIIO::TypeDesc::FLOAT), image.rgba.data());
  OIIO::ImageBufAlgo::fill(canvas, {1.0f, 1.0f, 1.0f, 1.0f});

  double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
  for (const PlotSeries& s : series)
    for (const glm::dvec2& p : s.points)
      if (p.x > 0 && p.y > 0) {
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
      }
  if (minX > maxX) minX = 1e-3, maxX = 1, minY = 1e-3, maxY = 1;
  const int x0 = static_cast<int>(std::floor(std::log10(minX))), x1 = static_cast<int>(std::ceil(std::log10(maxX)));
  const int y0 = static_cast<int>(std::floor(std::log10(minY))), y1 = static_cast<int>(std::ceil(std::log10(maxY)));
  const int left = 110, right = widthPx - 290, top = 50, bottom = heightPx - 70;
  auto toPixel = [&](glm::dvec2 p) {
    const double fx = (std::log10(p.x) - x0) / std::max(1, x1 - x0);
    const double fy = (std::log10(p.y) - y0) / std::max(1, y1 - y0);
    return glm::ivec2(static_cast<int>(std::lround(left + fx * (right - left))),
                      static_cast<int>(std::lround(bottom - fy * (bottom - top))));
  };
  const auto line = [&](glm::ivec2 a, glm::ivec2 b, const glm::vec3& c, int thickness) {
    // OpenImageIO's lines are one pixel wide: offset copies make them thicker.
    for (int k = 0; k < thickness; ++k) {
      const int d = k - thickness / 2;
      const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
      const glm::ivec2 o = steep ? glm::ivec2(d, 0) : glm::ivec2(0, d);
      OIIO::ImageBufAlgo::render_line(canvas, a.x + o.x, a.y + o.y, b.x + o.x, b.y + o.y, rgba(c), true);
    }
  };
  const auto text = [&](int x, int y, const std::string& words, int size,
                        OIIO::ImageBufAlgo::TextAlignX alignX = OIIO::ImageBufAlgo::TextAlignX::Left) {
    OIIO::ImageBufAlgo::render_text(canvas, x, y, words, size, font, {0.0f, 0.0f, 0.0f, 1.0f}, alignX,
                                    OIIO::ImageBufAlgo::TextAlignY::Center);
  };
  const glm::vec3 grey(0.75f), black(0.0f);
  for (int e = x0; e <= x1; ++e) {
    const int px = toPixel({std::pow(10.0, e), std::pow(10.0, y0)}).x;
    line({px, top}, {px, bottom}, grey, 1);
    text(px, bottom + 18, decadeLabel(e), 18, OIIO::ImageBufAlgo::TextAlignX::Center);
  }
  for (int e = y0; e <= y1; ++e) {
    const int py = toPixel({std::pow(10.0, x0), std::pow(10.0, e)}).y;
    line({left, py}, {right, py}, grey, 1);
    text(left - 10, py, decadeLabel(e), 18, OIIO::ImageBufAlgo::TextAlignX::Right);
  }
  line({left, bottom}, {right, bottom}, black, 2);
  line({left, top}, {left, bottom}, black, 2);
  text((left + right) / 2, heightPx - 25, xLabel, 20, OIIO::ImageBufAlgo::TextAlignX::Center);
  text(10, 22, yLabel, 20);
  text((left + right) / 2, 22, title, 22, OIIO::ImageBufAlgo::TextAlignX::Center);
  int legendY = top + 8;
  for (const PlotSeries& s : series) {
    glm::ivec2 previous(-1);
    for (const glm::dvec2& p : s.points) {
      if (!(p.x > 0 && p.y > 0)) continue;
      const glm::ivec2 q = toPixel(p);
      if (previous.x >= 0) line(previous, q, s.color, 3);
      OIIO::ImageBufAlgo::render_box(canvas, q.x - 3, q.y - 3, q.x + 3, q.y + 3, rgba(s.color), true);
      previous = q;
    }
    line({right + 20, legendY}, {right + 50, legendY}, s.color, 4);
    text(right + 58, legendY, s.name, 18);
    legendY += 26;
  }
  if (canvas.has_error()) throw std::runtime_error("plot: " + canvas.geterror());
  return image;
}

}  // namespace lenslab
