// The environment's maps and placement as the scene's programs see them (render/GpuEnvironment
// binds them), and the lookups of environment.glsl on them:
//   environmentBackground(environmentParams(), direction)
//   environmentDiffuse(environmentParams(), normal)
//   environmentSpecular(environmentParams(), reflected, perceptualRoughness)
// Call them only where hasEnvironment is true: without an environment no texture is bound.
// Locations 100–119 and texture units 5–8 are the environment's (locations.glsl).
#include "locations.glsl"
layout(binding = UNIT_ENVIRONMENT_BACKGROUND) uniform sampler2D environmentBackgroundMap;
layout(binding = UNIT_ENVIRONMENT_SPECULAR) uniform sampler2DArray environmentSpecularMap;
layout(binding = UNIT_ENVIRONMENT_DIFFUSE) uniform sampler2D environmentDiffuseMap;
layout(location = LOCATION_ENVIRONMENT_ROTATION) uniform vec2 environmentRotation;  // cos, sin of the turn about +Y
layout(location = LOCATION_ENVIRONMENT_INTENSITY) uniform float environmentIntensity;
layout(location = LOCATION_ENVIRONMENT_LEVELS) uniform int environmentLevels;  // roughness levels, level 0 included
layout(location = LOCATION_HAS_ENVIRONMENT) uniform bool hasEnvironment;

// Fetches only (no GPU filtering): environment.glsl interpolates, as the C++ does.
vec3 environmentTexel(int map, int x, int y, int layer) {
  if (map == 0) return texelFetch(environmentBackgroundMap, ivec2(x, y), 0).rgb;
  if (map == 1) return texelFetch(environmentSpecularMap, ivec3(x, y, layer), 0).rgb;
  return texelFetch(environmentDiffuseMap, ivec2(x, y), 0).rgb;
}

#include "environment.glsl"

EnvironmentParams environmentParams() {
  return EnvironmentParams(environmentRotation, environmentIntensity, textureSize(environmentBackgroundMap, 0),
                           textureSize(environmentSpecularMap, 0).xy, textureSize(environmentDiffuseMap, 0),
                           environmentLevels);
}
