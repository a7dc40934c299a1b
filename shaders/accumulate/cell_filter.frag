#version 450 core
// One aperture view, filtered by its cell's image before it is added to the sum (blending ONE,
// ONE). The view was seen from one point p of its cell of the aperture (lens/ApertureCells.h); a
// point at inverse depth 1/Z that the view shows at pixel y is, seen from any point q of the cell,
// at y + M·(q − p), M = spreadAtInfinity + (1/Z)·spreadPerInverseDepth (the thin lens's circle of
// confusion per unit of aperture: affine in 1/Z, zero on the plane of focus; p and q are points of
// the aperture's shape, whose cells are the disk's cells carried by the shape's map, curved and
// squeezed, and undone here by diskFromAperture). So the view's pixel y
// stands for the cell's image, the cell scaled by M, and this pixel x gathers every neighbour y
// whose image covers it: q = p + M⁻¹·(x − y) inside the cell, with weight 1 / (the image's area in
// pixels), at most 1 (an image smaller than a pixel stays in its own pixel).
//
// Nearer surfaces cover farther ones. The neighbours are sorted into three layers against this
// pixel's own surface, continued as a plane (1/Z is affine in the pixel position on a plane):
// nearer, the same surface, farther. Each layer's coverage is its summed weight (at most 1), its
// colour the weighted mean, and the three are composited front to back. What no neighbour shows —
// a surface this view does not see that other points of the cell would — is missing from this view
// (its coverage falls short of 1 there) and comes from the other views: the error that remains
// shrinks as the cells do.
#include "../common/locations.glsl"
layout(binding = 0) uniform sampler2DArray views;
layout(binding = 1) uniform sampler2D viewDepth;  // reverse-Z
layout(location = LOCATION_CELL_WEIGHT) uniform vec4 weight;
layout(location = LOCATION_CELL_SPREAD_AT_INFINITY) uniform vec4 spreadAtInfinity;
layout(location = LOCATION_CELL_SPREAD_PER_INVERSE_DEPTH) uniform vec4 spreadPerInverseDepth;
layout(location = LOCATION_CELL_INVERSE_DEPTH) uniform vec2 inverseDepthFromNdc;  // 1/Z = x·z_ndc + y
layout(location = LOCATION_CELL_LENS_POINT) uniform vec2 lensPoint;
layout(location = LOCATION_CELL_RADII2) uniform vec2 radii2;  // the cell's ring, radii squared
layout(location = LOCATION_CELL_FIRST_EDGE) uniform vec2 firstEdge;
layout(location = LOCATION_CELL_LAST_EDGE) uniform vec2 lastEdge;
layout(location = LOCATION_CELL_WHOLE_RING) uniform int wholeRing;
layout(location = LOCATION_CELL_AREA) uniform float cellArea;  // of the unit disk
layout(location = LOCATION_CELL_DISPLACEMENTS) uniform ivec4 displacements;  // x − y: min, max
layout(location = LOCATION_CELL_SQUARE_BOX) uniform vec4 squareBox;
layout(location = LOCATION_CELL_MARGIN) uniform ivec2 marginPx;
layout(location = LOCATION_CELL_RECTANGLE_CENTRE) uniform vec2 rectangleCentre;
layout(location = LOCATION_CELL_RECTANGLE_AXES) uniform vec4 rectangleAxes;
layout(location = LOCATION_CELL_SECTORS) uniform vec4 sectors;
layout(location = LOCATION_CELL_SECTOR_SCALE) uniform vec4 sectorScale;
layout(location = LOCATION_CELL_DEPTH_REFERENCE) uniform float depthReference;  // Z_ref, world units  // the view's pixel of sum pixel (0, 0)
layout(location = 0) out vec4 sum;
layout(location = 1) out vec4 weightOut;  // the coverage summed beside the colour
layout(location = 2) out vec4 behindOut;  // the view's own surface, weighted to favour the farthest
layout(location = 3) out vec4 holeOut;    // the coverage this view misses behind an edge

// Pixels². A cell image smaller than kPointArea stays in its own pixel, as in plain accumulation
// (its weight at any other pixel is under a quarter of it, and an image of area 0, on the plane of
// focus, has no overlap to divide). One of at least kFewSamplesArea is tested at the pixel centre
// only; a smaller one is measured exactly, as its cell's moment rectangle over the pixel
// (overlapArea). Below kHoleArea the coverage a pixel gathers is not trusted to show an edge's
// hole (the images' edges are pixel-sized), so where this pixel's own image is that small its
// shortfall is not a hole: the pixel's colour is divided by the weight it gathered, as in plain
// accumulation. (Kept in its pixel from 1.5 px², the filter measured 34.9 dB on rows at 32 views
// where this gives 38.8, and 36.9 on the bokeh scene at 64 where this gives 39.7; small images
// tested at 2 × 2 or 4 × 4 points of the pixel instead of measured took 1.8 times as long on rows
// at 4 views.)
const float kPointArea = 0.25;
const float kFewSamplesArea = 16.0;
const float kHoleArea = 4.0;

float inverseDepthAt(ivec2 p) { return inverseDepthFromNdc.x * texelFetch(viewDepth, p, 0).r + inverseDepthFromNdc.y; }

// Shirley and Chiu's concentric map undone (lens/AperturePattern.cpp, concentricSquare).
vec2 concentricSquare(vec2 q) {
  const float quarterPi = 0.78539816339744831;
  float r = length(q), phi = atan(q.y, q.x);
  vec2 offset;
  if (abs(phi) <= quarterPi) offset = vec2(r, r * phi / quarterPi);
  else if (abs(phi) >= 3.0 * quarterPi) offset = vec2(-r, -r * (phi > 0.0 ? phi - 4.0 * quarterPi : phi + 4.0 * quarterPi) / quarterPi);
  else if (phi > 0.0) offset = vec2(r * (2.0 * quarterPi - phi) / quarterPi, r);
  else offset = vec2(-r * (2.0 * quarterPi - (phi + 4.0 * quarterPi)) / quarterPi, -r);
  return 0.5 * (offset + 1.0);
}

// lens/ApertureShape.cpp's diskFromAperture: the point of the unit disk that the shape's map
// carries to aperture point a. The cells are the disk's; M and the view's point are the aperture's.
float twiceSectorArea(float theta) {
  float t = tan(theta);
  return sectors.z * sectors.z * t + 2.0 * sectors.z * sectors.w * asinh(t) + sectors.w * sectors.w * theta;
}

vec2 diskFromAperture(vec2 a) {
  vec2 p = vec2(a.x * sectorScale.y, a.y / sectorScale.y);
  float r = length(p);
  if (sectorScale.z == 0.0 || r == 0.0) return p;
  float psi = atan(p.y, p.x);
  float normal = sectors.x + 2.0 * sectors.y * round((psi - sectors.x) / (2.0 * sectors.y));
  float theta = clamp(psi - normal, -sectors.y, sectors.y);
  float phi = normal - sectors.y + sectors.y * (twiceSectorArea(theta) + sectorScale.w) / sectorScale.w;
  return r / (sectorScale.x * (sectors.z / cos(theta) + sectors.w)) * vec2(cos(phi), sin(phi));
}

bool inCell(vec2 q) {
  float r2 = dot(q, q);
  if (squareBox.z > 0.0) {
    if (!(r2 <= 1.0)) return false;
    vec2 u = concentricSquare(q);
    return all(greaterThanEqual(u, squareBox.xy)) && all(lessThan(u, squareBox.zw));
  }
  if (!(r2 >= radii2.x && r2 < radii2.y)) return false;  // NaN is outside too
  if (wholeRing != 0) return true;
  return firstEdge.x * q.y - firstEdge.y * q.x >= 0.0 && q.x * lastEdge.y - q.y * lastEdge.x > 0.0;
}

// The slope of 1/Z along one axis: the one-sided difference of smaller size, so that a pixel at an
// edge takes it from its own side.
float slopeAlong(ivec2 x, ivec2 step, float here, ivec2 size) {
  ivec2 before = clamp(x - step, ivec2(0), size - 1), after = clamp(x + step, ivec2(0), size - 1);
  float back = here - inverseDepthAt(before), ahead = inverseDepthAt(after) - here;
  return abs(back) < abs(ahead) ? back : ahead;
}

// ∫ clamp(s, 0, w) ds from 0 to s.
float clampIntegral(float s, float w) { return s <= 0.0 ? 0.0 : s < w ? 0.5 * s * s : w * (s - 0.5 * w); }

// ∫ clamp(x − lo.x, 0, hi.x − lo.x) dy along the part of the segment a → b with y in [lo.y, hi.y].
// Summed over a convex polygon's edges it is the polygon's area inside the box (Green's theorem:
// at each height the edge going up and the one coming down bound the slice, clipped to the box).
float edgeIntegral(vec2 a, vec2 b, vec2 lo, vec2 hi) {
  float dy = b.y - a.y;
  if (dy == 0.0) return 0.0;
  float t0 = clamp((lo.y - a.y) / dy, 0.0, 1.0), t1 = clamp((hi.y - a.y) / dy, 0.0, 1.0);
  float ta = min(t0, t1), tb = max(t0, t1);
  float w = hi.x - lo.x;
  float xa = a.x + (b.x - a.x) * ta - lo.x, xb = a.x + (b.x - a.x) * tb - lo.x;
  float dx = xb - xa;
  float mean = abs(dx) > 1e-4 ? (clampIntegral(xb, w) - clampIntegral(xa, w)) / dx : clamp(0.5 * (xa + xb), 0.0, w);
  return dy * (tb - ta) * mean;
}

// The area of the parallelogram o ± a ± b inside the box [lo, hi].
float overlapArea(vec2 o, vec2 a, vec2 b, vec2 lo, vec2 hi) {
  vec2 v0 = o - a - b, v1 = o + a - b, v2 = o + a + b, v3 = o - a + b;
  return abs(edgeIntegral(v0, v1, lo, hi) + edgeIntegral(v1, v2, lo, hi) + edgeIntegral(v2, v3, lo, hi) +
             edgeIntegral(v3, v0, lo, hi));
}

// The weight of a neighbour's image at this pixel, x − y = d: the share of the pixel it covers over
// the image's area (at most 1: an image smaller than a pixel stays whole in its own pixel).
float imageWeight(ivec2 d, mat2 m, float imageArea) {
  if (imageArea < kPointArea) return d == ivec2(0) ? 1.0 : 0.0;
  if (imageArea >= kFewSamplesArea) {
    return inCell(diskFromAperture(lensPoint + inverse(m) * vec2(d))) ? 1.0 / imageArea : 0.0;
  } else {
    // A small image is measured as its cell's moment rectangle (a parallelogram in the image): its
    // exact overlap with the pixel. A test at one point would jump between 0 and 1 (the image's
    // edges are pixel-sized) and the weights gathered would scatter; the overlaps of one image over
    // the pixel grid sum to its area, so on a surface the weights gathered sum to 1.
    vec2 o = m * (rectangleCentre - lensPoint), a = m * rectangleAxes.xy, b = m * rectangleAxes.zw;
    vec2 reach = abs(a) + abs(b) + 0.5;
    if (any(greaterThan(abs(vec2(d) - o), reach))) return 0.0;
    return overlapArea(o, a, b, vec2(d) - 0.5, vec2(d) + 0.5) / imageArea;
  }
}

void main() {
  ivec2 size = textureSize(viewDepth, 0);
  ivec2 x = ivec2(gl_FragCoord.xy) + marginPx;
  float here = inverseDepthAt(x);
  vec2 slope = vec2(slopeAlong(x, ivec2(1, 0), here, size), slopeAlong(x, ivec2(0, 1), here, size));
  float tolerance = 0.1 * abs(here) + abs(slope.x) + abs(slope.y);
  // Nearer, the same surface, farther: named, not an array (a dynamically indexed array costs a
  // trip through memory on a CPU rasterizer).
  vec4 nearer = vec4(0.0), same = vec4(0.0), farther = vec4(0.0);
  float nearerCover = 0.0, sameCover = 0.0, fartherCover = 0.0;
  for (int dy = displacements.y; dy <= displacements.w; ++dy) {
    for (int dx = displacements.x; dx <= displacements.z; ++dx) {
      ivec2 d = ivec2(dx, dy), y = x - d;
      if (any(lessThan(y, ivec2(0))) || any(greaterThanEqual(y, size))) continue;
      float inverseDepth = inverseDepthAt(y);
      float off = inverseDepth - (here + dot(slope, vec2(y - x)));
      mat2 m = mat2(spreadAtInfinity + inverseDepth * spreadPerInverseDepth);
      float imageArea = abs(determinant(m)) * cellArea;
      float w = imageWeight(d, m, imageArea);
      if (w == 0.0) continue;
      vec4 c = w * texelFetch(views, ivec3(y, 0), 0);
      if (off > tolerance) {
        nearer += c;
        nearerCover += w;
      } else if (off < -tolerance) {
        farther += c;
        fartherCover += w;
      } else {
        same += c;
        sameCover += w;
      }
    }
  }
  // Front to back: each layer covers what the layers before it leave, by its own coverage. What no
  // layer covers is what this view cannot see: the farther surface that the rest of its cell would
  // see past an edge this view shows. That shortfall is summed apart (holes), and resolve.frag
  // (CELL_FILL) fills it with the farthest surface the views saw at the pixel: each view adds its
  // own surface's colour weighted by (Z / Z_ref)^8, a soft maximum over depth. (Where the views all
  // see one surface that is the surface itself, and the fill only evens out how the images fall
  // on the pixel grid.)
  vec4 colour = vec4(0.0);
  float covered = 0.0;
  if (nearerCover > 0.0) {
    covered = min(nearerCover, 1.0);
    colour = covered * nearer / nearerCover;
  }
  if (sameCover <= 0.0) {  // its own image missed every sample point of the pixel: a sliver
    same = texelFetch(views, ivec3(x, 0), 0);
    sameCover = 1.0;
  }
  float share = (1.0 - covered) * min(sameCover, 1.0);
  colour += share * same / sameCover;
  covered += share;
  if (fartherCover > 0.0) {
    share = (1.0 - covered) * min(fartherCover, 1.0);
    colour += share * farther / fartherCover;
    covered += share;
  }
  float ownArea = abs(determinant(mat2(spreadAtInfinity + here * spreadPerInverseDepth))) * cellArea;
  float hole = ownArea >= kHoleArea ? 1.0 - covered : 0.0;
  sum = weight * colour;
  weightOut = weight * covered;
  holeOut = weight * hole;
  // Depth ratios beyond 100 weigh alike: (10^2)^8 times a bright environment's radiance, summed over
  // 65536 views, stays far inside a float.
  float depthRatio = clamp(1.0 / (max(here, 1e-30) * depthReference), 1e-2, 1e2);
  float farness = pow(depthRatio, 8.0);
  behindOut = farness * vec4(weight.rgb * same.rgb / sameCover, (weight.r + weight.g + weight.b) / 3.0);
}
