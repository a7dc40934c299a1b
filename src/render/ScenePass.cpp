#include "render/ScenePass.h"

#include "camera/ProjectionCentre.h"
#include "gl/Shader.h"
#include "scene/BlendOrder.h"
#include "scene/Brdf.h"
#include "scene/ShadingLights.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {
namespace {

// Uniform locations, as declared in shaders/scene/*.
enum Location : GLint {
  kClipFromModel = 0,
  kWorldNormalFromModel = 1,
  kBaseColorFactor = 2,
  kHasBaseColorTexture = 3,
  kUnlit = 4,
  kAlphaMask = 5,
  kAlphaCutoff = 6,
  kDoubleSided = 7,
  kAmbient = 9,
  kLodBias = 11,
  kClipFromModelDouble = 12,  // narrow_field.vert
  kBackground = 13,           // ADD_TO_SUM
  kAddWeight = 14,            // ADD_TO_SUM
  kEmissive = 15,
  kHasEmissiveTexture = 16,
  // Metallic-roughness and punctual lights (scene.frag, scene.vert).
  kShadingFromModel = 20,
  kTowardViewer = 21,
  kParallelView = 22,
  kMetallicFactor = 23,
  kRoughnessFactor = 24,
  kHasMetallicRoughnessTexture = 25,
  kHasOcclusionTexture = 26,
  kOcclusionStrength = 27,
  kLightCount = 28,
  kLightPositionRange = 32,  // arrays of kMaxShadingLights
  kLightDirectionType = 40,
  kLightIntensity = 48,
  kLightSpot = 56,
  // Normal maps and texture coordinates (80–99).
  kWorldTangentFromModel = 80,
  kHandednessFromModel = 81,
  kHasNormalTexture = 82,
  kNormalScale = 83,
  kNormalTexCoord = 84,  // each slot: its TEXCOORD set, then its uv transform one location on
  kBaseColorTexCoord = 86,
  kEmissiveTexCoord = 88,
  kMetallicRoughnessTexCoord = 90,
  kOcclusionTexCoord = 92,
};

// Texture units (scene.frag).
constexpr GLuint kMetallicRoughnessUnit = 2;
constexpr GLuint kOcclusionUnit = 3;
constexpr GLuint kNormalTextureUnit = 4;
constexpr GLuint kDfgUnit = 9;
static_assert(kMaxShadingLights == 8, "scene.frag's light arrays hold 8");

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
void setMaterialMaps(GLuint program, const GpuScene& gpuScene, const Material& material, const Mesh& mesh, const glm::dmat3& linear) {
  const std::pair<GLint, const TextureRef*> slots[] = {{kBaseColorTexCoord, &material.baseColorTexture},
                                                       {kEmissiveTexCoord, &material.emissiveTexture},
                                                       {kMetallicRoughnessTexCoord, &material.metallicRoughnessTexture},
                                                       {kOcclusionTexCoord, &material.occlusionTexture}};
  for (const auto& [location, ref] : slots)
    if (ref->present()) setTextureSlot(program, location, *ref);
  const bool normalMapped = material.normalTexture.present() && mesh.hasTangents;
  glProgramUniform1i(program, kHasNormalTexture, normalMapped);
  if (!normalMapped) return;
  gpuScene.bindLinearTexture(material.normalTexture.texture, kNormalTextureUnit);
  setTextureSlot(program, kNormalTexCoord, material.normalTexture);
  glProgramUniform1f(program, kNormalScale, material.normalScale);
  glProgramUniformMatrix3fv(program, kWorldTangentFromModel, 1, GL_FALSE, glm::value_ptr(tangentFromModel(linear)));
  glProgramUniform1f(program, kHandednessFromModel, glm::determinant(linear) < 0.0 ? -1.0f : 1.0f);
}

const Material kDefaultMaterial{};  // glTF's default material: white, lit, opaque, single-sided

}  // namespace

bool materialMaps(const Material& m) {
  if (m.normalTexture.present() || m.metallicRoughnessTexture.present() || m.occlusionTexture.present()) return true;
  for (const TextureRef* ref : {&m.baseColorTexture, &m.emissiveTexture, &m.metallicRoughnessTexture, &m.occlusionTexture})
    if (ref->present() && (ref->texCoord != 0 || ref->uvFromTexCoord != glm::mat3(1.0f))) return true;
  return false;
}

bool isNarrowField(const glm::dmat4& clipFromWorld) {
  // Rows x, y of a perspective projection grow as 1/(window size) and row w as 1/(PRP distance);
  // a parallel projection has no w row to compare with (its w is constant).
  const auto rowLength = [&](int r) { return glm::length(glm::dvec3(clipFromWorld[0][r], clipFromWorld[1][r], clipFromWorld[2][r])); };
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
  glProgramUniform1f(program, kAmbient, scene.lighting.ambient);
  glProgramUniform1f(program, kLodBias, lodBias);
  glProgramUniform3fv(program, kTowardViewer, 1, glm::value_ptr(towardViewer_));
  glProgramUniform1i(program, kParallelView, parallelView_);
  const std::vector<ShadingLight> lights = shadingLights(scene, shadingOrigin_);
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
  glProgramUniform1i(program, kLightCount, n);
  if (n > 0) {
    glProgramUniform4fv(program, kLightPositionRange, n, glm::value_ptr(positionRange[0]));
    glProgramUniform4fv(program, kLightDirectionType, n, glm::value_ptr(directionType[0]));
    glProgramUniform3fv(program, kLightIntensity, n, glm::value_ptr(intensity[0]));
    glProgramUniform2fv(program, kLightSpot, n, glm::value_ptr(spot[0]));
  }
  if (const GpuEnvironment* env = environment(scene)) env->bind(program);
}

void ScenePass::placeShadingOrigin(const Scene& scene, const glm::dmat4& clipFromWorld) const {
  // The view's eye (shading positions and lights relative to it, composed in double); a parallel
  // view has none: the scene's centre serves, and v is the constant way back along its rays.
  const ProjectionCentre centre = projectionCentre(clipFromWorld);
  parallelView_ = centre.atInfinity;
  towardViewer_ = glm::vec3(centre.towardViewer);
  shadingOrigin_ = !centre.atInfinity ? centre.point : scene.bounds.empty() ? glm::dvec3(0.0) : scene.bounds.center();
}

const GpuEnvironment* ScenePass::environment(const Scene& scene) const {
  if (!scene.environment) return nullptr;
  if (environmentSource_ != scene.environment) {
    environment_ = std::make_unique<GpuEnvironment>(*scene.environment);
    environmentSource_ = scene.environment;
  }
  return environment_.get();
}

void ScenePass::drawAddedBackground(const GpuEnvironment& env, const glm::dmat4& clipFromWorld, const gl::DrawTarget& target,
                                    const glm::vec4& weight) const {
  // Where the depth pass left far and the stencil lets this view add (as its surfaces do).
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  env.drawBackground(clipFromWorld, target.width, target.height, glm::vec3(weight), true);
  glDisable(GL_STENCIL_TEST);
}

GLuint ScenePass::buildSceneProgram(gl::Program& slot, bool narrow, const std::vector<std::string>& defines) const {
  if (!slot)
    slot = narrow ? gl::buildProgramWithGeometry("scene/narrow_field.vert", "scene/narrow_field.geom", "scene/scene.frag",
                                                 withVariant(defines))
                  : gl::buildProgram("scene/scene.vert", "scene/scene.frag", withVariant(defines));
  return slot.id();
}

ScenePass::Programs ScenePass::variant(const char* define, bool narrow) const {
  const auto build = [&](gl::Program& slot, const std::vector<std::string>& defines) { return buildSceneProgram(slot, narrow, defines); };
  gl::Program* slots = addPrograms_[narrow ? 1 : 0];
  if (std::string(define) == "DEPTH_ONLY") return {build(slots[0], {"DEPTH_ONLY"}), build(slots[1], {"DEPTH_ONLY", "ALPHA_MASK"})};
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
  if (std::string(define) == "DEPTH_ONLY") return {build(slots[1], {"DEPTH_ONLY"}), build(slots[2], {"DEPTH_ONLY", "ALPHA_MASK"})};
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

  selectPrograms(scene.environment != nullptr,
                 static_cast<int>(std::min(shadingLights(scene, glm::dvec3(0.0)).size(), static_cast<std::size_t>(kMaxShadingLights))));
  const bool narrow = isNarrowField(clipFromWorld);
  const GLuint program = buildSceneProgram(narrow ? narrowProgram_ : program_, narrow, {});
  placeShadingOrigin(scene, clipFromWorld);
  glBindTextureUnit(kDfgUnit, dfgTable_.id());
  glBindSampler(kDfgUnit, 0);
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

void ScenePass::drawAdded(const GpuScene& gpuScene, const glm::dmat4& clipFromWorld, bool narrow, const glm::vec4& weight,
                          float lodBias) const {
  // Depth only: no colour written, so llvmpipe shades nothing (opaque materials have no discard).
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  const Scene& scene = gpuScene.scene();
  const bool anyMaps = std::any_of(scene.materials.begin(), scene.materials.end(), materialMaps);
  const auto maps = [&](const char* define) { return anyMaps ? mapsVariant(define, narrow, scene, lodBias) : Programs{}; };
  drawInstances(variant("DEPTH_ONLY", narrow), maps("DEPTH_ONLY"), narrow, gpuScene, clipFromWorld);

  // Colour where the depth is the visible surface's, once per pixel.
  const Programs add = variant("ADD_TO_SUM", narrow), addMaps = maps("ADD_TO_SUM");
  // With an environment the background varies per pixel and view: drawn by the view itself
  // (drawAddedBackground), so the accumulator adds none and the surfaces subtract none.
  const glm::vec3 bg = gpuScene.scene().environment ? glm::vec3(0.0f) : gpuScene.scene().lighting.background;
  for (const GLuint id : {add.opaque, addMaps.opaque}) {
    if (!id) continue;
    glProgramUniform3fv(id, kBackground, 1, glm::value_ptr(bg));
    glProgramUniform4fv(id, kAddWeight, 1, glm::value_ptr(weight));
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
    const Material& material =
        mesh.material >= 0 ? scene.materials[static_cast<std::size_t>(mesh.material)] : kDefaultMaterial;
    const bool maps = withMaps.opaque != 0 && materialMaps(material);
    const Programs& chosen = maps ? withMaps : programs;
    const GLuint program = material.alphaMode == AlphaMode::Mask ? chosen.masked : chosen.opaque;
    glUseProgram(program);

    // Composed in double, rounded once (see scene.vert).
    const glm::dmat4 clipFromModel = wellScaled(clipFromWorld * instance.worldFromModel);
    const glm::dmat3 linear(instance.worldFromModel);
    const glm::mat3 normalFromModel(worldNormalFromModel(instance.worldFromModel));
    if (narrow) {
      glProgramUniformMatrix4dv(program, kClipFromModelDouble, 1, GL_FALSE, glm::value_ptr(clipFromModel));
    } else {
      const glm::mat4 rounded(clipFromModel);
      glProgramUniformMatrix4fv(program, kClipFromModel, 1, GL_FALSE, glm::value_ptr(rounded));
    }
    glProgramUniformMatrix3fv(program, kWorldNormalFromModel, 1, GL_FALSE, glm::value_ptr(normalFromModel));
    glm::dmat4 shadingFromWorld(1.0);
    shadingFromWorld[3] = glm::dvec4(-shadingOrigin_, 1.0);
    const glm::mat4 shadingFromModel(shadingFromWorld * instance.worldFromModel);
    glProgramUniformMatrix4fv(program, kShadingFromModel, 1, GL_FALSE, glm::value_ptr(shadingFromModel));
    glProgramUniform1f(program, kMetallicFactor, material.metallicFactor);
    glProgramUniform1f(program, kRoughnessFactor, material.roughnessFactor);
    glProgramUniform1f(program, kOcclusionStrength, material.occlusionStrength);
    glProgramUniform1i(program, kHasMetallicRoughnessTexture, material.metallicRoughnessTexture.present());
    if (material.metallicRoughnessTexture.present())
      gpuScene.bindLinearTexture(material.metallicRoughnessTexture.texture, kMetallicRoughnessUnit);
    glProgramUniform1i(program, kHasOcclusionTexture, material.occlusionTexture.present());
    if (material.occlusionTexture.present()) gpuScene.bindLinearTexture(material.occlusionTexture.texture, kOcclusionUnit);
    glProgramUniform4fv(program, kBaseColorFactor, 1, glm::value_ptr(material.baseColorFactor));
    const bool textured = material.baseColorTexture.present();
    glProgramUniform1i(program, kHasBaseColorTexture, textured);
    if (textured) gpuScene.bindTexture(material.baseColorTexture.texture, 0);
    glProgramUniform3fv(program, kEmissive, 1, glm::value_ptr(material.emissive));
    const bool emissiveTextured = material.emissiveTexture.present();
    glProgramUniform1i(program, kHasEmissiveTexture, emissiveTextured);
    if (emissiveTextured) gpuScene.bindTexture(material.emissiveTexture.texture, 1);
    if (maps) setMaterialMaps(program, gpuScene, material, mesh, linear);
    glProgramUniform1i(program, kUnlit, material.unlit);
    glProgramUniform1i(program, kAlphaMask, material.alphaMode == AlphaMode::Mask);
    glProgramUniform1f(program, kAlphaCutoff, material.alphaCutoff);
    glProgramUniform1i(program, kDoubleSided, material.doubleSided);

    if (material.doubleSided) {
      glDisable(GL_CULL_FACE);
    } else {
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
    }
    // A mirroring transform turns counter-clockwise front faces clockwise.
    glFrontFace(glm::determinant(linear) < 0.0 ? GL_CW : GL_CCW);

    const GpuScene::GpuMesh& gpuMesh = gpuScene.mesh(instance.mesh);
    glBindVertexArray(gpuMesh.vertexArray.id());
    glDrawElements(GL_TRIANGLES, gpuMesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }
}

}  // namespace lenslab
