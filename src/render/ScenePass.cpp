#include "render/ScenePass.h"

#include "camera/ProjectionCentre.h"
#include "gl/Shader.h"
#include "render/SceneUniforms.h"
#include "scene/BlendOrder.h"
#include "scene/Brdf.h"
#include "scene/ShadingLights.h"

#include "../../shaders/common/locations.glsl"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

bool materialMaps(const Material& m) {
  if (m.normalTexture.present() || m.metallicRoughnessTexture.present() || m.occlusionTexture.present()) return true;
  for (const TextureRef* ref :
       {&m.baseColorTexture, &m.emissiveTexture, &m.metallicRoughnessTexture, &m.occlusionTexture})
    if (ref->present() && (ref->texCoord != 0 || ref->uvFromTexCoord != glm::mat3(1.0f))) return true;
  return false;
}

bool isNarrowField(const glm::dmat4& clipFromWorld) {
  // Rows x, y of a perspective projection grow as 1/(window size) and row w as 1/(PRP distance);
  // a parallel projection has no w row to compare with (its w is constant).
  const auto rowLength = [&](int r) {
    return glm::length(glm::dvec3(clipFromWorld[0][r], clipFromWorld[1][r], clipFromWorld[2][r]));
  };
  const double w = rowLength(3);
  return w > 0.0 && std::max(rowLength(0), rowLength(1)) > kNarrowFieldSlope * w;
}

// The programs are built on the first draw, for its scene's lighting (selectPrograms).
ScenePass::ScenePass() : dfgTable_(gl::Texture::create()) {
  // The split-sum DFG table (scene/Brdf.h), bilinear and clamped: scene.frag reads it by one
  // filtered lookup (dfg_filtered.glsl), which weighs the texels as brdf.glsl's dfgLookup and the
  // ray caster do.
  glTextureStorage2D(dfgTable_.id(), 1, GL_RGB32F, kDfgTableSize, kDfgTableSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(dfgTable_.id(), 0, 0, 0, kDfgTableSize, kDfgTableSize, GL_RGB, GL_FLOAT, dfgTable().data());
  glTextureParameteri(dfgTable_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(dfgTable_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(dfgTable_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(dfgTable_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::vector<std::string> ScenePass::withVariant(std::vector<std::string> defines) const {
  if (environmentVariant_) defines.push_back("ENVIRONMENT");
  if (lightCountVariant_ >= 0) defines.push_back("LIGHT_COUNT " + std::to_string(lightCountVariant_));
  return defines;
}

void ScenePass::selectPrograms(bool environment, int lightCount) const {
  if (environment == environmentVariant_ && lightCount == lightCountVariant_) return;
  environmentVariant_ = environment;
  lightCountVariant_ = lightCount;
  program_ = gl::Program();
  narrowProgram_ = gl::Program();
  for (auto& row : addPrograms_)
    for (gl::Program& p : row) p = gl::Program();
  for (auto& row : mapsPrograms_)
    for (gl::Program& p : row) p = gl::Program();
  for (auto& row : blendPrograms_)
    for (gl::Program& p : row) p = gl::Program();
}

void ScenePass::setLighting(GLuint program, const Scene& scene, float lodBias) const {
  setLightingUniforms(program, scene, shadingView_, lodBias);
  if (const GpuEnvironment* env = environment(scene)) env->bind(program);
}

void ScenePass::placeShadingOrigin(const Scene& scene, const glm::dmat4& clipFromWorld) const {
  // The view's eye (shading positions and lights relative to it, composed in double); a parallel
  // view has none: the scene's centre serves, and v is the constant way back along its rays.
  const ProjectionCentre centre = projectionCentre(clipFromWorld);
  shadingView_.parallel = centre.atInfinity;
  shadingView_.towardViewer = glm::vec3(centre.towardViewer);
  shadingView_.origin = !centre.atInfinity     ? centre.point
                        : scene.bounds.empty() ? glm::dvec3(0.0)
                                               : scene.bounds.center();
}

const GpuEnvironment* ScenePass::environment(const Scene& scene) const {
  if (!scene.environment) return nullptr;
  if (environmentSource_ != scene.environment) {
    environment_ = std::make_unique<GpuEnvironment>(*scene.environment);
    environmentSource_ = scene.environment;
  }
  return environment_.get();
}

void ScenePass::drawAddedBackground(const GpuEnvironment& env, const glm::dmat4& clipFromWorld,
                                    const gl::DrawTarget& target, const glm::vec4& weight) const {
  // Where the depth pass left far and the stencil lets this view add (as its surfaces do).
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  env.drawBackground(clipFromWorld, target.width, target.height, glm::vec3(weight), true);
  glDisable(GL_STENCIL_TEST);
}

GLuint ScenePass::buildSceneProgram(gl::Program& slot, bool narrow, const std::vector<std::string>& defines) const {
  if (!slot)
    slot = narrow ? gl::buildProgramWithGeometry("scene/narrow_field.vert", "scene/narrow_field.geom",
                                                 "scene/scene.frag", withVariant(defines))
                  : gl::buildProgram("scene/scene.vert", "scene/scene.frag", withVariant(defines));
  return slot.id();
}

ScenePass::Programs ScenePass::variant(const char* define, bool narrow) const {
  const auto build = [&](gl::Program& slot, const std::vector<std::string>& defines) {
    return buildSceneProgram(slot, narrow, defines);
  };
  gl::Program* slots = addPrograms_[narrow ? 1 : 0];
  if (std::string(define) == "DEPTH_ONLY")
    return {build(slots[0], {"DEPTH_ONLY"}), build(slots[1], {"DEPTH_ONLY", "ALPHA_MASK"})};
  const GLuint addProgram = build(slots[2], {define});
  return {addProgram, addProgram};
}

ScenePass::Programs ScenePass::mapsVariant(const char* define, bool narrow, const Scene& scene, float lodBias) const {
  const auto build = [&](gl::Program& slot, std::vector<std::string> defines) {
    defines.push_back("MATERIAL_MAPS");
    const GLuint id = buildSceneProgram(slot, narrow, defines);
    setLighting(id, scene, lodBias);
    return id;
  };
  gl::Program* slots = mapsPrograms_[narrow ? 1 : 0];
  if (!define) {
    const GLuint plain = build(slots[0], {});
    return {plain, plain};
  }
  if (std::string(define) == "DEPTH_ONLY")
    return {build(slots[1], {"DEPTH_ONLY"}), build(slots[2], {"DEPTH_ONLY", "ALPHA_MASK"})};
  const GLuint addProgram = build(slots[3], {define});
  return {addProgram, addProgram};
}

void ScenePass::draw(const GpuScene& gpuScene, const glm::dmat4& clipFromWorld, const gl::DrawTarget& target,
                     float lodBias, const std::vector<PixelBox>* boxes, const glm::vec4* addWeight) const {
  const Scene& scene = gpuScene.scene();
  target.bind();
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  selectPrograms(scene.environment != nullptr, static_cast<int>(std::min(shadingLights(scene, glm::dvec3(0.0)).size(),
                                                                         static_cast<std::size_t>(kMaxShadingLights))));
  const bool narrow = isNarrowField(clipFromWorld);
  const GLuint program = buildSceneProgram(narrow ? narrowProgram_ : program_, narrow, {});
  placeShadingOrigin(scene, clipFromWorld);
  glBindTextureUnit(UNIT_DFG, dfgTable_.id());
  glBindSampler(UNIT_DFG, 0);
  if (!addWeight) setLighting(program, scene, lodBias);
  const bool anyMaps = std::any_of(scene.materials.begin(), scene.materials.end(), materialMaps);
  const Programs plainMaps = anyMaps && !addWeight ? mapsVariant(nullptr, narrow, scene, lodBias) : Programs{};
  // Blending does not fit an added view (one fragment per pixel adds); Renderer layers such scenes.
  const bool blended = anyBlended(scene);
  if (addWeight && blended)
    throw std::logic_error("ScenePass: a view of a scene with alphaMode BLEND cannot be added into a sum");
  std::vector<std::size_t> backToFront;
  if (blended) {
    const ProjectionCentre centre = projectionCentre(clipFromWorld);
    backToFront = blendBackToFront(scene, centre.atInfinity ? nullptr : &centre.point, centre.towardViewer);
  }
  if (addWeight) {
    for (const char* define : {"DEPTH_ONLY", "ADD_TO_SUM"}) {
      const Programs p = variant(define, narrow);
      for (const GLuint id : {p.opaque, p.masked}) setLighting(id, scene, lodBias);
    }
  }

  // One box over the whole target is no box: llvmpipe clears whole bins fastest without a scissor.
  if (boxes && boxes->size() == 1 && (*boxes)[0] == PixelBox{0, 0, target.width, target.height}) boxes = nullptr;
  const std::size_t passes = boxes ? boxes->size() : 1;
  for (std::size_t pass = 0; pass < passes; ++pass) {
    if (boxes) {
      const PixelBox& b = (*boxes)[pass];
      glEnable(GL_SCISSOR_TEST);
      glScissor(b.x, b.y, b.width, b.height);
    }
    if (addWeight) {
      drawAdded(gpuScene, clipFromWorld, narrow, *addWeight, lodBias);
      if (const GpuEnvironment* env = environment(scene)) drawAddedBackground(*env, clipFromWorld, target, *addWeight);
      continue;
    }
    const glm::vec3& bg = scene.lighting.background;
    // Alpha is coverage: 0 where no surface is drawn (the background shows), 1 where one is; the
    // mean of the views is then the fraction of the pixel (× aperture) that sees a surface.
    const float clearColor[] = {bg.r, bg.g, bg.b, 0.0f};
    const float clearDepth = 0.0f;  // reverse-Z: far is 0
    glClearBufferfv(GL_COLOR, 0, clearColor);
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);
    drawInstances({program, program}, plainMaps, narrow, gpuScene, clipFromWorld);
    if (const GpuEnvironment* env = environment(scene))
      env->drawBackground(clipFromWorld, target.width, target.height, glm::vec3(1.0f), false);
    if (!backToFront.empty()) drawBlended(gpuScene, clipFromWorld, narrow, lodBias, backToFront);
  }
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
}

void ScenePass::drawAdded(const GpuScene& gpuScene, const glm::dmat4& clipFromWorld, bool narrow,
                          const glm::vec4& weight, float lodBias) const {
  // Depth only: no colour written, so llvmpipe shades nothing (opaque materials have no discard).
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  const Scene& scene = gpuScene.scene();
  const bool anyMaps = std::any_of(scene.materials.begin(), scene.materials.end(), materialMaps);
  const auto maps = [&](const char* define) {
    return anyMaps ? mapsVariant(define, narrow, scene, lodBias) : Programs{};
  };
  drawInstances(variant("DEPTH_ONLY", narrow), maps("DEPTH_ONLY"), narrow, gpuScene, clipFromWorld);

  // Colour where the depth is the visible surface's, once per pixel.
  const Programs add = variant("ADD_TO_SUM", narrow), addMaps = maps("ADD_TO_SUM");
  // With an environment the background varies per pixel and view: drawn by the view itself
  // (drawAddedBackground), so the accumulator adds none and the surfaces subtract none.
  const glm::vec3 bg = gpuScene.scene().environment ? glm::vec3(0.0f) : gpuScene.scene().lighting.background;
  for (const GLuint id : {add.opaque, addMaps.opaque}) {
    if (!id) continue;
    glProgramUniform3fv(id, LOCATION_BACKGROUND, 1, glm::value_ptr(bg));
    glProgramUniform4fv(id, LOCATION_ADD_WEIGHT, 1, glm::value_ptr(weight));
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  drawInstances(add, addMaps, narrow, gpuScene, clipFromWorld);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);
}

void ScenePass::drawBlended(const GpuScene& gpuScene, const glm::dmat4& clipFromWorld, bool narrow, float lodBias,
                            const std::vector<std::size_t>& backToFront) const {
  const Scene& scene = gpuScene.scene();
  const auto build = [&](gl::Program& slot, const std::vector<std::string>& defines) {
    const GLuint id = buildSceneProgram(slot, narrow, defines);
    setLighting(id, scene, lodBias);
    return id;
  };
  gl::Program* slots = blendPrograms_[narrow ? 1 : 0];
  const GLuint plain = build(slots[0], {"ALPHA_BLEND"});
  bool anyMaps = false;
  for (const std::size_t i : backToFront) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(scene.instances[i].mesh)];
    anyMaps = anyMaps || materialMaps(scene.materials[static_cast<std::size_t>(mesh.material)]);
  }
  const GLuint maps = anyMaps ? build(slots[1], {"ALPHA_BLEND", "MATERIAL_MAPS"}) : 0;
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  drawInstances({plain, plain}, {maps, maps}, narrow, gpuScene, clipFromWorld, &backToFront);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

void ScenePass::drawInstances(Programs programs, Programs withMaps, bool narrow, const GpuScene& gpuScene,
                              const glm::dmat4& clipFromWorld, const std::vector<std::size_t>* only) const {
  const Scene& scene = gpuScene.scene();
  const std::size_t count = only ? only->size() : scene.instances.size();
  for (std::size_t k = 0; k < count; ++k) {
    const Instance& instance = scene.instances[only ? (*only)[k] : k];
    if (!only && isBlended(scene, instance)) continue;
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const Material& material = materialOf(scene, mesh);
    const bool maps = withMaps.opaque != 0 && materialMaps(material);
    const Programs& chosen = maps ? withMaps : programs;
    const GLuint program = material.alphaMode == AlphaMode::Mask ? chosen.masked : chosen.opaque;
    glUseProgram(program);
    setInstanceUniforms(program, gpuScene, instance, clipFromWorld, narrow, shadingView_, maps);

    if (material.doubleSided) {
      glDisable(GL_CULL_FACE);
    } else {
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
    }
    // A mirroring transform turns counter-clockwise front faces clockwise.
    glFrontFace(glm::determinant(glm::dmat3(instance.worldFromModel)) < 0.0 ? GL_CW : GL_CCW);

    const GpuScene::GpuMesh& gpuMesh = gpuScene.mesh(instance.mesh);
    glBindVertexArray(gpuMesh.vertexArray.id());
    glDrawElements(GL_TRIANGLES, gpuMesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }
}

}  // namespace lenslab
