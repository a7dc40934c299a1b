#version 450 core
// The environment behind one view: drawn where the view's depth is still far (no surface), with
// each pixel's direction from this view's own inverse projection, so that jittered thin-lens
// views, the lens remap and the field-curvature warp treat it as they treat any surface.
#include "../common/environment_textures.glsl"

// World direction (not unit) of the ray through NDC (x, y): worldDirectionFromNdc · (x, y, 1).
layout(location = LOCATION_WORLD_DIRECTION_FROM_NDC) uniform mat3 worldDirectionFromNdc;
layout(location = LOCATION_NDC_PER_PIXEL) uniform vec2 ndcPerPixel;  // 2 / width, 2 / height of the target
// Colour weight per channel; alpha stays 0 (the background has no coverage). 1 for a plain view;
// an added view's weight when it is blended into a sum (render/Accumulator).
layout(location = LOCATION_BACKGROUND_WEIGHT) uniform vec3 weight;

layout(location = 0) out vec4 outColor;

void main() {
  vec2 ndc = gl_FragCoord.xy * ndcPerPixel - 1.0;
  vec3 direction = worldDirectionFromNdc * vec3(ndc, 1.0);
  outColor = vec4(weight * environmentBackground(environmentParams(), direction), 0.0);
}
