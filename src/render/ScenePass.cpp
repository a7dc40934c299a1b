#include "render/ScenePass.h"

#include "gl/Shader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
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
  kToLight = 8,
  kAmbient = 9,
  kDiffuse = 10,
  kLodBias = 11,
  kClipFromModelDouble = 12,  // narrow_field.vert
  kBackground = 13,           // ADD_TO_SUM
  kAddWeight = 14,            // ADD_TO_SUM
  kEmissive = 15,
  kHasEmissiveTexture = 16,
};

// The same projection scaled to its largest entry near 1. Clip coordinates are homogeneous, so
// the image is unchanged, but a PRP 1e-100 from the view plane (entries of 1e100) no longer
// overflows float, nor one 1e100 away underflows it.
glm::dmat4 wellScaled(const glm::dmat4& m) {
  double largest = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) largest = std::max(largest, std::abs(m[c][r]));
  return largest > 0.0 && std::isfinite(largest) ? m * (1.0 / largest) : m;
}

const Material kDefaultMaterial{};  // glTF's default material: white, lit, opaque, single-sided

}  // namespace

bool isNarrowField(const glm::dmat4& clipFromWorld) {
  // Rows x, y of a perspective projection grow as 1/(window size) and row w as 1/(PRP distance);
  // a parallel projection has no w row to compare with (its w is constant).
  const auto rowLength = [&](int r) { return glm::length(glm::dvec3(clipFromWorld[0][r], clipFromWorld[1][r], clipFromWorld[2][r])); };
  const double w = rowLength(3);
  return w > 0.0 && std::max(rowLength(0), rowLength(1)) > kNarrowFieldSlope * w;
}

ScenePass::ScenePass() : program_(gl::buildProgram("scene/scene.vert", "scene/scene.frag")) {}

void ScenePass::setLighting(GLuint program, const Scene& scene, float lodBias) const {
  glProgramUniform3fv(program, kToLight, 1, glm::value_ptr(scene.lighting.toLight));
  glProgramUniform1f(program, kAmbient, scene.lighting.ambient);
  glProgramUniform1f(program, kDiffuse, scene.lighting.diffuse);
  glProgramUniform1f(program, kLodBias, lodBias);
  if (const GpuEnvironment* env = environment(scene)) env->bind(program);
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

ScenePass::Programs ScenePass::variant(const char* define, bool narrow) const {
  const auto build = [&](gl::Program& slot, std::vector<std::string> defines) {
    if (!slot)
      slot = narrow ? gl::buildProgramWithGeometry("scene/narrow_field.vert", "scene/narrow_field.geom", "scene/scene.frag", defines)
                    : gl::buildProgram("scene/scene.vert", "scene/scene.frag", defines);
    return slot.id();
  };
  gl::Program* slots = addPrograms_[narrow ? 1 : 0];
  if (std::string(define) == "DEPTH_ONLY") return {build(slots[0], {"DEPTH_ONLY"}), build(slots[1], {"DEPTH_ONLY", "ALPHA_MASK"})};
  const GLuint addProgram = build(slots[2], {define});
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

  const bool narrow = isNarrowField(clipFromWorld);
  if (narrow && !narrowProgram_)
    narrowProgram_ = gl::buildProgramWithGeometry("scene/narrow_field.vert", "scene/narrow_field.geom", "scene/scene.frag");
  const GLuint program = narrow ? narrowProgram_->id() : program_.id();
  if (!addWeight) setLighting(program, scene, lodBias);
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
      drawAdded(gpuScene, clipFromWorld, narrow, *addWeight);
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
    drawInstances({program, program}, narrow, gpuScene, clipFromWorld);
    if (const GpuEnvironment* env = environment(scene))
      env->drawBackground(clipFromWorld, target.width, target.height, glm::vec3(1.0f), false);
  }
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
}

void ScenePass::drawAdded(const GpuScene& gpuScene, const glm::dmat4& clipFromWorld, bool narrow, const glm::vec4& weight) const {
  // Depth only: no colour written, so llvmpipe shades nothing (opaque materials have no discard).
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  drawInstances(variant("DEPTH_ONLY", narrow), narrow, gpuScene, clipFromWorld);

  // Colour where the depth is the visible surface's, once per pixel.
  const Programs add = variant("ADD_TO_SUM", narrow);
  // With an environment the background varies per pixel and view: drawn by the view itself
  // (drawAddedBackground), so the accumulator adds none and the surfaces subtract none.
  const glm::vec3 bg = gpuScene.scene().environment ? glm::vec3(0.0f) : gpuScene.scene().lighting.background;
  glProgramUniform3fv(add.opaque, kBackground, 1, glm::value_ptr(bg));
  glProgramUniform4fv(add.opaque, kAddWeight, 1, glm::value_ptr(weight));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  drawInstances(add, narrow, gpuScene, clipFromWorld);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);
}

void ScenePass::drawInstances(Programs programs, bool narrow, const GpuScene& gpuScene, const glm::dmat4& clipFromWorld) const {
  const Scene& scene = gpuScene.scene();
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const Material& material =
        mesh.material >= 0 ? scene.materials[static_cast<std::size_t>(mesh.material)] : kDefaultMaterial;
    const GLuint program = material.alphaMode == AlphaMode::Mask ? programs.masked : programs.opaque;
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
    glProgramUniform4fv(program, kBaseColorFactor, 1, glm::value_ptr(material.baseColorFactor));
    const bool textured = material.baseColorTexture >= 0;
    glProgramUniform1i(program, kHasBaseColorTexture, textured);
    if (textured) gpuScene.bindTexture(material.baseColorTexture, 0);
    glProgramUniform3fv(program, kEmissive, 1, glm::value_ptr(material.emissive));
    const bool emissiveTextured = material.emissiveTexture >= 0;
    glProgramUniform1i(program, kHasEmissiveTexture, emissiveTextured);
    if (emissiveTextured) gpuScene.bindTexture(material.emissiveTexture, 1);
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
