#version 450 core
// Adds a batch of aperture views into the running sum (blending ONE, ONE into an RGBA32F target).
// The lecture: "compute color along every deflected ray, average the results" — the sum here,
// the division in resolve.frag. Views are rendered into the layers of an array texture and summed
// a batch at a time, so that the scene passes of a batch need not wait for one another.
// Each view has a weight per channel: 1 for a full view; with axial chromatic aberration each
// aperture point gives three views, each focused for one colour and adding only that colour.
#include "../common/locations.glsl"
layout(binding = 0) uniform sampler2DArray views;
layout(location = LOCATION_ACCUMULATE_VIEW_COUNT) uniform int viewCount;
layout(location = LOCATION_ACCUMULATE_WEIGHTS) uniform vec4 weights[ACCUMULATE_MAX_BATCH];
#ifdef FIELD_CURVATURE
// The lecture's "curved focal plane" (see src/render/Accumulator.h): pixel x of a view focused on
// the curved surface is what the flat-focused view shows at x − shift·r(x)², r the normalised
// radius of x. Sampled with Catmull–Rom.
layout(location = LOCATION_ACCUMULATE_SHIFT_PER_RADIUS2) uniform vec2 shiftPerRadius2[ACCUMULATE_MAX_BATCH];
#endif
#if defined(FIELD_CURVATURE) || defined(BARREL)
// Normalised image coordinates (the pinhole ray's x/z, y/z) of GL pixel corner (0, 0), and their step.
layout(location = LOCATION_ACCUMULATE_NORMALISED_AT_ORIGIN) uniform vec2 normalisedAtOrigin;
layout(location = LOCATION_ACCUMULATE_NORMALISED_PER_PIXEL) uniform vec2 normalisedPerPixel;
#endif
#ifdef BARREL
// Cat's-eye vignetting (src/lens/LensBarrel.h): the ray from view i's aperture point toward
// direction n crosses the barrel's opening at barrelLens[i] + barrelReach·n, in units of the
// opening's radius; outside it the barrel stops the ray and the view adds nothing there.
layout(location = LOCATION_ACCUMULATE_BARREL_LENS) uniform vec2 barrelLens[ACCUMULATE_MAX_BATCH];
layout(location = LOCATION_ACCUMULATE_BARREL_REACH) uniform float barrelReach;
// Each view's sub-pixel jitter (view pixels): view i's texel at p shows the scene at p + jitter[i],
// and that is the ray the barrel tests, so that a pixel's share converges to its area's (a
// barrel whose opening passes less than a pixel is not point-sampled at the pixel centre).
layout(location = LOCATION_GATHER_JITTER) uniform vec2 jitter[ACCUMULATE_MAX_BATCH];
#endif
layout(location = 0) out vec4 sum;
#ifdef BARREL
// Per pixel, the weight each channel received (resolve.frag's PER_PIXEL_WEIGHT): a view the
// barrel stops counts in the colour's (it brings no light: the cat's eye darkens the pixel) but
// not in alpha's (coverage is the share of the rays the lens passes that meet a surface).
layout(location = 1) out vec4 weight;
#endif

#ifdef FIELD_CURVATURE
#include "../common/catmull_rom.glsl"

// Layer `layer` at pixel position p, Catmull–Rom (bilinear would blur every view by its
// fractional shift).
vec4 catmullRom(vec2 p, int layer) {
  ivec2 first;
  vec2 w[4];
  catmullRomTaps(p, first, w);
  ivec2 last = textureSize(views, 0).xy - 1;
  vec4 s = vec4(0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      s += w[i].x * w[j].y * texelFetch(views, ivec3(clamp(first + ivec2(i, j), ivec2(0), last), layer), 0);
  return s;
}
#endif

// 1 where view i's aperture point reaches this pixel, whose value comes from the view's position
// `viewPx`; 0 where the barrel hides it. The barrel is tested at the view's own sample: a view
// is a perspective from its aperture point, so that position is the ray (with field curvature
// the pixel shows the view at x − shift·r², and the flat-focused ray through that position is the
// curved-focused ray through x: the same line from the same point).
float passes(int i, vec2 viewPx) {
#ifdef BARREL
  vec2 n = normalisedAtOrigin + (viewPx + jitter[i]) * normalisedPerPixel;
  vec2 atOpening = barrelLens[i] + barrelReach * n;
  if (dot(atOpening, atOpening) > 1.0) return 0.0;
#endif
  return 1.0;
}

void main() {
  vec4 total = vec4(0.0), w = vec4(0.0);
#ifdef FIELD_CURVATURE
  vec2 n = normalisedAtOrigin + gl_FragCoord.xy * normalisedPerPixel;
  float r2 = dot(n, n);
  for (int i = 0; i < viewCount; ++i) {
    vec2 viewPx = gl_FragCoord.xy - shiftPerRadius2[i] * r2;
    float p = passes(i, viewPx);
    total += p * weights[i] * catmullRom(viewPx, i);
    w += weights[i] * vec4(1.0, 1.0, 1.0, p);
  }
  total = max(total, vec4(0.0));
#else
  for (int i = 0; i < viewCount; ++i) {
    float p = passes(i, gl_FragCoord.xy);
    total += p * weights[i] * texelFetch(views, ivec3(gl_FragCoord.xy, i), 0);
    w += weights[i] * vec4(1.0, 1.0, 1.0, p);
  }
#endif
  sum = total;
#ifdef BARREL
  weight = w;
#endif
}
