#pragma once
// An environment: the radiance arriving from every direction at infinity, as an equirectangular
// linear-RGB image, turned about world +Y and scaled. Pure data and math (GLM + std), no GL.
//
// Convention (the same in shaders/common/environment.glsl, which defines the lookups for both
// renderers): the image's centre, u = 0.5, is the direction −Z (what a default camera looks at);
// u grows towards +X (u = 0.75) and wraps at +Z (u = 0 and 1); the top row, v = 0, is +Y, the
// bottom row −Y. Seen from inside, looking along −Z with +Y up, the image is not mirrored.
// Texel (x, y) of a W × H image covers u in [x, x + 1] / W and v in [y, y + 1] / H; lookups are
// bilinear between texel centres, columns wrapping across the seam, rows clamped at the poles.
//
// Rotation: an environment turned by θ degrees about +Y (right-handed: at 90° the image centre
// is seen towards −X) shows at world direction d what the unturned image holds at R_y(−θ)·d.
#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace lenslab {

// Linear RGB radiance, rows from the top (+Y).
struct EnvironmentImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> rgb;  // width × height
  const glm::vec3& at(int x, int y) const {
    return rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  glm::vec3& at(int x, int y) {
    return rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

// How the environment is placed in the world (--environment-rotation, --environment-intensity).
struct EnvironmentPlacement {
  double rotationDegrees = 0.0;  // about world +Y
  float intensity = 1.0f;        // multiplies the radiance, ≥ 0
};

// (u, v) of the unturned image for a world direction (need not be unit), and back (unit).
glm::vec2 uvFromDirection(const glm::vec3& direction);
glm::vec3 directionFromUv(const glm::vec2& uv);

// The image's radiance at (u, v), bilinear as above (the shaders' own interpolation).
glm::vec3 sampleBilinear(const EnvironmentImage& image, const glm::vec2& uv);

// The solid angle (steradians) of a texel of row y of an equirectangular W × H image.
double texelSolidAngle(int y, int width, int height);

// The smallest perceptual roughness the shading uses (brdf.glsl's kMinPerceptualRoughness, asserted
// equal to environment.glsl's kEnvironmentMinRoughness in Environment.cpp).
constexpr double kEnvironmentMinRoughness = 0.045;
// Perceptual roughness of specular level `level` of `levels`: kEnvironmentMinRoughness … 1, evenly.
inline double environmentLevelRoughness(int level, int levels) {
  return kEnvironmentMinRoughness + (1.0 - kEnvironmentMinRoughness) * static_cast<double>(level) / (levels - 1);
}

// The environment prefiltered for image-based lighting (scene/EnvironmentPrefilter.h makes it).
struct PrefilteredEnvironment {
  EnvironmentImage background;             // the source: seen straight, and level 0 (roughness ≤ 0.045)
  std::vector<EnvironmentImage> specular;  // roughness levels 1 … n − 1, all of one size
  EnvironmentImage diffuse;                // irradiance / π
  int specularLevels() const { return static_cast<int>(specular.size()) + 1; }
  // Perceptual roughness of level l: evenly spaced from kEnvironmentMinRoughness (level 0, the
  // source image standing for the smoothest surface the shading draws) to 1 (the last).
  double levelRoughness(int level) const { return environmentLevelRoughness(level, specularLevels()); }
};

// The three lookups both renderers use (shaders/common/environment.glsl, compiled here as C++),
// with the placement applied inside: what the GLSL returns for the same arguments.
class EnvironmentLookup {
 public:
  EnvironmentLookup(std::shared_ptr<const PrefilteredEnvironment> maps, const EnvironmentPlacement& placement);
  // Radiance seen straight along `direction`, × intensity.
  glm::vec3 background(const glm::vec3& direction) const;
  // Irradiance / π on a surface facing `normal`, × intensity: what a white Lambertian surface shows.
  glm::vec3 diffuse(const glm::vec3& normal) const;
  // Radiance around `reflected` prefiltered by GGX of `perceptualRoughness` (0 … 1), × intensity.
  glm::vec3 specular(const glm::vec3& reflected, float perceptualRoughness) const;

  const PrefilteredEnvironment& maps() const { return *maps_; }
  const EnvironmentPlacement& placement() const { return placement_; }
  // cos and sin of the rotation, as the shaders take them (computed once, here).
  glm::vec2 rotationCosSin() const { return rotation_; }

 private:
  std::shared_ptr<const PrefilteredEnvironment> maps_;
  EnvironmentPlacement placement_;
  glm::vec2 rotation_{1.0f, 0.0f};
};

}  // namespace lenslab
