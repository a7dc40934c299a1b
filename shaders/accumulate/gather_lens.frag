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
layout(binding = 0) uniform sampler2DArray views;
layout(binding = 1) uniform sampler2D forwardPosition;  // per view texel: distorted x, y (output px); |det J|
layout(binding = 2) uniform sampler2D forwardJacobian;  // per view texel: ∂position/∂x (xy), ∂position/∂y (zw)
layout(binding = 3) uniform sampler2D greenMap;         // per output pixel: the view position it shows (texture coordinates)
#ifdef LATERAL_COLOUR
layout(binding = 4) uniform sampler2D redMap;
layout(binding = 5) uniform sampler2D blueMap;
#endif
layout(location = 0) uniform int viewCount;
layout(location = 1) uniform vec4 weights[8];
#ifdef FIELD_CURVATURE
layout(location = 9) uniform vec2 shiftPerRadius2[8];
layout(location = 17) uniform vec2 normalisedAtOrigin;
layout(location = 18) uniform vec2 normalisedPerPixel;
#endif
layout(location = 19) uniform vec2 jitter[8];  // each view's sub-pixel offset (view pixels, GL orientation)
layout(location = 27) uniform float reach;     // view pixels: see ForwardTable::reachPx
#ifdef LATERAL_COLOUR
layout(location = 28) uniform vec2 principalPoint;  // output pixels, GL orientation
layout(location = 29) uniform vec2 lateralScale;    // 1 + lateral, red and blue
#endif
layout(location = 0) out vec4 sum;
layout(location = 1) out vec4 weight;

#ifdef FIELD_CURVATURE
#include "../common/catmull_rom.glsl"

// The field-curvature warp of view `layer` (accumulate.frag): Catmull–Rom at p.
vec4 catmullRom(vec2 p, int layer) {
  ivec2 first;
  vec2 w[4];
  catmullRomTaps(p, first, w);
  ivec2 last = textureSize(views, 0).xy - 1;
  vec4 s = vec4(0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      s += w[i].x * w[j].y * texelFetch(views, ivec3(clamp(first + ivec2(i, j), ivec2(0), last), layer), 0);
  return max(s, vec4(0.0));
}
#endif

// View `i` at texel t (through the field-curvature warp when there is one).
vec4 viewAt(ivec2 t, int i) {
#ifdef FIELD_CURVATURE
  vec2 n = normalisedAtOrigin + (vec2(t) + 0.5) * normalisedPerPixel;
  return catmullRom(vec2(t) + 0.5 - shiftPerRadius2[i] * dot(n, n), i);
#else
  return texelFetch(views, ivec3(t, i), 0);
#endif
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
  ivec2 lo = clamp(ivec2(ceil(centre - reach)), ivec2(0), last);
  ivec2 hi = clamp(ivec2(floor(centre + reach - 1.0)), ivec2(0), last);
  float nearest = 1e30;
  ivec3 nearestSample = ivec3(0);
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      ivec2 t = ivec2(x, y);
      vec4 p = texelFetch(forwardPosition, t, 0);
      vec4 j = texelFetch(forwardJacobian, t, 0);
      mat2 jacobian = mat2(j.xy, j.zw);
      for (int i = 0; i < viewCount; ++i) {
        if (channel >= 0 && weights[i][channel] == 0.0) continue;
        vec2 landed = p.xy + jacobian * jitter[i];
#ifdef LATERAL_COLOUR
        landed = principalPoint + scale * (landed - principalPoint);
#endif
        vec2 d = landed - gl_FragCoord.xy;
        if (max(abs(d.x), abs(d.y)) < 0.5) {  // inside this pixel (a sample exactly on an edge: measure zero)
          vec4 share = weights[i] * p.z;
          s += share * viewAt(t, i);
          w += share;
        }
        float d2 = dot(d, d);
        if (d2 < nearest) {
          nearest = d2;
          nearestSample = ivec3(t, i);
        }
      }
    }
  if (nearest < 1e30) {
    s += 1e-6 * weights[nearestSample.z] * viewAt(nearestSample.xy, nearestSample.z);
    w += 1e-6 * weights[nearestSample.z];
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
