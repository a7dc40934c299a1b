#include "app/LensPlot.h"

#include "lens/RealLens.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace lenslab {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kFieldColours[] = {"#1f77b4", "#2ca02c", "#d62728"};  // axis, 0.7, corner

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

// Maps lens coordinates (z along the axis, y up) into a panel of the picture.
struct Frame {
  double x0, y0, width, height;  // the panel, in picture units
  double zMin, zMax, yMax;       // what it shows: z from zMin to zMax, y from −yMax to yMax
  double scale() const { return std::min(width / (zMax - zMin), height / (2.0 * yMax)); }
  double x(double z) const { return x0 + (z - zMin) * scale(); }
  double y(double h) const { return y0 + 0.5 * height - h * scale(); }
};

void polyline(std::ostringstream& out, const std::vector<glm::dvec2>& points, const char* colour, double width,
              double opacity = 1.0) {
  out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width << "\" stroke-opacity=\""
      << opacity << "\" points=\"";
  for (const glm::dvec2& p : points) out << number(p.x) << "," << number(p.y) << " ";
  out << "\"/>\n";
}

void text(std::ostringstream& out, double x, double y, const std::string& s, const char* anchor = "start",
          int size = 12) {
  out << "<text x=\"" << number(x) << "\" y=\"" << number(y) << "\" font-size=\"" << size << "\" text-anchor=\""
      << anchor << "\" font-family=\"sans-serif\">" << s << "</text>\n";
}

// The lens in section: each surface's profile, the glass between them shaded, the stop.
void drawSurfaces(std::ostringstream& out, const LensPrescription& lens, const LensReport& report, const Frame& f) {
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    const LensSurface& s = lens.surfaces[i];
    const double z = lens.vertexMm(i), half = 0.5 * s.apertureMm;
    if (s.isStop()) {
      const double stopHalf = 0.5 * report.stopDiameterMm, outer = stopHalf + 0.08 * f.yMax;
      for (double sign : {-1.0, 1.0})
        polyline(out, {{f.x(z), f.y(sign * stopHalf)}, {f.x(z), f.y(sign * outer)}}, "#000", 2.5);
      continue;
    }
    std::vector<glm::dvec2> profile;
    for (int k = 0; k <= 40; ++k) {
      const double h = -half + s.apertureMm * k / 40.0;
      profile.push_back({f.x(z + s.sagMm(std::abs(h))), f.y(h)});
    }
    polyline(out, profile, "#333", 1.2);
    // A glass's edge: from this surface's rim to the next one's, at the smaller of the two rims.
    if (s.indexAfter != 1.0 && i + 1 < lens.surfaces.size()) {
      const LensSurface& next = lens.surfaces[i + 1];
      const double rim = std::min(half, 0.5 * next.apertureMm);
      for (double sign : {-1.0, 1.0})
        polyline(
            out,
            {{f.x(z + s.sagMm(rim)), f.y(sign * rim)}, {f.x(lens.vertexMm(i + 1) + next.sagMm(rim)), f.y(sign * rim)}},
            "#333", 1.2);
    }
  }
}

// The lens in section (drawSurfaces), the film, and rays from three field points (a parallel
// bundle from infinity, or from the point in focus).
void drawLayout(std::ostringstream& out, const LensPrescription& lens, const LensReport& report,
                const LensAnalysisOptions& o, const Frame& f) {
  drawSurfaces(out, lens, report, f);
  const double filmZ = lens.lengthMm() + report.filmDistanceMm;
  const double halfDiagonal = 0.5 * glm::length(o.sensorMm);
  polyline(out, {{f.x(filmZ), f.y(-halfDiagonal)}, {f.x(filmZ), f.y(halfDiagonal)}}, "#000", 2.0);
  text(out, f.x(filmZ), f.y(-halfDiagonal) + 16, "film", "middle");
  polyline(out, {{f.x(f.zMin), f.y(0.0)}, {f.x(filmZ), f.y(0.0)}}, "#999", 0.6);

  // Rays: from each field point's chief ray, a fan across the pupil in the drawing's plane.
  const bool atInfinity = !(o.focusDistanceMm > 0.0) || std::isinf(o.focusDistanceMm);
  const double fractions[] = {0.0, 0.7, 1.0};
  for (int k = 0; k < 3; ++k) {
    const double angle = report.field.empty() ? 0.0 : [&] {
      // The field angle at this fraction, interpolated in the report's table.
      const double t = fractions[k] * static_cast<double>(report.field.size() - 1);
      const std::size_t i = std::min(static_cast<std::size_t>(t), report.field.size() - 2);
      const double a = report.field[i].fieldAngleDegrees, b = report.field[i + 1].fieldAngleDegrees;
      return (a + (t - static_cast<double>(i)) * (b - a)) * kPi / 180.0;
    }();
    // Rays come in from below for a point above the axis: they land on the film above (inverted).
    const glm::dvec3 direction(0.0, std::sin(angle), std::cos(angle));
    const double startZ = f.zMin;
    // From infinity a parallel bundle; from a finite distance, rays from the object point on the
    // chief ray (through the entrance pupil's centre) focusDistance in front of the film.
    const glm::dvec3 pupil(0.0, 0.0, report.firstOrder.entrancePupilMm);
    const glm::dvec3 object = pupil - (pupil.z - (filmZ - o.focusDistanceMm)) / direction.z * direction;
    const auto rayFrom = [&](double h) {
      const glm::dvec3 start(0.0, h, startZ);
      return LensRay{start, atInfinity ? direction : glm::normalize(start - object)};
    };
    LensTrace trace;
    trace.stopDiameterMm = report.stopDiameterMm;
    const double centre = pupil.y + (startZ - pupil.z) * std::tan(angle);
    const double reach = std::max(lens.surfaces.front().apertureMm, 2.0 * report.firstOrder.entrancePupilDiameterMm) /
                         std::max(0.1, std::cos(angle));
    std::vector<double> passing;
    for (int j = 0; j <= 400; ++j) {
      const double h = centre - reach + 2.0 * reach * j / 400.0;
      if (traceLens(lens, rayFrom(h), false, trace)) passing.push_back(h);
    }
    if (passing.empty()) continue;
    const double lo = passing.front(), hi = passing.back();
    for (int j = 0; j < 5; ++j) {
      const double h = lo + (hi - lo) * j / 4.0;
      std::vector<glm::dvec3> path;
      trace.path = &path;
      const std::optional<LensRay> out0 = traceLens(lens, rayFrom(h), false, trace);
      trace.path = nullptr;
      if (!out0) continue;
      std::vector<glm::dvec2> points = {{f.x(startZ), f.y(h)}};
      for (const glm::dvec3& p : path) points.push_back({f.x(p.z), f.y(p.y)});
      const double t = (filmZ - out0->origin.z) / out0->direction.z;
      const glm::dvec3 onFilm = out0->origin + t * out0->direction;
      points.push_back({f.x(onFilm.z), f.y(onFilm.y)});
      polyline(out, points, kFieldColours[k], 0.8, 0.85);
    }
  }
}

// A small chart of the report's field table: `value` against the field fraction.
template <class Value>
void drawChart(std::ostringstream& out, const LensReport& report, double x0, double y0, double w, double h,
               const std::string& title, Value value, double lo, double hi) {
  out << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << w << "\" height=\"" << h
      << "\" fill=\"none\" stroke=\"#999\"/>\n";
  text(out, x0 + 0.5 * w, y0 - 6, title, "middle");
  const auto px = [&](double t) { return x0 + t * w; };
  const auto py = [&](double v) { return y0 + h - (v - lo) / (hi - lo) * h; };
  if (lo < 0.0 && hi > 0.0) polyline(out, {{px(0), py(0)}, {px(1), py(0)}}, "#bbb", 0.6);
  std::vector<glm::dvec2> points;
  for (const FieldSample& s : report.field) points.push_back({px(s.fieldFraction), py(value(s))});
  polyline(out, points, "#d62728", 1.8);
  text(out, x0 - 4, y0 + 10, number(hi), "end", 10);
  text(out, x0 - 4, y0 + h, number(lo), "end", 10);
  text(out, x0, y0 + h + 14, "axis", "start", 10);
  text(out, x0 + w, y0 + h + 14, "corner", "end", 10);
}

}  // namespace

std::string lensPlotSvg(const LensPrescription& lens, const LensReport& report, const LensAnalysisOptions& o) {
  std::ostringstream out;
  const double width = 960, height = 400;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const double filmZ = lens.lengthMm() + report.filmDistanceMm;
  double yMax = 0.5 * glm::length(o.sensorMm);
  for (const LensSurface& s : lens.surfaces) yMax = std::max(yMax, 0.5 * s.apertureMm);
  const double lead = 0.25 * filmZ;
  const Frame frame{20, 40, 600, 330, -lead, filmZ + 0.02 * filmZ, 1.1 * yMax};
  text(out, 20, 22, lens.comments.empty() ? lens.source : lens.comments.front(), "start", 14);
  // Rays from far off the axis start outside the panel: it clips them.
  out << "<clipPath id=\"layout\"><rect x=\"" << frame.x0 << "\" y=\"" << frame.y0 << "\" width=\"" << frame.width + 20
      << "\" height=\"" << frame.height << "\"/></clipPath>\n<g clip-path=\"url(#layout)\">\n";
  drawLayout(out, lens, report, o, frame);
  out << "</g>\n";
  text(out, 20, height - 8,
       "focal length " + number(report.firstOrder.focalLengthMm) + " mm, f/" + number(report.firstOrder.fNumber) +
           ", field " + number(report.fieldOfViewDegrees.z) + " deg diagonal on " + number(o.sensorMm.x) + " x " +
           number(o.sensorMm.y) + " mm",
       "start", 12);
  double dLo = 0.0, dHi = 0.0;
  for (const FieldSample& s : report.field)
    dLo = std::min(dLo, s.distortionPercent), dHi = std::max(dHi, s.distortionPercent);
  const double span = std::max(1.0, dHi - dLo);
  drawChart(
      out, report, 690, 50, 240, 120, "distortion (%)", [](const FieldSample& s) { return s.distortionPercent; },
      dLo - 0.1 * span, dHi + 0.1 * span);
  drawChart(
      out, report, 690, 240, 240, 120, "relative illumination",
      [](const FieldSample& s) { return s.relativeIllumination; }, 0.0, 1.05);
  out << "</svg>\n";
  return out.str();
}

}  // namespace lenslab
