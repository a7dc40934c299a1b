#version 450 core
// Shows a linear float image in a rectangle of the window: scaled to fit (the caller keeps the
// aspect ratio), exposed and through a view transform as PNG files are (io/ToneMap.h), then
// sRGB-encoded because the window's framebuffer is 8-bit and not sRGB-aware.
#include "../common/view_transform.glsl"

layout(binding = 0) uniform sampler2D image;
layout(location = 0) uniform vec4 viewportRect;  // x, y, width, height in framebuffer pixels (GL origin)
layout(location = 1) uniform int encodeSrgb;
layout(location = 2) uniform float gain;         // < 1 dims the scene under the outside view's diagram
layout(location = 3) uniform float exposureScale;  // io/ToneMap.h's DisplayEncoding
layout(location = 4) uniform int viewTransform;    // view_transform.glsl's kViewTransform*
layout(location = 0) out vec4 fragColor;

vec3 srgbFromLinear(vec3 c) {
  c = clamp(c, 0.0, 1.0);  // (a no-op after viewTransformed; kept for encodeSrgb's other callers)
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
  vec2 uv = (gl_FragCoord.xy - viewportRect.xy) / viewportRect.zw;
  vec3 c = viewTransformed(exposureScale * (gain * texture(image, uv).rgb), viewTransform);
  fragColor = vec4(encodeSrgb != 0 ? srgbFromLinear(c) : c, 1.0);
}
