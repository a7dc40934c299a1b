// The sweep's error-against-run-time plot (report/Plot.h, LogAxis.h, PlotStyle.h): series told
// apart by colour and marker, the reference line at the row its value gives, axes fitted to the
// data with readable ticks, and a line that never runs back in time. (No GL needed; it lives
// beside the sweep, in the GL tests' executable.)
#include "report/LogAxis.h"
#include "report/Plot.h"
#include "report/PlotStyle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

namespace lenslab {
namespace {

// CIELAB (D65) of a linear sRGB colour, for the CIE76 colour difference: the Euclidean distance,
// where about 2.3 is a just-noticeable difference.
glm::dvec3 lab(const glm::vec3& linear) {
  const glm::dvec3 c(linear);
  const glm::dvec3 xyz(0.4124 * c.r + 0.3576 * c.g + 0.1805 * c.b, 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b,
                       0.0193 * c.r + 0.1192 * c.g + 0.9505 * c.b);
  const glm::dvec3 white(0.95047, 1.0, 1.08883);
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : t * 24389.0 / 27.0 / 116.0 + 16.0 / 116.0;
  };
  const glm::dvec3 n(f(xyz.x / white.x), f(xyz.y / white.y), f(xyz.z / white.z));
  return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}
double deltaE(const glm::vec3& a, const glm::vec3& b) { return glm::length(lab(a) - lab(b)); }

TEST(PlotStyle, TheFirstNineSeriesDifferClearlyInColourAndInShape) {
  // 20 ΔE76 is several times a just-noticeable difference; Tol's muted scheme's closest pair
  // (olive and sand) is 22.8 apart.
  for (int i = 0; i < kPlotColours; ++i) {
    EXPECT_GT(deltaE(seriesStyle(i).colour, glm::vec3(1.0f)), 20.0) << "series " << i << " against the white page";
    EXPECT_GT(deltaE(seriesStyle(i).colour, referenceLineColour()), 20.0) << "series " << i;
    for (int j = 0; j < i; ++j) {
      EXPECT_GT(deltaE(seriesStyle(i).colour, seriesStyle(j).colour), 20.0) << "series " << j << " and " << i;
      EXPECT_NE(seriesStyle(i).marker, seriesStyle(j).marker) << "series " << j << " and " << i;
    }
  }
}

TEST(PlotStyle, PastNineSeriesNoTwoShareBothColourAndShape) {
  std::set<std::pair<int, int>> seen;
  for (int i = 0; i < kPlotColours * kMarkerShapes; ++i)
    EXPECT_TRUE(seen.insert({i % kPlotColours, static_cast<int>(seriesStyle(i).marker)}).second) << "series " << i;
}

TEST(PlotStyle, TheColoursAreTolsMutedSchemeAfterSrgbEncoding) {
  // Indigo #332288: the linear value the plot draws with is what the PNG writer encodes back to it.
  const glm::vec3 indigo = seriesStyle(0).colour;
  const auto encode = [](float x) { return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f; };
  EXPECT_NEAR(encode(indigo.r) * 255.0f, 0x33, 0.01f);
  EXPECT_NEAR(encode(indigo.g) * 255.0f, 0x22, 0.01f);
  EXPECT_NEAR(encode(indigo.b) * 255.0f, 0x88, 0.01f);
}

TEST(LogAxis, TheFittedRangeHugsTheDataInsteadOfWideningToDecades) {
  const LogRange r = fittedLogRange(0.12, 0.8);
  EXPECT_LT(r.lo, 0.12);
  EXPECT_GT(r.hi, 0.8);
  EXPECT_GT(r.lo, 0.1);  // not widened to the decade
  EXPECT_LT(r.hi, 1.0);
  EXPECT_GT(std::log10(0.8 / 0.12) / std::log10(r.hi / r.lo), 0.85) << "the data fill most of the axis";
  // One value: a range of at least a factor of 4, centred on it (in log space).
  const LogRange one = fittedLogRange(0.3, 0.3);
  EXPECT_GE(one.hi / one.lo, 4.0);
  EXPECT_NEAR(std::sqrt(one.lo * one.hi), 0.3, 1e-12);
}

std::vector<std::string> labels(const std::vector<AxisTick>& ticks) {
  std::vector<std::string> out;
  for (const AxisTick& t : ticks) out.push_back(t.label);
  return out;
}

TEST(LogAxis, TicksAre125UnderACoupleOfDecadesAndDecadesOverThem) {
  EXPECT_EQ(labels(logTicks({0.03, 0.4})), (std::vector<std::string>{"0.05", "0.1", "0.2"}));
  EXPECT_EQ(labels(logTicks({0.8, 60.0})), (std::vector<std::string>{"1", "2", "5", "10", "20", "50"}));
  EXPECT_EQ(labels(logTicks({2e-6, 3.0})), (std::vector<std::string>{"1e-5", "0.0001", "0.001", "0.01", "0.1", "1"}));
  EXPECT_EQ(labels(logTicks({1.5, 4.5})), (std::vector<std::string>{"2", "3", "4"}));
  EXPECT_EQ(labels(logTicks({3000.0, 2e4})), (std::vector<std::string>{"5000", "1e4", "2e4"}));
  EXPECT_NEAR(logTicks({0.03, 0.4})[0].value, 0.05, 1e-15);
}

TEST(LogAxis, EveryFittedRangeHasAtLeastTwoTicksInsideInOrder) {
  std::mt19937 random(36);
  std::uniform_real_distribution<double> exponent(-8.0, 4.0), span(0.0, 9.0);
  for (int i = 0; i < 2000; ++i) {
    const double lo = std::pow(10.0, exponent(random)), hi = lo * std::pow(10.0, span(random));
    const LogRange r = fittedLogRange(lo, hi);
    const std::vector<AxisTick> ticks = logTicks(r);
    ASSERT_GE(ticks.size(), 2u) << lo << " to " << hi;
    EXPECT_LE(ticks.size(), 10u) << lo << " to " << hi;
    for (std::size_t k = 0; k < ticks.size(); ++k) {
      EXPECT_GE(ticks[k].value, r.lo * (1.0 - 1e-9));
      EXPECT_LE(ticks[k].value, r.hi * (1.0 + 1e-9));
      if (k > 0) {
        EXPECT_GT(ticks[k].value, ticks[k - 1].value);
      }
    }
  }
}

TEST(PointsOnTheLine, ARunTimedSlowerThanALargerOneIsLeftOff) {
  // Sample counts 1, 2, 4, 8: the run of 2 took longer than that of 4 (the machine was busy).
  const std::vector<glm::dvec2> points = {{0.1, 0.4}, {0.5, 0.3}, {0.3, 0.2}, {0.6, 0.1}};
  EXPECT_EQ(pointsOnTheLine(points), (std::vector<bool>{true, false, true, true}));
  // Points that cannot be placed on log axes are never on it, and break nothing else.
  EXPECT_EQ(pointsOnTheLine({{0.1, 0.4}, {0.0, 0.3}, {0.2, 0.0}, {0.3, 0.1}}),
            (std::vector<bool>{true, false, false, true}));
  EXPECT_TRUE(pointsOnTheLine({}).empty());
}

TEST(PointsOnTheLine, TheLineNeverRunsBackAndLeavesOffOnlyWhatItMust) {
  std::mt19937 random(8);
  std::uniform_real_distribution<double> seconds(0.01, 1.0);
  for (int i = 0; i < 500; ++i) {
    std::vector<glm::dvec2> points(1 + i % 12);
    for (glm::dvec2& p : points) p = {seconds(random), 0.1};
    const std::vector<bool> on = pointsOnTheLine(points);
    double previous = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      // Off exactly when a later point is faster: the line keeps every point it can.
      bool fasterLater = false;
      for (std::size_t later = k + 1; later < points.size(); ++later) fasterLater |= points[later].x < points[k].x;
      EXPECT_EQ(on[k], !fasterLater);
      if (!on[k]) continue;
      EXPECT_GE(points[k].x, previous) << "the line runs back";
      previous = points[k].x;
    }
    EXPECT_TRUE(on.back()) << "the largest run is always on the line";
  }
}

// The rows of the image holding at least `minPixels` pixels of exactly colour c, averaged.
double rowOf(const Image& image, const glm::vec3& c, int minPixels) {
  double sum = 0.0;
  int rows = 0;
  for (int y = 0; y < image.height; ++y) {
    int count = 0;
    for (int x = 0; x < image.width; ++x) count += glm::vec3(image.at(x, y)) == c;
    if (count >= minPixels) sum += y, ++rows;
  }
  return rows ? sum / rows : -1.0;
}

TEST(Plot, TheReferenceLineLiesAtItsValueAmongTheSeries) {
  ASSERT_FALSE(plotFontPath().empty()) << "fonts-dejavu-core (tools/install-deps.sh) or LENSLAB_PLOT_FONT";
  // Two flat series a hundredfold apart, and the line at the geometric mean between them: on log
  // axes it lies halfway between their rows.
  const std::vector<PlotSeries> series = {{"upper", {{0.1, 0.1}, {1.0, 0.1}}}, {"lower", {{0.1, 1e-3}, {1.0, 1e-3}}}};
  const Image image = logLogPlot(series, "seconds", "RMSE", "test", HorizontalLine{0.01, "reference noise"});
  // A series' line crosses the plot (over 300 of its 560 pixels), the dashes cover 10 of every 16;
  // the legend's samples are 41 pixels long.
  const double upper = rowOf(image, seriesStyle(0).colour, 300), lower = rowOf(image, seriesStyle(1).colour, 300);
  const double level = rowOf(image, referenceLineColour(), 200);
  ASSERT_GT(upper, 0.0);
  ASSERT_GT(lower, upper + 300.0) << "two decades apart fill most of the 520-pixel plot";
  ASSERT_GT(level, 0.0) << "no dashed line drawn";
  EXPECT_NEAR(level, 0.5 * (upper + lower), 1.0);
  EXPECT_GT(deltaE(seriesStyle(0).colour, seriesStyle(1).colour), 20.0);
}

TEST(Plot, WithoutDataOrLineItStillDrawsItsAxes) {
  ASSERT_FALSE(plotFontPath().empty()) << "fonts-dejavu-core (tools/install-deps.sh) or LENSLAB_PLOT_FONT";
  const Image image = logLogPlot({}, "seconds", "RMSE", "empty");
  EXPECT_EQ(image.width, 960);
  EXPECT_EQ(image.at(0, 0), glm::vec4(1.0f));
}

}  // namespace
}  // namespace lenslab
