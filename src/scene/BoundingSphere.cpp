#include "scene/BoundingSphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace lenslab {
namespace {

struct Ball {
  glm::dvec3 c{0.0};
  double r2 = -1.0;  // squared radius; negative: empty
};

// Inside, with a relative slack so that points on the boundary, rounded, count as inside.
bool holds(const Ball& b, const glm::dvec3& p) {
  const glm::dvec3 d = p - b.c;
  return b.r2 >= 0.0 && glm::dot(d, d) <= b.r2 * (1.0 + 1e-12) + 1e-300;
}

Ball ballThrough(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c = 0.5 * (a + b);
  return {c, glm::dot(a - c, a - c)};
}

Ball smallestOfFew(const glm::dvec3* p, int n);

// The circle through three points (its centre in their plane); collinear points: the smallest
// ball of the three.
Ball ballThrough(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = a - c, v = b - c;
  const glm::dvec3 n = glm::cross(u, v);
  const double n2 = glm::dot(n, n);
  if (!(n2 > 1e-24 * glm::dot(u, u) * glm::dot(v, v))) {
    const glm::dvec3 q[3] = {a, b, c};
    return smallestOfFew(q, 3);
  }
  const glm::dvec3 offset = glm::cross(glm::dot(u, u) * v - glm::dot(v, v) * u, n) / (2.0 * n2);
  return {c + offset, glm::dot(offset, offset)};
}

// The sphere through four points; coplanar points: the smallest ball of the four.
Ball ballThrough(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
  const glm::dvec3 a = p1 - p0, b = p2 - p0, d = p3 - p0;
  const double det = glm::dot(a, glm::cross(b, d));
  const double scale = glm::length(a) * glm::length(b) * glm::length(d);
  if (!(std::abs(det) > 1e-12 * scale)) {
    const glm::dvec3 q[4] = {p0, p1, p2, p3};
    return smallestOfFew(q, 4);
  }
  const glm::dvec3 offset =
      (glm::dot(a, a) * glm::cross(b, d) + glm::dot(b, b) * glm::cross(d, a) + glm::dot(d, d) * glm::cross(a, b)) /
      (2.0 * det);
  return {p0 + offset, glm::dot(offset, offset)};
}

// The smallest ball of up to four points, by trying every support of two and three (degenerate
// cases only: the general ones go through Welzl's recursion).
Ball smallestOfFew(const glm::dvec3* p, int n) {
  Ball best;
  const auto consider = [&](const Ball& b) {
    for (int k = 0; k < n; ++k)
      if (!holds(b, p[k])) return;
    if (best.r2 < 0.0 || b.r2 < best.r2) best = b;
  };
  if (n == 1) return {p[0], 0.0};
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) consider(ballThrough(p[i], p[j]));
  if (best.r2 >= 0.0) return best;
  // No pair's ball holds them all: three points span it (non-collinear, or a pair would have).
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const glm::dvec3 u = p[i] - p[k], v = p[j] - p[k];
        const glm::dvec3 normal = glm::cross(u, v);
        if (glm::dot(normal, normal) > 0.0) consider(ballThrough(p[i], p[j], p[k]));
      }
  if (best.r2 >= 0.0) return best;
  // Rounding defeated every candidate: the ball about the centroid through the farthest point.
  glm::dvec3 c(0.0);
  for (int k = 0; k < n; ++k) c += p[k];
  c /= n;
  double r2 = 0.0;
  for (int k = 0; k < n; ++k) r2 = std::max(r2, glm::dot(p[k] - c, p[k] - c));
  return {c, r2};
}

Ball ballOfBoundary(const std::array<glm::dvec3, 4>& r, int nr) {
  switch (nr) {
    case 0: return {};
    case 1: return {r[0], 0.0};
    case 2: return ballThrough(r[0], r[1]);
    case 3: return ballThrough(r[0], r[1], r[2]);
    default: return ballThrough(r[0], r[1], r[2], r[3]);
  }
}

// Welzl (1991): the smallest ball of points[0, n) with the `nr` points of `boundary` on its
// surface. Recursion depth is at most n + 4; it runs on the core set only (tens of points).
Ball welzl(const std::vector<glm::dvec3>& points, std::size_t n, std::array<glm::dvec3, 4>& boundary, int nr) {
  if (n == 0 || nr == 4) return ballOfBoundary(boundary, nr);
  const glm::dvec3& p = points[n - 1];
  Ball b = welzl(points, n - 1, boundary, nr);
  if (holds(b, p)) return b;
  boundary[static_cast<std::size_t>(nr)] = p;
  return welzl(points, n - 1, boundary, nr + 1);
}

}  // namespace

BoundingSphere smallestEnclosingSphere(const std::vector<glm::dvec3>& points) {
  if (points.empty()) return {glm::dvec3(0.0), -1.0};
  // The core set starts with the extreme points along 13 directions (axes, face and space
  // diagonals), which already hold nearly every point's sphere; each round adds the point farthest
  // outside. The smallest ball of the whole set is that of a few of its points, so this ends with
  // the core holding them: tens of rounds at most, each one pass over the points.
  static const glm::dvec3 directions[13] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},  {1, -1, 0},
                                            {1, 0, 1},  {1, 0, -1}, {0, 1, 1},  {0, 1, -1}, {1, 1, 1},
                                            {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};
  std::vector<glm::dvec3> core;
  // One pass for all 13 directions: each point's projections against the lowest and highest yet.
  std::array<std::size_t, 13> lo{}, hi{};
  std::array<double, 13> loValue{}, hiValue{};
  for (std::size_t k = 0; k < 13; ++k) loValue[k] = hiValue[k] = glm::dot(points[0], directions[k]);
  for (std::size_t i = 1; i < points.size(); ++i)
    for (std::size_t k = 0; k < 13; ++k) {
      const double s = glm::dot(points[i], directions[k]);
      if (s < loValue[k]) {
        loValue[k] = s;
        lo[k] = i;
      }
      if (s > hiValue[k]) {
        hiValue[k] = s;
        hi[k] = i;
      }
    }
  for (std::size_t k = 0; k < 13; ++k)
    for (const std::size_t i : {lo[k], hi[k]})
      if (std::find(core.begin(), core.end(), points[i]) == core.end()) core.push_back(points[i]);
  Ball ball;
  for (int round = 0; round < 64; ++round) {
    std::array<glm::dvec3, 4> boundary{};
    ball = welzl(core, core.size(), boundary, 0);
    std::size_t farthest = 0;
    double farthest2 = -1.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double d2 = glm::dot(points[i] - ball.c, points[i] - ball.c);
      if (d2 > farthest2) {
        farthest2 = d2;
        farthest = i;
      }
    }
    if (farthest2 <= ball.r2 * (1.0 + 2e-9)) break;  // radius within 1e-9
    // Welzl takes the last points first: the new one goes to the front of the queue it checks last
    // (move-to-front keeps the recursion short).
    core.insert(core.begin(), points[farthest]);
  }
  // Whatever rounding left outside (or the rounds' cap), Ritter's growth step takes in: the ball
  // grows just enough to hold the point, so every point ends inside.
  for (const glm::dvec3& p : points) {
    const double d = glm::length(p - ball.c), r = std::sqrt(std::max(ball.r2, 0.0));
    if (d > r) {
      const double grown = 0.5 * (r + d);
      ball.c += (grown - r) / d * (p - ball.c);
      ball.r2 = grown * grown;
    }
  }
  return {ball.c, std::sqrt(std::max(ball.r2, 0.0))};
}

BoundingSphere boundingSphere(const Scene& scene) {
  std::vector<glm::dvec3> points;
  for (const Instance& instance : scene.instances)
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(instance.mesh)].vertices)
      points.push_back(glm::dvec3(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0)));
  return smallestEnclosingSphere(points);
}

}  // namespace lenslab
