#pragma once
// The scene programs' uniforms (shaders/scene/scene.vert, narrow_field.vert, scene.frag; their
// locations and texture units in shaders/common/locations.glsl): the lights and surround of a
// view, and the transforms and material of one instance, with its textures bound.
#include "gl/Object.h"
#include "render/GpuScene.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace lenslab {

// Where a view shades from: its eye for a perspective view; a parallel view has none, so a point
// near the scene serves as the origin and `towardViewer` is the constant way back along its rays.
// Shading positions and lights are relative to `origin` (composed in double), so that a scene far
// from the world origin keeps its precision.
struct ShadingView {
  glm::dvec3 origin{0.0};
  glm::vec3 towardViewer{0.0f, 0.0f, 1.0f};
  bool parallel = false;
};

// The view's punctual lights (scene/ShadingLights.h), the uniform surround, the direction toward
// the viewer, and `lodBias`, added to the textures' level of detail (scene.frag says why).
void setLightingUniforms(GLuint program, const Scene& scene, const ShadingView& view, float lodBias);

// Everything of `instance` that scene.vert and scene.frag take: its transforms (clipFromModel in
// double for the `narrow` field path), and its material as the ray caster shades it
// (scene/ShadeSurface.h's surfaceMaterial) with its textures bound; with `maps`, the
// MATERIAL_MAPS variant's uv sets, uv transforms and normal map too.
void setInstanceUniforms(GLuint program, const GpuScene& gpuScene, const Instance& instance,
                         const glm::dmat4& clipFromWorld, bool narrow, const ShadingView& view, bool maps);

// glTF's default material, for a mesh without one: white, lit, opaque, single-sided.
const Material& materialOf(const Scene& scene, const Mesh& mesh);

}  // namespace lenslab
