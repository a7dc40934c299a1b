#include "pixel_integral.h"

#include "camera/ViewSpec.h"

#include <algorithm>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace lenslab::test {

double signedArea(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

Polygon clipToHalfPlane(const Polygon& subject, glm::dvec2 normal, double offset) {
  Polygon out;
  out.reserve(subject.size() + 1);
  for (std::size_t i = 0; i < subject.size(); ++i) {
    const glm::dvec2 a = subject[i], b = subject[(i + 1) % subject.size()];
    const double da = glm::dot(normal, a) - offset, db = glm::dot(normal, b) - offset;
    if (da <= 0.0) out.push_back(a);
    // The crossing is computed from the inside end, so that it lands on the line to rounding.
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
  }
  return out.size() >= 3 ? out : Polygon{};
}

Polygon clipToBox(const Polygon& subject, glm::dvec2 lo, glm::dvec2 hi) {
  Polygon p = clipToHalfPlane(subject, {-1.0, 0.0}, -lo.x);
  p = clipToHalfPlane(p, {1.0, 0.0}, hi.x);
  p = clipToHalfPlane(p, {0.0, -1.0}, -lo.y);
  return clipToHalfPlane(p, {0.0, 1.0}, hi.y);
}

Polygon clipToConvex(const Polygon& subject, const Polygon& clipper) {
  // Each edge of the clipper bounds a half-plane; its inside is the side of the interior.
  const double orientation = signedArea(clipper) >= 0.0 ? 1.0 : -1.0;
  Polygon p = subject;
  for (std::size_t i = 0; i < clipper.size() && !p.empty(); ++i) {
    const glm::dvec2 a = clipper[i], b = clipper[(i + 1) % clipper.size()];
    const glm::dvec2 outward = orientation * glm::dvec2(b.y - a.y, a.x - b.x);
    p = clipToHalfPlane(p, outward, glm::dot(outward, a));
  }
  return p;
}

QuadratureRule gaussLegendre01(int n) {
  QuadratureRule rule;
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from Tricomi's guess for the i-th root.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(0.5 * (1.0 - x));
    rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));  // 2/(...) on [−1, 1], halved
  }
  return rule;
}

PinholeProjection::PinholeProjection(const Camera& camera, ImageSize size, glm::dvec2 lensOffset) {
  const ViewSpec& view = camera.view;
  if (view.projection != Projection::Perspective || camera.inverseFocusOffPlane)
    throw std::invalid_argument("PinholeProjection: perspective cameras focused on their view plane only");
  const ViewBasis basis = viewBasis(view);
  u_ = basis.u;
  v_ = basis.v;
  n_ = basis.n;
  vrp_ = view.vrp;
  prp_ = view.prp + glm::dvec3(lensOffset, 0.0);
  focal_ = view.prp.z;
  pxPerWindow_ = {size.widthPx / view.window.width(), size.heightPx / view.window.height()};
  windowTopLeft_ = {view.window.umin, view.window.vmax};
}

glm::dvec3 PinholeProjection::homogeneous(const glm::dvec4& world) const {
  const glm::dvec3 relative = glm::dvec3(world) - world.w * vrp_;
  const glm::dvec3 vrc(glm::dot(relative, u_), glm::dot(relative, v_), glm::dot(relative, n_));
  const glm::dvec3 fromPrp = vrc - world.w * prp_;
  const double depth = -fromPrp.z;
  // window·Z = PRP·Z + f·(X, Y), then pixels: x right from umin, y down from vmax.
  const glm::dvec2 windowTimesDepth = glm::dvec2(prp_) * depth + focal_ * glm::dvec2(fromPrp);
  return {(windowTimesDepth.x - windowTopLeft_.x * depth) * pxPerWindow_.x,
          (windowTopLeft_.y * depth - windowTimesDepth.y) * pxPerWindow_.y, depth};
}

glm::dvec2 PinholeProjection::pixel(const glm::dvec3& world) const {
  const glm::dvec3 h = homogeneous(glm::dvec4(world, 1.0));
  return glm::dvec2(h) / h.z;
}

glm::dmat3 PinholeProjection::pixelFromUv(const glm::dvec3& origin, const glm::dvec3& perU,
                                          const glm::dvec3& perV) const {
  return glm::dmat3(homogeneous(glm::dvec4(perU, 0.0)), homogeneous(glm::dvec4(perV, 0.0)),
                    homogeneous(glm::dvec4(origin, 1.0)));
}

float decodeSrgb8(std::uint8_t value) {
  const float x = static_cast<float>(value) / 255.0f;
  return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

Mesh planeMesh(const TexturedPlane& plane, int material) {
  Mesh mesh;
  mesh.name = "plane";
  mesh.material = material;
  const glm::dvec2 corners[4] = {
      plane.uvMin, {plane.uvMax.x, plane.uvMin.y}, plane.uvMax, {plane.uvMin.x, plane.uvMax.y}};
  const glm::dvec3 normal = glm::normalize(glm::cross(plane.perU, plane.perV));
  for (const glm::dvec2& uv : corners) {
    Vertex vertex;
    vertex.position = glm::vec3(plane.world(uv));
    vertex.normal = glm::vec3(normal);
    vertex.uv = glm::vec2(uv);
    mesh.vertices.push_back(vertex);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

namespace {

int wrapRepeat(int i, int size) { return ((i % size) + size) % size; }

glm::dvec3 texel(const TextureImage& image, int i, int j) {
  const std::uint8_t* p =
      &image.rgba8[(static_cast<std::size_t>(wrapRepeat(j, image.height)) * static_cast<std::size_t>(image.width) +
                    static_cast<std::size_t>(wrapRepeat(i, image.width))) *
                   4];
  return {decodeSrgb8(p[0]), decodeSrgb8(p[1]), decodeSrgb8(p[2])};
}

// The cell boundaries along one texture axis inside [lo, hi]: texel edges k/size (nearest) or
// texel centres (k + 0.5)/size (bilinear), with lo and hi themselves.
std::vector<double> cellEdges(double lo, double hi, int size, double shift) {
  std::vector<double> edges{lo};
  for (double k = std::floor(lo * size - shift) + 1.0; (k + shift) / size < hi; k += 1.0)
    if ((k + shift) / size > lo) edges.push_back((k + shift) / size);
  edges.push_back(hi);
  return edges;
}

}  // namespace

Image planeImage(const TexturedPlane& plane, const PinholeProjection& projection, ImageSize size, glm::dvec3 background,
                 int quadraturePoints) {
  const TextureImage& image = *plane.image;
  const double shift = plane.nearest ? 0.0 : 0.5;
  const glm::dmat3 pixelFromUv = projection.pixelFromUv(plane.origin, plane.perU, plane.perV);
  const glm::dmat3 uvFromPixel = glm::inverse(pixelFromUv);
  const QuadratureRule rule = gaussLegendre01(quadraturePoints);
  const std::size_t pixels = static_cast<std::size_t>(size.widthPx) * static_cast<std::size_t>(size.heightPx);
  std::vector<glm::dvec3> sum(pixels, glm::dvec3(0.0));
  std::vector<double> covered(pixels, 0.0);

  const std::vector<double> edgesU = cellEdges(plane.uvMin.x, plane.uvMax.x, image.width, shift);
  const std::vector<double> edgesV = cellEdges(plane.uvMin.y, plane.uvMax.y, image.height, shift);
  for (std::size_t cv = 0; cv + 1 < edgesV.size(); ++cv)
    for (std::size_t cu = 0; cu + 1 < edgesU.size(); ++cu) {
      const double u0 = edgesU[cu], u1 = edgesU[cu + 1], v0 = edgesV[cv], v1 = edgesV[cv + 1];
      // The texel (nearest) or the lower-left of the four texels (bilinear) this cell belongs to.
      const int i = static_cast<int>(std::floor(0.5 * (u0 + u1) * image.width - shift));
      const int j = static_cast<int>(std::floor(0.5 * (v0 + v1) * image.height - shift));
      const glm::dvec3 c00 = texel(image, i, j);
      const glm::dvec3 c10 = texel(image, i + 1, j), c01 = texel(image, i, j + 1), c11 = texel(image, i + 1, j + 1);
      Polygon quad;
      for (const glm::dvec2 uv : {glm::dvec2(u0, v0), glm::dvec2(u1, v0), glm::dvec2(u1, v1), glm::dvec2(u0, v1)}) {
        const glm::dvec3 h = pixelFromUv * glm::dvec3(uv, 1.0);
        if (!(h.z > 0.0)) throw std::invalid_argument("planeImage: the plane reaches behind the camera");
        quad.push_back(glm::dvec2(h) / h.z);
      }
      glm::dvec2 lo = quad[0], hi = quad[0];
      for (const glm::dvec2& p : quad) lo = glm::min(lo, p), hi = glm::max(hi, p);
      const int x0 = std::max(0, static_cast<int>(std::floor(lo.x))),
                x1 = std::min(size.widthPx, static_cast<int>(std::ceil(hi.x)));
      const int y0 = std::max(0, static_cast<int>(std::floor(lo.y))),
                y1 = std::min(size.heightPx, static_cast<int>(std::ceil(hi.y)));
      const auto bilinear = [&](glm::dvec2 p) {
        const glm::dvec3 h = uvFromPixel * glm::dvec3(p, 1.0);
        const double a = h.x / h.z * image.width - shift - i, b = h.y / h.z * image.height - shift - j;
        return (1.0 - b) * ((1.0 - a) * c00 + a * c10) + b * ((1.0 - a) * c01 + a * c11);
      };
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          const Polygon piece = clipToBox(quad, {x, y}, {x + 1.0, y + 1.0});
          if (piece.empty()) continue;
          const std::size_t k =
              static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx) + static_cast<std::size_t>(x);
          const double area = std::abs(signedArea(piece));
          covered[k] += area;
          sum[k] += plane.nearest ? area * c00 : integrateConvex(piece, bilinear, rule);
        }
    }
  Image out(size.widthPx, size.heightPx);
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const std::size_t k =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx) + static_cast<std::size_t>(x);
      out.set(x, y, glm::vec4(glm::vec3(sum[k] + (1.0 - covered[k]) * background), 1.0f));
    }
  return out;
}

namespace {

// Area of `piece` not hidden by nearer[from..]: A(P \ (N_t ∪ rest)) = A(P \ rest) − A((P ∩ N_t) \ rest).
double visibleArea(const Polygon& piece, const std::vector<const Polygon*>& nearer, std::size_t from) {
  if (piece.empty()) return 0.0;
  if (from == nearer.size()) return std::abs(signedArea(piece));
  return visibleArea(piece, nearer, from + 1) - visibleArea(clipToConvex(piece, *nearer[from]), nearer, from + 1);
}

}  // namespace

Image polygonsImage(const std::vector<ColouredPolygon>& nearestFirst, ImageSize size, glm::dvec3 background) {
  Image out(size.widthPx, size.heightPx);
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      glm::dvec3 sum(0.0);
      double covered = 0.0;
      std::vector<const Polygon*> nearer;  // those that reach into this pixel
      for (const ColouredPolygon& layer : nearestFirst) {
        const Polygon piece = clipToBox(layer.pixels, {x, y}, {x + 1.0, y + 1.0});
        const double area = visibleArea(piece, nearer, 0);
        sum += area * layer.colour;
        covered += area;
        if (!piece.empty()) nearer.push_back(&layer.pixels);
      }
      out.set(x, y, glm::vec4(glm::vec3(sum + (1.0 - covered) * background), 1.0f));
    }
  return out;
}

namespace {

// The interval [lo + slope·a, hi + slope·a] of one axis, a being the lens offset along that axis.
struct MovingInterval {
  double lo, hi, slope;
};
using Intervals = std::vector<MovingInterval>;

// Length of the intersection of `intervals` at lens offset a: piecewise linear in a.
double overlap(const Intervals& intervals, double a) {
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
  for (const MovingInterval& i : intervals)
    lo = std::max(lo, i.lo + i.slope * a), hi = std::min(hi, i.hi + i.slope * a);
  return std::max(0.0, hi - lo);
}

// Where overlap() may kink inside (−limit, limit): where two ends change order.
std::vector<double> kinks(const Intervals& intervals, double limit) {
  std::vector<double> out;
  const auto crossing = [&](double p0, double s0, double p1, double s1) {
    if (s0 == s1) return;
    const double a = (p1 - p0) / (s0 - s1);
    if (std::abs(a) < limit) out.push_back(a);
  };
  for (std::size_t i = 0; i < intervals.size(); ++i)
    for (std::size_t j = 0; j < intervals.size(); ++j) {
      const MovingInterval &p = intervals[i], &q = intervals[j];
      if (i < j) crossing(p.lo, p.slope, q.lo, q.slope), crossing(p.hi, p.slope, q.hi, q.slope);
      if (i != j) crossing(p.lo, p.slope, q.hi, q.slope);
    }
  std::sort(out.begin(), out.end());
  return out;
}

// ∫ overlap over [−h, h], exactly: trapezoids between the sorted kinks.
double overlapIntegral(const Intervals& intervals, const std::vector<double>& sortedKinks, double h) {
  double sum = 0.0, previous = -h, fPrevious = overlap(intervals, -h);
  for (const double k : sortedKinks)
    if (k > -h && k < h) {
      const double f = overlap(intervals, k);
      sum += 0.5 * (fPrevious + f) * (k - previous);
      previous = k;
      fPrevious = f;
    }
  return sum + 0.5 * (fPrevious + overlap(intervals, h)) * (h - previous);
}

bool mayOverlap(const Intervals& intervals, double radius) {
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
  for (const MovingInterval& i : intervals)
    lo = std::max(lo, i.lo - std::abs(i.slope) * radius), hi = std::min(hi, i.hi + std::abs(i.slope) * radius);
  return hi > lo;
}

// ∫ over the disk |a| <= R of overlap(x, a.x)·overlap(y, a.y): the inner integral along y exactly,
// the outer along x = R·sin φ (which takes the disk's square-root edge away) by Gauss–Legendre
// between the angles where the integrand kinks, where it is analytic.
double diskIntegral(const Intervals& x, const Intervals& y, double radius, const QuadratureRule& rule) {
  if (!mayOverlap(x, radius) || !mayOverlap(y, radius)) return 0.0;
  const std::vector<double> kinksX = kinks(x, radius), kinksY = kinks(y, radius);
  std::vector<double> angles{-0.5 * std::numbers::pi, 0.5 * std::numbers::pi};
  for (const double k : kinksX) angles.push_back(std::asin(k / radius));
  for (const double k : kinksY) angles.push_back(std::acos(std::abs(k) / radius)), angles.push_back(-angles.back());
  std::sort(angles.begin(), angles.end());
  double sum = 0.0;
  for (std::size_t piece = 0; piece + 1 < angles.size(); ++piece) {
    const double a0 = angles[piece], span = angles[piece + 1] - a0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const double phi = a0 + rule.nodes[i] * span, c = radius * std::cos(phi);
      sum += rule.weights[i] * span * overlap(x, radius * std::sin(phi)) * overlapIntegral(y, kinksY, c) * c;
    }
  }
  return sum;
}

MovingInterval alongX(const MovingRect& r) { return {r.lo.x, r.hi.x, r.pxPerLens.x}; }
MovingInterval alongY(const MovingRect& r) { return {r.lo.y, r.hi.y, r.pxPerLens.y}; }

}  // namespace

Image thinLensRectsImage(const MovingRect& front, const std::vector<MovingRect>& back, ImageSize size,
                         glm::dvec3 background, double apertureRadius, int quadraturePoints) {
  if (!(apertureRadius > 0.0)) throw std::invalid_argument("thinLensRectsImage: the aperture needs a radius");
  const QuadratureRule rule = gaussLegendre01(quadraturePoints);
  const double diskArea = std::numbers::pi * apertureRadius * apertureRadius;
  Image out(size.widthPx, size.heightPx);
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      const MovingInterval pixelX{static_cast<double>(x), x + 1.0, 0.0}, pixelY{static_cast<double>(y), y + 1.0, 0.0};
      const double frontArea = diskIntegral({pixelX, alongX(front)}, {pixelY, alongY(front)}, apertureRadius, rule);
      glm::dvec3 sum = frontArea * front.colour;
      double covered = frontArea;
      for (const MovingRect& r : back) {
        // The back rectangle's part in the pixel, less the part of that which the front hides.
        const double visible =
            diskIntegral({pixelX, alongX(r)}, {pixelY, alongY(r)}, apertureRadius, rule) -
            diskIntegral({pixelX, alongX(r), alongX(front)}, {pixelY, alongY(r), alongY(front)}, apertureRadius, rule);
        sum += visible * r.colour;
        covered += visible;
      }
      out.set(x, y, glm::vec4(glm::vec3((sum + (diskArea - covered) * background) / diskArea), 1.0f));
    }
  return out;
}

Camera axisCamera(double focusM, double halfWidth, double apertureRadius, ImageSize size) {
  ViewSpec v;
  v.vrp = {0.0, 0.0, -focusM};
  v.prp = {0.0, 0.0, focusM};
  const double halfHeight = halfWidth * size.heightPx / size.widthPx;
  v.window = {-halfWidth, -halfHeight, halfWidth, halfHeight};
  v.nearDistance = 0.01;
  return cameraFocusedOnViewPlane(v, apertureRadius, "oracle");
}

TextureImage randomTexture(int width, int height, std::uint32_t seed) {
  TextureImage image;
  image.name = "random";
  image.width = width;
  image.height = height;
  for (int i = 0; i < width * height; ++i) {
    for (int c = 0; c < 3; ++c) {
      seed = seed * 1664525u + 1013904223u;
      image.rgba8.push_back(static_cast<std::uint8_t>(seed >> 24));
    }
    image.rgba8.push_back(255);
  }
  return image;
}

}  // namespace lenslab::test
