#include "scene/Environment.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace lenslab {

namespace {

// shaders/common/environment.glsl as C++: glm's names are GLSL's, and environmentTexel, which the
// GLSL takes from its samplers, reads the maps here. Compiled inside a class so that the included
// functions see it.
struct EnvironmentGlsl {
  using vec2 = glm::vec2;
  using vec3 = glm::vec3;
  using ivec2 = glm::ivec2;
  static float atan(float y, float x) { return std::atan2(y, x); }
  static float sqrt(float x) { return std::sqrt(x); }
  static float floor(float x) { return std::floor(x); }
  static int clamp(int x, int lo, int hi) { return glm::clamp(x, lo, hi); }
  static float clamp(float x, float lo, float hi) { return glm::clamp(x, lo, hi); }
  static int min(int a, int b) { return glm::min(a, b); }
  static vec3 mix(const vec3& a, const vec3& b, float t) { return glm::mix(a, b, t); }

  const PrefilteredEnvironment* maps = nullptr;
  const EnvironmentImage* single = nullptr;  // sampleBilinear's one image

  vec3 environmentTexel(int map, int x, int y, int layer) const {
    // Only a direction that is not finite (a NaN's int) reaches outside; no read may.
    x = glm::clamp(x, 0, (single ? single->width : mapWidth(map)) - 1);
    y = glm::clamp(y, 0, (single ? single->height : mapHeight(map)) - 1);
    if (single) return single->at(x, y);
    if (map == kEnvironmentSpecular) layer = glm::clamp(layer, 0, static_cast<int>(maps->specular.size()) - 1);
    if (map == kEnvironmentBackground) return maps->background.at(x, y);
    if (map == kEnvironmentDiffuse) return maps->diffuse.at(x, y);
    return maps->specular[static_cast<std::size_t>(layer)].at(x, y);
  }

  const EnvironmentImage& mapImage(int map) const {
    return map == kEnvironmentBackground ? maps->background
           : map == kEnvironmentDiffuse  ? maps->diffuse
                                         : maps->specular.front();
  }
  int mapWidth(int map) const { return mapImage(map).width; }
  int mapHeight(int map) const { return mapImage(map).height; }

#include "../../shaders/common/environment.glsl"

  EnvironmentParams params(glm::vec2 rotation, float intensity) const {
    EnvironmentParams p;
    p.rotation = rotation;
    p.intensity = intensity;
    p.backgroundSize = {maps->background.width, maps->background.height};
    const EnvironmentImage& s = maps->specular.empty() ? maps->background : maps->specular.front();
    p.specularSize = {s.width, s.height};
    p.diffuseSize = {maps->diffuse.width, maps->diffuse.height};
    p.specularLevels = maps->specularLevels();
    return p;
  }
};

EnvironmentGlsl::EnvironmentParams unturned() {
  EnvironmentGlsl::EnvironmentParams p{};
  p.rotation = {1.0f, 0.0f};
  p.intensity = 1.0f;
  return p;
}

}  // namespace

glm::vec2 uvFromDirection(const glm::vec3& direction) { return EnvironmentGlsl{}.environmentUv(unturned(), direction); }

glm::vec3 directionFromUv(const glm::vec2& uv) {
  const double phi = (uv.x - 0.5) * 2.0 * std::numbers::pi;
  const double theta = uv.y * std::numbers::pi;
  return glm::vec3(glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)));
}

glm::vec3 sampleBilinear(const EnvironmentImage& image, const glm::vec2& uv) {
  EnvironmentGlsl glsl;
  glsl.single = &image;
  return glsl.environmentBilinear(0, 0, {image.width, image.height}, uv);
}

double texelSolidAngle(int y, int width, int height) {
  const double top = std::numbers::pi * y / height, bottom = std::numbers::pi * (y + 1) / height;
  return 2.0 * std::numbers::pi / width * (std::cos(top) - std::cos(bottom));
}

EnvironmentLookup::EnvironmentLookup(std::shared_ptr<const PrefilteredEnvironment> maps,
                                     const EnvironmentPlacement& placement)
    : maps_(std::move(maps)), placement_(placement) {
  assert(maps_ && maps_->specularLevels() >= 2);
  const double radians = placement.rotationDegrees * std::numbers::pi / 180.0;
  rotation_ = {static_cast<float>(std::cos(radians)), static_cast<float>(std::sin(radians))};
}

glm::vec3 EnvironmentLookup::background(const glm::vec3& direction) const {
  EnvironmentGlsl glsl;
  glsl.maps = maps_.get();
  return glsl.environmentBackground(glsl.params(rotation_, placement_.intensity), direction);
}

glm::vec3 EnvironmentLookup::diffuse(const glm::vec3& normal) const {
  EnvironmentGlsl glsl;
  glsl.maps = maps_.get();
  return glsl.environmentDiffuse(glsl.params(rotation_, placement_.intensity), normal);
}

glm::vec3 EnvironmentLookup::specular(const glm::vec3& reflected, float perceptualRoughness) const {
  EnvironmentGlsl glsl;
  glsl.maps = maps_.get();
  return glsl.environmentSpecular(glsl.params(rotation_, placement_.intensity), reflected, perceptualRoughness);
}

}  // namespace lenslab
