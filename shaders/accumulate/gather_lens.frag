#version 450 core
// Distortion and lateral colour, applied to each aperture view as it is summed (the lens pass of
// an accumulated frame). The lecture: "points are distorted geometrically from the true
// perspective position". Each view's texel t shows the true perspective image at one point,
// t + ½ + that view's jitter; the distortion carries that point to one place in the output image.
// An output pixel's value is the mean of the view samples that land inside it, each weighted by
// |det J| (the area its texel covers in the output). Over jittered views the samples of each view
// form a randomly shifted lattice, so these sums converge to the integral of the true image over
// the pixel's pre-image — the pixel integral of the distorted image — with no resampling filter
// to ring or blur, and the mean of samples never leaves the range of the scene's values.
#include "../common/locations.glsl"
layout(binding = 0) uniform sampler2DArray views;
layout(binding = 1) uniform sampler2D forwardPosition;  // per view texel: distorted x, y (output px); |det J|
layout(binding = 2) uniform sampler2D forwardJacobian;  // per view texel: ∂position/∂x (xy), ∂position/∂y (zw)
layout(binding = 3) uniform sampler2D greenMap;         // per output pixel: the view position it shows (texture coordinates)
#ifdef LATERAL_COLOUR
layout(binding = 4) uniform sampler2D redMap;
layout(binding = 5) uniform sampler2D blueMap;
#endif
layout(location = LOCATION_ACCUMULATE_VIEW_COUNT) uniform int viewCount;
layout(location = LOCATION_ACCUMULATE_WEIGHTS) uniform vec4 weights[ACCUMULATE_MAX_BATCH];
#ifdef FIELD_CURVATURE
layout(location = LOCATION_ACCUMULATE_SHIFT_PER_RADIUS2) uniform vec2 shiftPerRadius2[ACCUMULATE_MAX_BATCH];
layout(location = LOCATION_ACCUMULATE_NORMALISED_AT_ORIGIN) uniform vec2 normalisedAtOrigin;
layout(location = LOCATION_ACCUMULATE_NORMALISED_PER_PIXEL) uniform vec2 normalisedPerPixel;
#endif
layout(location = LOCATION_GATHER_JITTER) uniform vec2 jitter[ACCUMULATE_MAX_BATCH];  // each view's sub-pixel offset (view pixels, GL orientation)
layout(location = LOCATION_GATHER_REACH) uniform float reach;     // view pixels: see ForwardTable::reachPx
#ifdef LATERAL_COLOUR
layout(location = LOCATION_GATHER_PRINCIPAL_POINT) uniform vec2 principalPoint;  // output pixels, GL orientation
layout(location = LOCATION_GATHER_LATERAL_SCALE) uniform vec2 lateralScale;    // 1 + lateral, red and blue
#endif
#ifdef BARREL
// Cat's-eye vignetting (src/lens/LensBarrel.h), per sample: the ray of view i's texel t leaves
// aperture point p toward the true perspective position t + ½ + jitter (the flat-focused view's
// own position: a view is a perspective from p, so each of its positions is one ray, whatever
// the lens later does with it). That ray crosses the opening's plane, in units of the opening's
// radius, at barrelLens[i] + barrelAtOrigin + (t + ½ + jitter)·barrelPerPixel (= p·(1 − L/z_f)/R
// + (L/R)·n); outside the unit circle the barrel stops it. The distortion and lateral colour move
// where a sample lands, not which ray it is, so each channel's gather masks the same samples.
layout(location = LOCATION_GATHER_BARREL_AT_ORIGIN) uniform vec2 barrelAtOrigin;   // (L/R)·n at GL pixel corner (0, 0) of the views
layout(location = LOCATION_GATHER_BARREL_PER_PIXEL) uniform vec2 barrelPerPixel;   // (L/R)·n's step per view pixel
layout(location = LOCATION_GATHER_BARREL_LENS) uniform vec2 barrelLens[ACCUMULATE_MAX_BATCH];    // 62–69: p·(1 − L/z_f)/R per view
#endif
layout(location = 0) out vec4 sum;
layout(location = 1) out vec4 weight;

#ifdef FIELD_CURVATURE
// The lecture's "curved focal plane" (src/render/Accumulator.h): a view focused on the curved
// surface shows at x what the flat-focused view shows at x − shift·r(x)². So the flat view's
// sample at y belongs at y + shift·r(y)² (r² varies too slowly across a pixel's shift for the
// difference to matter): the warp moves each sample's position before the lens carries it on —
// nothing is resampled.
float radius2(vec2 p) {
  vec2 n = normalisedAtOrigin + p * normalisedPerPixel;
  return dot(n, n);
}
#endif

// 1 where the barrel lets view i's sample of texel t through, 0 where it stops it.
float passes(ivec2 t, int i) {
#ifdef BARREL
  vec2 atOpening = barrelLens[i] + barrelAtOrigin + (vec2(t) + 0.5 + jitter[i]) * barrelPerPixel;
  return dot(atOpening, atOpening) > 1.0 ? 0.0 : 1.0;
#else
  return 1.0;
#endif
}

// What a sample of view i that the barrel passes (`through` 1) or stops (0) adds to the weights:
// a stopped sample still counts in the colour's weight (a ray that brings no light: the cat's eye
// darkens the pixel, as the ray caster's), but not in alpha's: coverage is the share of the rays
// the lens passes that meet a surface.
vec4 weightOf(int i, float through) {
  return weights[i] * vec4(1.0, 1.0, 1.0, through);
}

// One sample: view `i`'s texel t, landing at `landed` in the output. Adds it when it lands inside
// this pixel (a sample exactly on an edge: measure zero), and remembers the nearest.
void visit(ivec2 t, int i, float area, vec2 landed, inout vec4 s, inout vec4 w, inout float nearest,
           inout ivec3 nearestSample) {
  vec2 d = landed - gl_FragCoord.xy;
  if (max(abs(d.x), abs(d.y)) < 0.5) {
    float through = passes(t, i);
    s += area * weights[i] * through * texelFetch(views, ivec3(t, i), 0);
    w += area * weightOf(i, through);
  }
  float d2 = dot(d, d);
  if (d2 < nearest) {
    nearest = d2;
    nearestSample = ivec3(t, i);
  }
}

// Where texel t's sample of view i lands: its centre's distorted position carried by the
// Jacobian over the sample's offset (jitter, and the field-curvature shift), then the channel's
// magnification about the principal point.
vec2 land(vec4 p, vec4 j, vec2 offset, float scale) {
  vec2 landed = p.xy + mat2(j.xy, j.zw) * offset;
#ifdef LATERAL_COLOUR
  landed = principalPoint + scale * (landed - principalPoint);
#endif
  return landed;
}

// The weighted sums of this pixel's samples, for one channel's mapping: `centre` is the view
// position (view pixels) whose distorted image is this pixel's centre, `scale` the channel's
// magnification about the principal point (1 for green). Only texels within `reach` can send a
// jittered sample here: |t + ½ − centre| ≤ reach − ½ per axis. Where the lens magnifies, a batch
// may land no sample in a pixel: its nearest sample still counts, with a weight (1e-6) that any
// real sample outweighs, so that no pixel is ever left without a value. With lateral colour each
// channel gathers only the views that carry it (`channel`; −1: every view): with axial colour
// too, a view focused for red adds nothing to green's or blue's sums.
void gather(vec2 centre, float scale, int channel, out vec4 s, out vec4 w) {
  s = vec4(0.0);
  w = vec4(0.0);
  ivec2 last = textureSize(forwardPosition, 0) - 1;
  float nearest = 1e30;
  ivec3 nearestSample = ivec3(0);
#ifdef FIELD_CURVATURE
  // Each view's samples are shifted by its own amount: each view gets its own window.
  float centreRadius2 = radius2(centre);
  for (int i = 0; i < viewCount; ++i) {
    if (channel >= 0 && weights[i][channel] == 0.0) continue;
    vec2 c = centre - shiftPerRadius2[i] * centreRadius2;
    ivec2 lo = clamp(ivec2(ceil(c - reach)), ivec2(0), last);
    ivec2 hi = clamp(ivec2(floor(c + reach - 1.0)), ivec2(0), last);
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        ivec2 t = ivec2(x, y);
        vec4 p = texelFetch(forwardPosition, t, 0);
        vec2 offset = jitter[i] + shiftPerRadius2[i] * radius2(vec2(t) + 0.5);
        visit(t, i, p.z, land(p, texelFetch(forwardJacobian, t, 0), offset, scale), s, w, nearest, nearestSample);
      }
  }
#else
  ivec2 lo = clamp(ivec2(ceil(centre - reach)), ivec2(0), last);
  ivec2 hi = clamp(ivec2(floor(centre + reach - 1.0)), ivec2(0), last);
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      ivec2 t = ivec2(x, y);
      vec4 p = texelFetch(forwardPosition, t, 0);
      vec4 j = texelFetch(forwardJacobian, t, 0);
      for (int i = 0; i < viewCount; ++i) {
        if (channel >= 0 && weights[i][channel] == 0.0) continue;
        visit(t, i, p.z, land(p, j, jitter[i], scale), s, w, nearest, nearestSample);
      }
    }
#endif
  if (nearest < 1e30) {
    float through = passes(nearestSample.xy, nearestSample.z);
    s += 1e-6 * weights[nearestSample.z] * through * texelFetch(views, ivec3(nearestSample.xy, nearestSample.z), 0);
    w += 1e-6 * weightOf(nearestSample.z, through);
  }
}

void main() {
  vec2 viewSize = vec2(textureSize(forwardPosition, 0));
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 s, w;
#ifdef LATERAL_COLOUR
  gather(texelFetch(greenMap, pixel, 0).xy * viewSize, 1.0, 1, s, w);  // alpha from green's views
  vec4 sr, wr, sb, wb;
  gather(texelFetch(redMap, pixel, 0).xy * viewSize, lateralScale.x, 0, sr, wr);
  gather(texelFetch(blueMap, pixel, 0).xy * viewSize, lateralScale.y, 2, sb, wb);
  s = vec4(sr.r, s.g, sb.b, s.a);
  w = vec4(wr.r, w.g, wb.b, w.a);
#else
  gather(texelFetch(greenMap, pixel, 0).xy * viewSize, 1.0, -1, s, w);
#endif
  sum = s;
  weight = w;
}
