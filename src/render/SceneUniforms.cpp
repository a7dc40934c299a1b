#include "render/SceneUniforms.h"

#include "scene/ShadeSurface.h"
#include "scene/ShadingLights.h"

#include "../../shaders/common/locations.glsl"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab {
namespace {

static_assert(kMaxShadingLights == MAX_SHADING_LIGHTS, "scene.frag's light arrays hold MAX_SHADING_LIGHTS");

const Material kDefaultMaterial{};

// A texture slot's TEXCOORD set and KHR_texture_transform, into the uniforms from `texCoordLocation`.
void setTextureSlot(GLuint program, GLint texCoordLocation, const TextureRef& ref) {
  glProgramUniform1i(program, texCoordLocation, ref.texCoord);
  glProgramUniformMatrix3fv(program, texCoordLocation + 1, 1, GL_FALSE, glm::value_ptr(ref.uvFromTexCoord));
}

// worldFromModel's linear part scaled to its largest entry near 1 (tangents are normalised after,
// and a model scaled by 1e-20 would otherwise hand the shader tangents whose squares underflow).
glm::mat3 tangentFromModel(const glm::dmat3& linear) {
  double largest = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(linear[c][r]));
  return glm::mat3(largest > 0.0 && std::isfinite(largest) ? linear * (1.0 / largest) : linear);
}

// The same projection scaled to its largest entry near 1. Clip coordinates are homogeneous, so
// the image is unchanged, but a PRP 1e-100 from the view plane (entries of 1e100) no longer
// overflows float, nor one 1e100 away underflows it.
glm::dmat4 wellScaled(const glm::dmat4& m) {
  double largest = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) largest = std::max(largest, std::abs(m[c][r]));
  return largest > 0.0 && std::isfinite(largest) ? m * (1.0 / largest) : m;
}

// The MATERIAL_MAPS variant's uniforms: each texture slot's uv set and transform, and the normal
// map with its tangent frame (the file's tangents or generated ones, scene/Tangents.h).
void setMaterialMaps(GLuint program, const GpuScene& gpuScene, const Material& material, const SurfaceMaterial& surface,
                     const glm::dmat3& linear) {
  const std::pair<GLint, const TextureRef*> slots[] = {
      {LOCATION_BASE_COLOR_TEX_COORD, &material.baseColorTexture},
      {LOCATION_EMISSIVE_TEX_COORD, &material.emissiveTexture},
      {LOCATION_METALLIC_ROUGHNESS_TEX_COORD, &material.metallicRoughnessTexture},
      {LOCATION_OCCLUSION_TEX_COORD, &material.occlusionTexture}};
  for (const auto& [location, ref] : slots)
    if (ref->present()) setTextureSlot(program, location, *ref);
  glProgramUniform1i(program, LOCATION_HAS_NORMAL_TEXTURE, surface.normalMapped);
  if (!surface.normalMapped) return;
  gpuScene.bindLinearTexture(material.normalTexture.texture, UNIT_NORMAL);
  setTextureSlot(program, LOCATION_NORMAL_TEX_COORD, material.normalTexture);
  glProgramUniform1f(program, LOCATION_NORMAL_SCALE, surface.normalScale);
  glProgramUniformMatrix3fv(program, LOCATION_WORLD_TANGENT_FROM_MODEL, 1, GL_FALSE,
                            glm::value_ptr(tangentFromModel(linear)));
  glProgramUniform1f(program, LOCATION_HANDEDNESS_FROM_MODEL, glm::determinant(linear) < 0.0 ? -1.0f : 1.0f);
}

// shade_surface.glsl's SurfaceMaterial, field by field, and the textures it reads bound.
void setSurfaceMaterial(GLuint program, const GpuScene& gpuScene, const Material& material,
                        const SurfaceMaterial& surface) {
  glProgramUniform1f(program, LOCATION_METALLIC_FACTOR, surface.metallicFactor);
  glProgramUniform1f(program, LOCATION_ROUGHNESS_FACTOR, surface.roughnessFactor);
  glProgramUniform1f(program, LOCATION_OCCLUSION_STRENGTH, surface.occlusionStrength);
  glProgramUniform1i(program, LOCATION_HAS_METALLIC_ROUGHNESS_TEXTURE, surface.hasMetallicRoughnessTexture);
  if (surface.hasMetallicRoughnessTexture)
    gpuScene.bindLinearTexture(material.metallicRoughnessTexture.texture, UNIT_METALLIC_ROUGHNESS);
  glProgramUniform1i(program, LOCATION_HAS_OCCLUSION_TEXTURE, surface.hasOcclusionTexture);
  if (surface.hasOcclusionTexture) gpuScene.bindLinearTexture(material.occlusionTexture.texture, UNIT_OCCLUSION);
  glProgramUniform4fv(program, LOCATION_BASE_COLOR_FACTOR, 1, glm::value_ptr(surface.baseColorFactor));
  glProgramUniform1i(program, LOCATION_HAS_BASE_COLOR_TEXTURE, surface.hasBaseColorTexture);
  if (surface.hasBaseColorTexture) gpuScene.bindTexture(material.baseColorTexture.texture, UNIT_BASE_COLOR);
  glProgramUniform3fv(program, LOCATION_EMISSIVE, 1, glm::value_ptr(surface.emissive));
  glProgramUniform1i(program, LOCATION_HAS_EMISSIVE_TEXTURE, surface.hasEmissiveTexture);
  if (surface.hasEmissiveTexture) gpuScene.bindTexture(material.emissiveTexture.texture, UNIT_EMISSIVE);
  glProgramUniform1i(program, LOCATION_UNLIT, surface.unlit);
  glProgramUniform1i(program, LOCATION_ALPHA_MASK, surface.alphaMask);
  glProgramUniform1f(program, LOCATION_ALPHA_CUTOFF, surface.alphaCutoff);
  glProgramUniform1i(program, LOCATION_DOUBLE_SIDED, surface.doubleSided);
}

}  // namespace

const Material& materialOf(const Scene& scene, const Mesh& mesh) {
  return mesh.material >= 0 ? scene.materials[static_cast<std::size_t>(mesh.material)] : kDefaultMaterial;
}

void setLightingUniforms(GLuint program, const Scene& scene, const ShadingView& view, float lodBias) {
  glProgramUniform1f(program, LOCATION_AMBIENT, scene.lighting.ambient);
  glProgramUniform1f(program, LOCATION_LOD_BIAS, lodBias);
  glProgramUniform3fv(program, LOCATION_TOWARD_VIEWER, 1, glm::value_ptr(view.towardViewer));
  glProgramUniform1i(program, LOCATION_PARALLEL_VIEW, view.parallel);
  const std::vector<ShadingLight> lights = shadingLights(scene, view.origin);
  const std::size_t count = std::min(lights.size(), static_cast<std::size_t>(kMaxShadingLights));
  glm::vec4 positionRange[kMaxShadingLights], directionType[kMaxShadingLights];
  glm::vec3 intensity[kMaxShadingLights];
  glm::vec2 spot[kMaxShadingLights];
  for (std::size_t i = 0; i < count; ++i) {
    const ShadingLight& l = lights[i];
    positionRange[i] = glm::vec4(l.position, l.range);
    directionType[i] = glm::vec4(l.direction, static_cast<float>(l.type));
    intensity[i] = l.intensity;
    spot[i] = glm::vec2(l.spotScale, l.spotOffset);
  }
  const auto n = static_cast<GLsizei>(count);
  glProgramUniform1i(program, LOCATION_LIGHT_COUNT, n);
  if (n > 0) {
    glProgramUniform4fv(program, LOCATION_LIGHT_POSITION_RANGE, n, glm::value_ptr(positionRange[0]));
    glProgramUniform4fv(program, LOCATION_LIGHT_DIRECTION_TYPE, n, glm::value_ptr(directionType[0]));
    glProgramUniform3fv(program, LOCATION_LIGHT_INTENSITY, n, glm::value_ptr(intensity[0]));
    glProgramUniform2fv(program, LOCATION_LIGHT_SPOT, n, glm::value_ptr(spot[0]));
  }
}

void setInstanceUniforms(GLuint program, const GpuScene& gpuScene, const Instance& instance,
                         const glm::dmat4& clipFromWorld, bool narrow, const ShadingView& view, bool maps) {
  const Scene& scene = gpuScene.scene();
  const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
  const Material& material = materialOf(scene, mesh);
  // Composed in double, rounded once (see scene.vert).
  const glm::dmat4 clipFromModel = wellScaled(clipFromWorld * instance.worldFromModel);
  const glm::dmat3 linear(instance.worldFromModel);
  const glm::mat3 normalFromModel(worldNormalFromModel(instance.worldFromModel));
  if (narrow) {
    glProgramUniformMatrix4dv(program, LOCATION_CLIP_FROM_MODEL_DOUBLE, 1, GL_FALSE, glm::value_ptr(clipFromModel));
  } else {
    const glm::mat4 rounded(clipFromModel);
    glProgramUniformMatrix4fv(program, LOCATION_CLIP_FROM_MODEL, 1, GL_FALSE, glm::value_ptr(rounded));
  }
  glProgramUniformMatrix3fv(program, LOCATION_WORLD_NORMAL_FROM_MODEL, 1, GL_FALSE, glm::value_ptr(normalFromModel));
  glm::dmat4 shadingFromWorld(1.0);
  shadingFromWorld[3] = glm::dvec4(-view.origin, 1.0);
  const glm::mat4 shadingFromModel(shadingFromWorld * instance.worldFromModel);
  glProgramUniformMatrix4fv(program, LOCATION_SHADING_FROM_MODEL, 1, GL_FALSE, glm::value_ptr(shadingFromModel));
  const SurfaceMaterial surface = surfaceMaterial(material, mesh.hasTangents);
  setSurfaceMaterial(program, gpuScene, material, surface);
  if (maps) setMaterialMaps(program, gpuScene, material, surface, linear);
}

}  // namespace lenslab
