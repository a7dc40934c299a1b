#include "report/Plot.h"

#include "report/LogAxis.h"
#include "report/PlotStyle.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace lenslab {
namespace {

using OIIO::ImageBufAlgo::TextAlignX;

bool placeable(glm::dvec2 p) { return p.x > 0.0 && p.y > 0.0; }

// Signed distance from p to a closed polygon's edges: negative inside, positive outside.
double polygonDistance(const std::vector<glm::dvec2>& polygon, glm::dvec2 p) {
  double distance = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec2 a = polygon[j], b = polygon[i], edge = b - a;
    const double t = std::clamp(glm::dot(p - a, edge) / glm::dot(edge, edge), 0.0, 1.0);
    distance = std::min(distance, glm::length(p - (a + t * edge)));
    // Even-odd rule: a ray from p towards +x crosses this edge.
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * edge.x) inside = !inside;
  }
  return inside ? -distance : distance;
}

// The plot area in pixels (rows from the top) and the axes' ranges it shows.
struct Frame {
  int left = 0, right = 0, top = 0, bottom = 0;
  LogRange x, y;

  glm::ivec2 pixel(glm::dvec2 p) const {
    const double fx = std::log10(p.x / x.lo) / std::log10(x.hi / x.lo);
    const double fy = std::log10(p.y / y.lo) / std::log10(y.hi / y.lo);
    return {static_cast<int>(std::lround(left + fx * (right - left))),
            static_cast<int>(std::lround(bottom - fy * (bottom - top)))};
  }
};

// Axes fitted to every placeable point and to the horizontal line; the right-hand 290 pixels hold
// the legend.
Frame fitFrame(const std::vector<PlotSeries>& series, const std::optional<HorizontalLine>& level, int widthPx,
               int heightPx) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  glm::dvec2 lo(inf), hi(-inf);
  for (const PlotSeries& s : series)
    for (const glm::dvec2& p : s.points)
      if (placeable(p)) lo = glm::min(lo, p), hi = glm::max(hi, p);
  if (level && level->y > 0.0) lo.y = std::min(lo.y, level->y), hi.y = std::max(hi.y, level->y);
  if (lo.x > hi.x) lo.x = 0.01, hi.x = 1.0;  // nothing to place: some range all the same
  if (lo.y > hi.y) lo.y = 0.01, hi.y = 1.0;
  return {110, widthPx - 290, 50, heightPx - 70, fittedLogRange(lo.x, hi.x), fittedLogRange(lo.y, hi.y)};
}

// Drawing on the plot's linear image: OpenImageIO's lines and text, and markers of its own.
class Canvas {
 public:
  Canvas(Image& image, std::string font)
      : image_(image),
        buf_(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT), image.rgba.data()),
        font_(std::move(font)) {}

  void line(glm::ivec2 a, glm::ivec2 b, const glm::vec3& c, int thickness) {
    // OpenImageIO's lines are one pixel wide: offset copies make them thicker.
    for (int k = 0; k < thickness; ++k) {
      const int d = k - thickness / 2;
      const bool steep = std::abs(b.y - a.y) > std::abs(b.x - a.x);
      const glm::ivec2 o = steep ? glm::ivec2(d, 0) : glm::ivec2(0, d);
      OIIO::ImageBufAlgo::render_line(buf_, a.x + o.x, a.y + o.y, b.x + o.x, b.y + o.y, {c.r, c.g, c.b, 1.0f}, true);
    }
  }
  // Dashes of 10 pixels with gaps of 6, from x0 to x1 on row y.
  void dashedLine(int x0, int x1, int y, const glm::vec3& c) {
    for (int x = x0; x <= x1; x += 16) line({x, y}, {std::min(x + 9, x1), y}, c, 2);
  }
  void text(int x, int y, const std::string& words, int size, TextAlignX alignX = TextAlignX::Left) {
    OIIO::ImageBufAlgo::render_text(buf_, x, y, words, size, font_, {0.0f, 0.0f, 0.0f, 1.0f}, alignX,
                                    OIIO::ImageBufAlgo::TextAlignY::Center);
  }
  // A marker centred on pixel q, 16 samples a pixel for its coverage; a hollow one is an outline
  // with a white inside.
  void marker(glm::ivec2 q, MarkerShape shape, const glm::vec3& c, bool hollow) {
    const std::vector<glm::dvec2> polygon = markerPolygon(shape);
    const double radius = 6.0, stroke = 1.5;  // pixels
    const glm::dvec2 centre = glm::dvec2(q) + 0.5;
    const int reach = static_cast<int>(std::ceil(1.5 * radius));
    for (int y = q.y - reach; y <= q.y + reach; ++y)
      for (int x = q.x - reach; x <= q.x + reach; ++x) {
        if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) continue;
        int inside = 0, outline = 0;
        for (int s = 0; s < 16; ++s) {
          const glm::dvec2 offset = glm::dvec2(x + (s % 4 + 0.5) / 4.0, y + (s / 4 + 0.5) / 4.0) - centre;
          const double d = radius * polygonDistance(polygon, glm::dvec2(offset.x, -offset.y) / radius);
          if (d <= 0.0) ++inside, outline += d >= -stroke;
        }
        if (hollow) blend(x, y, glm::vec3(1.0f), static_cast<float>(inside) / 16.0f);
        blend(x, y, c, static_cast<float>(hollow ? outline : inside) / 16.0f);
      }
  }
  void throwOnError() const {
    if (buf_.has_error()) throw std::runtime_error("plot: " + buf_.geterror());
  }

 private:
  void blend(int x, int y, const glm::vec3& c, float coverage) {
    const glm::vec4 under = image_.at(x, y);
    image_.set(x, y, glm::vec4(glm::mix(glm::vec3(under), c, coverage), 1.0f));
  }

  Image& image_;
  OIIO::ImageBuf buf_;
  std::string font_;
};

void drawAxes(Canvas& canvas, const Frame& f, const std::string& xLabel, const std::string& yLabel,
              const std::string& title, glm::ivec2 sizePx) {
  const glm::vec3 grey(0.75f), black(0.0f);
  for (const AxisTick& tick : logTicks(f.x)) {
    const int px = f.pixel({tick.value, f.y.lo}).x;
    canvas.line({px, f.top}, {px, f.bottom}, grey, 1);
    canvas.text(px, f.bottom + 18, tick.label, 18, TextAlignX::Center);
  }
  for (const AxisTick& tick : logTicks(f.y)) {
    const int py = f.pixel({f.x.lo, tick.value}).y;
    canvas.line({f.left, py}, {f.right, py}, grey, 1);
    canvas.text(f.left - 10, py, tick.label, 18, TextAlignX::Right);
  }
  canvas.line({f.left, f.top}, {f.right, f.top}, black, 1);
  canvas.line({f.right, f.top}, {f.right, f.bottom}, black, 1);
  canvas.line({f.left, f.bottom}, {f.right, f.bottom}, black, 2);
  canvas.line({f.left, f.top}, {f.left, f.bottom}, black, 2);
  canvas.text((f.left + f.right) / 2, sizePx.y - 25, xLabel, 20, TextAlignX::Center);
  canvas.text(10, 22, yLabel, 20);
  canvas.text((f.left + f.right) / 2, 22, title, 22, TextAlignX::Center);
}

// The line through the points pointsOnTheLine keeps, filled markers on them, hollow markers on the
// others. Returns whether any point was left off the line.
bool drawSeries(Canvas& canvas, const Frame& f, const PlotSeries& s, const SeriesStyle& style) {
  const std::vector<bool> onLine = pointsOnTheLine(s.points);
  std::optional<glm::ivec2> previous;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (!onLine[i]) continue;
    const glm::ivec2 q = f.pixel(s.points[i]);
    if (previous) canvas.line(*previous, q, style.colour, 2);
    previous = q;
  }
  bool leftOff = false;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (!placeable(s.points[i])) continue;
    canvas.marker(f.pixel(s.points[i]), style.marker, style.colour, !onLine[i]);
    leftOff = leftOff || !onLine[i];
  }
  return leftOff;
}

}  // namespace

std::vector<bool> pointsOnTheLine(const std::vector<glm::dvec2>& points) {
  std::vector<bool> onLine(points.size(), false);
  double fastestLater = std::numeric_limits<double>::infinity();
  for (std::size_t i = points.size(); i-- > 0;) {
    if (!placeable(points[i])) continue;
    onLine[i] = points[i].x <= fastestLater;
    fastestLater = std::min(fastestLater, points[i].x);
  }
  return onLine;
}

std::string plotFontPath() {
  if (const char* env = std::getenv("LENSLAB_PLOT_FONT"); env && *env) return env;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
    if (std::filesystem::exists(path)) return path;
  return {};
}

Image logLogPlot(const std::vector<PlotSeries>& series, const std::string& xLabel, const std::string& yLabel,
                 const std::string& title, const std::optional<HorizontalLine>& level, int widthPx, int heightPx) {
  std::string font = plotFontPath();
  if (font.empty())
    throw std::runtime_error("no font for the plot: install fonts-dejavu-core or set LENSLAB_PLOT_FONT to a .ttf file");
  Image image(widthPx, heightPx);
  std::fill(image.rgba.begin(), image.rgba.end(), 1.0f);
  Canvas canvas(image, std::move(font));
  const Frame f = fitFrame(series, level, widthPx, heightPx);
  drawAxes(canvas, f, xLabel, yLabel, title, {widthPx, heightPx});
  const bool drawLevel = level && level->y > 0.0;
  if (drawLevel) canvas.dashedLine(f.left, f.right, f.pixel({f.x.lo, level->y}).y, referenceLineColour());

  // The legend, right of the plot: each series' line and marker, the reference line, and what a
  // hollow marker means when the plot has one.
  const int sampleLeft = f.right + 16, sampleRight = f.right + 56, textLeft = f.right + 64;
  int legendY = f.top + 8;
  bool anyLeftOff = false;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const SeriesStyle style = seriesStyle(static_cast<int>(i));
    anyLeftOff = drawSeries(canvas, f, series[i], style) || anyLeftOff;
    canvas.line({sampleLeft, legendY}, {sampleRight, legendY}, style.colour, 2);
    canvas.marker({(sampleLeft + sampleRight) / 2, legendY}, style.marker, style.colour, false);
    canvas.text(textLeft, legendY, series[i].name, 18);
    legendY += 26;
  }
  if (drawLevel) {
    canvas.dashedLine(sampleLeft, sampleRight, legendY, referenceLineColour());
    canvas.text(textLeft, legendY, level->label, 18);
    legendY += 26;
  }
  if (anyLeftOff) {
    canvas.marker({(sampleLeft + sampleRight) / 2, legendY}, MarkerShape::Circle, referenceLineColour(), true);
    canvas.text(textLeft, legendY, "slower than a larger run", 16);
  }
  canvas.throwOnError();
  return image;
}

}  // namespace lenslab
