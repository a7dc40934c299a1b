#pragma once
// The punctual lights a scene is shaded with, as both renderers hand them to brdf.glsl: the
// file's KHR_lights_punctual lights, or, where it has none and no environment lights it,
// lenslab's one default directional light (scene/Scene.h's Lighting), with positions relative to
// an origin near the viewer so that a scene far from the world origin keeps its precision.
#include "scene/Brdf.h"
#include "scene/Scene.h"

#include <vector>

namespace lenslab {

// The most punctual lights a scene may place: scene.frag's uniform arrays hold this many. The
// loader refuses more, naming the count.
constexpr int kMaxShadingLights = 8;

// The default light: directional along −lighting.toLight, of illuminance π · lighting.diffuse lux,
// so that a white Lambert surface facing it reflects radiance lighting.diffuse (the diffuse term
// of lenslab's former one-light model), before the specular reflection a dielectric adds.
PunctualLight defaultLight(const Lighting& lighting);

// The scene's lights (or the default one) in the form brdf.glsl takes, positions relative to
// `origin` (composed in double, then rounded).
std::vector<ShadingLight> shadingLights(const Scene& scene, const glm::dvec3& origin);

}  // namespace lenslab
