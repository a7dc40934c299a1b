#include "render/GpuEnvironment.h"

#include "gl/Shader.h"

#include "../../shaders/common/locations.glsl"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

gl::Texture upload(const EnvironmentImage& image) {
  gl::Texture t = gl::Texture::create();
  glTextureStorage2D(t.id(), 1, GL_RGB32F, image.width, image.height);
  glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGB, GL_FLOAT, image.rgb.data());
  // Complete without mipmaps (texelFetch reads level 0 of a complete texture only).
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

}  // namespace

glm::dmat3 worldDirectionFromNdc(const glm::dmat4& clipFromWorld) {
  // Only the linear part L (rows x, y, z, w of clipFromWorld's first three columns) is used: the
  // point at infinity along d has clip coordinates L·d, whatever the eye's position, so a view
  // 1e15 from the origin loses nothing to cancellation. A pixel at NDC (x, y) sees the d with
  // (L_x − x·L_w)·d = 0 and (L_y − y·L_w)·d = 0: their cross product, which expands to
  // L_x×L_y − x·(L_w×L_y) − y·(L_x×L_w), linear in (x, y). (A parallel view has L_w = 0: one
  // direction, L_x×L_y, for every pixel.)
  const auto row = [&](int r) { return glm::dvec3(clipFromWorld[0][r], clipFromWorld[1][r], clipFromWorld[2][r]); };
  const glm::dvec3 lx = row(0), ly = row(1), lz = row(2), lw = row(3);
  glm::dmat3 m(-glm::cross(lw, ly), -glm::cross(lx, lw), glm::cross(lx, ly));
  // Towards what the view sees: in front (w > 0) for a perspective view; towards the far plane
  // (reverse-Z: smaller depth) for a parallel one.
  const glm::dvec3 centre = m[2];
  const bool flip = glm::dot(lw, lw) > 0.0 ? glm::dot(lw, centre) < 0.0 : glm::dot(lz, centre) > 0.0;
  if (flip) m = -m;
  double scale = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) scale = std::max(scale, std::abs(m[c][r]));
  return scale > 0.0 && std::isfinite(scale) ? m * (1.0 / scale) : m;
}

GpuEnvironment::GpuEnvironment(const EnvironmentLookup& lookup)
    : lookup_(&lookup), program_(gl::buildProgram("common/fullscreen.vert", "scene/environment_background.frag")) {
  const PrefilteredEnvironment& maps = lookup.maps();
  background_ = upload(maps.background);
  diffuse_ = upload(maps.diffuse);
  specular_ = gl::TextureArray::create();
  const EnvironmentImage& first = maps.specular.front();
  const auto layers = static_cast<GLsizei>(maps.specular.size());
  glTextureStorage3D(specular_.id(), 1, GL_RGB32F, first.width, first.height, layers);
  for (GLsizei l = 0; l < layers; ++l)
    glTextureSubImage3D(specular_.id(), 0, 0, 0, l, first.width, first.height, 1, GL_RGB, GL_FLOAT,
                        maps.specular[static_cast<std::size_t>(l)].rgb.data());
  glTextureParameteri(specular_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(specular_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void GpuEnvironment::bind(GLuint program) const {
  const GLuint units[] = {UNIT_ENVIRONMENT_BACKGROUND, UNIT_ENVIRONMENT_SPECULAR, UNIT_ENVIRONMENT_DIFFUSE};
  const GLuint textures[] = {background_.id(), specular_.id(), diffuse_.id()};
  for (int i = 0; i < 3; ++i) {
    glBindTextureUnit(units[i], textures[i]);
    glBindSampler(units[i], 0);
  }
  // Set only where the program uses them: a location it optimised out is no location.
  const auto used = [&](const char* name) { return glGetUniformLocation(program, name) >= 0; };
  if (used("environmentRotation"))
    glProgramUniform2fv(program, LOCATION_ENVIRONMENT_ROTATION, 1, glm::value_ptr(lookup_->rotationCosSin()));
  if (used("environmentIntensity"))
    glProgramUniform1f(program, LOCATION_ENVIRONMENT_INTENSITY, lookup_->placement().intensity);
  if (used("environmentLevels"))
    glProgramUniform1i(program, LOCATION_ENVIRONMENT_LEVELS, lookup_->maps().specularLevels());
  if (used("hasEnvironment")) glProgramUniform1i(program, LOCATION_HAS_ENVIRONMENT, 1);
}

void GpuEnvironment::drawBackground(const glm::dmat4& clipFromWorld, int widthPx, int heightPx, const glm::vec3& weight,
                                    bool add) const {
  bind(program_.id());
  const glm::mat3 directionFromNdc(worldDirectionFromNdc(clipFromWorld));
  glProgramUniformMatrix3fv(program_.id(), LOCATION_WORLD_DIRECTION_FROM_NDC, 1, GL_FALSE,
                            glm::value_ptr(directionFromNdc));
  glProgramUniform2f(program_.id(), LOCATION_NDC_PER_PIXEL, 2.0f / static_cast<float>(widthPx),
                     2.0f / static_cast<float>(heightPx));
  glProgramUniform3fv(program_.id(), LOCATION_BACKGROUND_WEIGHT, 1, glm::value_ptr(weight));
  GLboolean depthMask = GL_TRUE;
  GLint depthFunc = GL_GREATER;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  const GLboolean blend = glIsEnabled(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_EQUAL);  // the triangle lies at depth 0: only where no surface was drawn
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  if (add) {
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
  } else {
    glDisable(GL_BLEND);
  }
  // Alpha is the coverage the scene pass wrote: 0 here already, and kept.
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  fullScreen_.draw(program_);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(static_cast<GLenum>(depthFunc));
  glDepthMask(depthMask);
  if (blend)
    glEnable(GL_BLEND);
  else
    glDisable(GL_BLEND);
}

}  // namespace lenslab
