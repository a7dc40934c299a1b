#pragma once
// Exact pixel integrals of simple scenes: oracles that share no code with either renderer.
//
// The project's truth: a pixel's value is the average of the shading over the pixel square × the
// aperture disk, with textures reconstructed at level 0 (bilinear in linear light, or nearest) and
// never pre-filtered. For planar pieces seen through a pinhole that average is geometry: every
// texel (nearest) or every cell between texel centres (bilinear) is a convex quad in the image,
// clipped against the pixel square; a constant is integrated by the clipped area, a bilinear
// function by a Gauss rule that is exact up to the rounding of doubles once it has converged.
//
// Image coordinates are lenslab's continuous pixels: origin at the top-left corner, +y down, pixel
// (x, y) the square [x, x + 1] × [y, y + 1], so a pixel's area is 1 and its integral its value.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace lenslab::test {

using Polygon = std::vector<glm::dvec2>;  // convex, either orientation

double signedArea(const Polygon& polygon);  // counter-clockwise in a y-up frame is positive

// Sutherland–Hodgman: the part of `subject` where dot(normal, p) <= offset.
Polygon clipToHalfPlane(const Polygon& subject, glm::dvec2 normal, double offset);
Polygon clipToBox(const Polygon& subject, glm::dvec2 lo, glm::dvec2 hi);
// The intersection of `subject` with the convex polygon `clipper`.
Polygon clipToConvex(const Polygon& subject, const Polygon& clipper);

// n-point Gauss–Legendre on [0, 1]: exact for polynomials of degree <= 2n − 1.
struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};
QuadratureRule gaussLegendre01(int n);

// ∫ f over a convex polygon: a fan of triangles, each by the collapsed (Duffy) product rule
// p = a + s·((b − a) + t·(c − b)), dp = 2·area·s ds dt, which is exact for polynomials in p of
// degree <= 2n − 2. f returns a dvec3 (a colour).
template <class F>
glm::dvec3 integrateConvex(const Polygon& polygon, F&& f, const QuadratureRule& rule) {
  glm::dvec3 sum(0.0);
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const glm::dvec2 a = polygon[0], ab = polygon[k] - a, bc = polygon[k + 1] - polygon[k];
    const double twiceArea = std::abs(ab.x * bc.y - ab.y * bc.x);
    if (twiceArea == 0.0) continue;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const double s = rule.nodes[i];
      for (std::size_t j = 0; j < rule.nodes.size(); ++j)
        sum += (rule.weights[i] * rule.weights[j] * s * twiceArea) * f(a + s * (ab + rule.nodes[j] * bc));
    }
  }
  return sum;
}

// The view through aperture offset `lensOffset` (u, v; world units) as a linear map of homogeneous
// world points to (x·Z, y·Z, Z): continuous pixel (x, y) and depth Z from the PRP along −n. Made
// from the lecture's formula (window u = PRP.u + f·X/Z, the window kept on the plane of focus),
// not from lenslab's matrices; perspective cameras focused on their view plane only.
class PinholeProjection {
 public:
  PinholeProjection(const Camera& camera, ImageSize size, glm::dvec2 lensOffset = {0.0, 0.0});
  glm::dvec3 homogeneous(const glm::dvec4& world) const;
  glm::dvec2 pixel(const glm::dvec3& world) const;
  // For points origin + u·perU + v·perV: (x·Z, y·Z, Z) = pixelFromUv · (u, v, 1).
  glm::dmat3 pixelFromUv(const glm::dvec3& origin, const glm::dvec3& perU, const glm::dvec3& perV) const;

 private:
  glm::dvec3 u_, v_, n_, vrp_, prp_;  // basis and VRP in the world; PRP (moved by the lens) in VRC
  double focal_;
  glm::dvec2 pxPerWindow_, windowTopLeft_;
};

// sRGB 8-bit to linear, the same float arithmetic as src/raycast/TextureSampler.cpp.
float decodeSrgb8(std::uint8_t value);

// A planar textured rectangle: world = origin + u·perU + v·perV over [uvMin, uvMax] (texture
// coordinates, glTF's: v = 0 is the image's top row), wrap REPEAT, unlit (colour = texel).
struct TexturedPlane {
  glm::dvec3 origin{0.0};
  glm::dvec3 perU{1.0, 0.0, 0.0};
  glm::dvec3 perV{0.0, 1.0, 0.0};
  glm::dvec2 uvMin{0.0};
  glm::dvec2 uvMax{1.0};
  const TextureImage* image = nullptr;
  bool nearest = true;  // else the bilinear level-0 reconstruction (texel centres at (i + 0.5)/W)

  glm::dvec3 world(glm::dvec2 uv) const { return origin + uv.x * perU + uv.y * perV; }
};

// Two triangles with the plane's positions and texture coordinates (double-sided is the material's).
Mesh planeMesh(const TexturedPlane& plane, int material);

// The exact pixel integral of `plane` seen through `projection` over `background`. The plane must
// lie wholly in front of the camera. Bilinear cells are integrated with an n-point rule.
Image planeImage(const TexturedPlane& plane, const PinholeProjection& projection, ImageSize size, glm::dvec3 background,
                 int quadraturePoints = 8);

// Convex flat-coloured polygons in pixel coordinates, nearest first (each hides what follows it):
// exact coverage by inclusion–exclusion over the nearer polygons.
struct ColouredPolygon {
  Polygon pixels;
  glm::dvec3 colour;
};
Image polygonsImage(const std::vector<ColouredPolygon>& nearestFirst, ImageSize size, glm::dvec3 background);

// Thin lens, fronto-parallel layers: an axis-aligned rectangle of the image that moves by
// pxPerLens ⊙ lensOffset as the view moves over the aperture (each depth has its own rate; 0 on
// the plane of focus). A front rectangle over a back layer of disjoint rectangles (the texels of a
// NEAREST plane), over the background, averaged over pixel × disk of `apertureRadius`. The disk
// integral is split where the integrand has kinks and done by Gauss–Legendre in between, so it
// converges exponentially; `quadraturePoints` per piece.
struct MovingRect {
  glm::dvec2 lo, hi;     // pixels, seen from the lens centre
  glm::dvec2 pxPerLens;  // pixels per world unit of lens offset, x and y
  glm::dvec3 colour;
};
Image thinLensRectsImage(const MovingRect& front, const std::vector<MovingRect>& back, ImageSize size,
                         glm::dvec3 background, double apertureRadius, int quadraturePoints = 12);

// Fixtures shared by the oracle and its own checks.
// Camera at the origin looking down −z; the view plane (= plane of focus) at `focusM`, the window
// `halfWidth` wide on each side of the axis, as tall as `size`'s aspect makes its pixels square.
Camera axisCamera(double focusM, double halfWidth, double apertureRadius, ImageSize size);
// Texels of independent random sRGB colours (opaque): neighbours differ, so blurring shows.
TextureImage randomTexture(int width, int height, std::uint32_t seed);

}  // namespace lenslab::test
