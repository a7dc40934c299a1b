#pragma once
// The ray caster's AOV images (core/Aovs.h, `capture --aov`): for each pixel centre, what the
// first surface seen through it from the lens centre is, through the frame's image map
// (camera/ImageMap.h), so that the AOVs line up with the image the map's rays make (with lens
// effects, each pixel is first taken back through the inverse lens model, green's). One ray per
// pixel: not averaged over the pixel or the aperture. Rows from the top.
#include "camera/ImageMap.h"
#include "core/Aovs.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <functional>
#include <limits>

namespace lenslab {

// What one pixel's ray sees first (RayCaster: the nearest surface with alpha ≥ its AOV threshold).
struct AovSurface {
  bool surface = false;                                    // false: the background
  double depth = std::numeric_limits<double>::infinity();  // along the optical axis (−n) from the lens centre
  glm::vec3 normal{0.0f};                                  // the normal it is shaded with, world, unit
  glm::vec3 albedo{0.0f};                                  // its base colour, linear RGB
  int gltfNode = -1;                                       // the glTF node of its instance
};

// Throws InputError naming the scene when the instance AOV cannot hold one of its node indices
// exactly (beyond 2^24, float's last exact integer).
void requireExactInstances(const Scene& scene);

// The selected images, `firstSurface(pixelCentre)` asked for every pixel on every core; normals
// in camera space (u, v, n: right, up, toward the viewer).
AovImages aovImagesThrough(const ImageMap& map, const AovSelection& selection,
                           const std::function<AovSurface(glm::dvec2 pixel)>& firstSurface);

}  // namespace lenslab
