#include "scene/ShadingLights.h"

namespace lenslab {

PunctualLight defaultLight(const Lighting& lighting) {
  PunctualLight light;
  light.name = "lenslab default";
  light.type = LightType::Directional;
  light.intensity = 3.14159265358979f * lighting.diffuse;
  light.worldDirection = -glm::dvec3(lighting.toLight);
  return light;
}

std::vector<ShadingLight> shadingLights(const Scene& scene, const glm::dvec3& origin) {
  std::vector<ShadingLight> out;
  const auto add = [&](const PunctualLight& l) {
    ShadingLight s;
    s.type = static_cast<int>(l.type);
    s.intensity = l.color * l.intensity;
    s.position = glm::vec3(l.worldPosition - origin);
    s.direction = glm::vec3(glm::normalize(l.worldDirection));
    s.range = static_cast<float>(l.range);
    const glm::vec2 cone = spotScaleOffset(l.innerConeAngleRadians, l.outerConeAngleRadians);
    s.spotScale = cone.x;
    s.spotOffset = cone.y;
    out.push_back(s);
  };
  // An environment lights the scene itself: the default light is for scenes with neither.
  if (scene.lights.empty() && !scene.environment) add(defaultLight(scene.lighting));
  for (const PunctualLight& l : scene.lights) add(l);
  return out;
}

}  // namespace lenslab
