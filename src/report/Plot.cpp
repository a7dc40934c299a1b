#include "report/Plot.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>

namespace lenslab {
namespace {

// 5×7 glyphs, one row per entry, the leftmost pixel in bit 4.
const std::map<char, std::array<std::uint8_t, 7>>& font() {
  static const std::map<char, std::array<std::uint8_t, 7>> glyphs = {
      {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},   {'2', {14, 17, 1, 2, 4, 8, 31}},
      {'3', {31, 2, 4, 2, 1, 17, 14}},     {'4', {2, 6, 10, 18, 31, 2, 2}},  {'5', {31, 16, 30, 1, 1, 17, 14}},
      {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},    {'8', {14, 17, 17, 14, 17, 17, 14}},
      {'9', {14, 17, 17, 15, 1, 2, 12}},   {'A', {14, 17, 17, 31, 17, 17, 17}}, {'B', {30, 17, 17, 30, 17, 17, 30}},
      {'C', {14, 17, 16, 16, 16, 17, 14}}, {'D', {28, 18, 17, 17, 17, 18, 28}}, {'E', {31, 16, 16, 30, 16, 16, 31}},
      {'F', {31, 16, 16, 30, 16, 16, 16}}, {'G', {14, 17, 16, 23, 17, 17, 15}}, {'H', {17, 17, 17, 31, 17, 17, 17}},
      {'I', {14, 4, 4, 4, 4, 4, 14}},      {'J', {7, 2, 2, 2, 2, 18, 12}},   {'K', {17, 18, 20, 24, 20, 18, 17}},
      {'L', {16, 16, 16, 16, 16, 16, 31}}, {'M', {17, 27, 21, 21, 17, 17, 17}}, {'N', {17, 17, 25, 21, 19, 17, 17}},
      {'O', {14, 17, 17, 17, 17, 17, 14}}, {'P', {30, 17, 17, 30, 16, 16, 16}}, {'Q', {14, 17, 17, 17, 21, 18, 13}},
      {'R', {30, 17, 17, 30, 20, 18, 17}}, {'S', {15, 16, 16, 14, 1, 1, 30}}, {'T', {31, 4, 4, 4, 4, 4, 4}},
      {'U', {17, 17, 17, 17, 17, 17, 14}}, {'V', {17, 17, 17, 17, 17, 10, 4}}, {'W', {17, 17, 17, 21, 21, 21, 10}},
      {'X', {17, 17, 10, 4, 10, 17, 17}},  {'Y', {17, 17, 17, 10, 4, 4, 4}},  {'Z', {31, 1, 2, 4, 8, 16, 31}},
      {'.', {0, 0, 0, 0, 0, 12, 12}},      {'-', {0, 0, 0, 31, 0, 0, 0}},    {'+', {0, 4, 4, 31, 4, 4, 0}},
      {'(', {2, 4, 8, 8, 8, 4, 2}},        {')', {8, 4, 2, 2, 2, 4, 8}},     {'/', {1, 1, 2, 4, 8, 16, 16}},
      {'=', {0, 0, 31, 0, 31, 0, 0}},      {':', {0, 12, 12, 0, 12, 12, 0}}, {',', {0, 0, 0, 0, 12, 4, 8}},
      {'^', {4, 10, 17, 0, 0, 0, 0}},      {'x', {0, 17, 10, 4, 10, 17, 0}}, {' ', {0, 0, 0, 0, 0, 0, 0}},
  };
  return glyphs;
}

void setPixel(Image& image, int x, int y, const glm::vec3& c) {
  if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.set(x, y, glm::vec4(c, 1.0f));
}

void line(Image& image, glm::dvec2 a, glm::dvec2 b, const glm::vec3& c, int thickness) {
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)))) + 1;
  for (int i = 0; i <= steps; ++i) {
    const glm::dvec2 p = a + (b - a) * (static_cast<double>(i) / steps);
    for (int dy = -thickness / 2; dy <= thickness / 2; ++dy)
      for (int dx = -thickness / 2; dx <= thickness / 2; ++dx)
        setPixel(image, static_cast<int>(std::lround(p.x)) + dx, static_cast<int>(std::lround(p.y)) + dy, c);
  }
}

std::string decadeLabel(int exponent) {
  std::ostringstream s;
  if (exponent >= -2 && exponent <= 3) s << std::pow(10.0, exponent);
  else s << "1E" << exponent;
  return s.str();
}

}  // namespace

void drawText(Image& image, int x, int y, const std::string& text, const glm::vec3& color, int scale) {
  int cx = x;
  for (char ch : text) {
    char key = ch == 'x' ? 'x' : static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    auto it = font().find(key);
    if (it == font().end()) it = font().find(' ');
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (it->second[static_cast<std::size_t>(row)] & (1 << (4 - col)))
          for (int sy = 0; sy < scale; ++sy)
            for (int sx = 0; sx < scale; ++sx) setPixel(image, cx + col * scale + sx, y + row * scale + sy, color);
    cx += 6 * scale;
  }
}

Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, int widthPx, int heightPx) {
  Image image(widthPx, heightPx);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = 1.0f;
    image.rgba[i + 3] = 1.0f;
  }
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
    return glm::dvec2(left + fx * (right - left), bottom - fy * (bottom - top));
  };
  const glm::vec3 grey(0.75f), black(0.0f);
  for (int e = x0; e <= x1; ++e) {
    const double px = toPixel({std::pow(10.0, e), std::pow(10.0, y0)}).x;
    line(image, {px, static_cast<double>(top)}, {px, static_cast<double>(bottom)}, grey, 1);
    drawText(image, static_cast<int>(px) - 12, bottom + 10, decadeLabel(e), black);
  }
  for (int e = y0; e <= y1; ++e) {
    const double py = toPixel({std::pow(10.0, x0), std::pow(10.0, e)}).y;
    line(image, {static_cast<double>(left), py}, {static_cast<double>(right), py}, grey, 1);
    drawText(image, 10, static_cast<int>(py) - 7, decadeLabel(e), black);
  }
  line(image, {static_cast<double>(left), static_cast<double>(bottom)}, {static_cast<double>(right), static_cast<double>(bottom)}, black, 2);
  line(image, {static_cast<double>(left), static_cast<double>(top)}, {static_cast<double>(left), static_cast<double>(bottom)}, black, 2);
  drawText(image, (left + right) / 2 - static_cast<int>(xLabel.size()) * 6, heightPx - 35, xLabel, black);
  drawText(image, 10, 20, yLabel, black);
  drawText(image, left + 150, 15, title, black);
  int legendY = top;
  for (const PlotSeries& s : series) {
    glm::dvec2 previous(-1.0);
    for (const glm::dvec2& p : s.points) {
      if (!(p.x > 0 && p.y > 0)) continue;
      const glm::dvec2 q = toPixel(p);
      if (previous.x >= 0) line(image, previous, q, s.color, 3);
      line(image, q - glm::dvec2(3, 0), q + glm::dvec2(3, 0), s.color, 5);
      previous = q;
    }
    line(image, {static_cast<double>(right + 20), legendY + 7.0}, {static_cast<double>(right + 50), legendY + 7.0}, s.color, 4);
    drawText(image, right + 58, legendY, s.name, black);
    legendY += 24;
  }
  return image;
}

}  // namespace lenslab
