#include "render/VignettePass.h"

#include "camera/Projection.h"
#include "gl/Shader.h"

#include "../../shaders/common/locations.glsl"

namespace lenslab {

VignetteGain vignetteGainFor(const Camera& camera, ImageSize size) {
  // Normalised coordinates are linear in the window: the GL corner (0, 0) is the window's
  // (umin, vmin), and each pixel steps by the window's pitch over the PRP's distance.
  const Window& w = camera.view.window;
  const Vignetting& v = camera.lens.effects.vignetting;
  VignetteGain g;
  g.normalisedAtOrigin = glm::vec2(normalisedFromWindow(camera.view, {w.umin, w.vmin}));
  g.normalisedPerPixel =
      glm::vec2(glm::dvec2(w.width() / size.widthPx, w.height() / size.heightPx) / camera.view.prp.z);
  g.coefficients = glm::vec3(static_cast<float>(v.a1), static_cast<float>(v.a2), static_cast<float>(v.a3));
  return g;
}

void setVignetteGain(GLuint program, const VignetteGain& gain) {
  glProgramUniform2fv(program, LOCATION_VIGNETTING_AT_ORIGIN, 1, &gain.normalisedAtOrigin.x);
  glProgramUniform2fv(program, LOCATION_VIGNETTING_PER_PIXEL, 1, &gain.normalisedPerPixel.x);
  glProgramUniform3fv(program, LOCATION_VIGNETTING_COEFFICIENTS, 1, &gain.coefficients.x);
}

VignettePass::VignettePass() : program_(gl::buildProgram("common/fullscreen.vert", "lens/vignetting.frag")) {}

void VignettePass::apply(const VignetteGain& gain, const gl::RenderTarget& in, const gl::RenderTarget& out) const {
  setVignetteGain(program_.id(), gain);
  out.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glBindTextureUnit(0, in.colorTexture());
  glBindSampler(0, 0);  // texelFetch only
  fullScreen_.draw(program_);
}

}  // namespace lenslab
