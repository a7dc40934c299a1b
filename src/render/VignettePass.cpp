#include "render/VignettePass.h"

#include "camera/Projection.h"
#include "gl/Shader.h"

namespace lenslab {

VignettePass::VignettePass() : program_(gl::buildProgram("common/fullscreen.vert", "lens/vignetting.frag")) {}

void VignettePass::apply(const Camera& camera, ImageSize size, const gl::RenderTarget& in, const gl::RenderTarget& out) const {
  // Normalised coordinates are linear in the window: the GL corner (0, 0) is the window's
  // (umin, vmin), and each pixel steps by the window's pitch over the PRP's distance.
  const Window& w = camera.view.window;
  const glm::vec2 atOrigin(normalisedFromWindow(camera.view, {w.umin, w.vmin}));
  const glm::vec2 perPixel(glm::dvec2(w.width() / size.widthPx, w.height() / size.heightPx) / camera.view.prp.z);
  const Vignetting& v = camera.effects.vignetting;
  const glm::vec3 coefficients(static_cast<float>(v.a1), static_cast<float>(v.a2), static_cast<float>(v.a3));
  glProgramUniform2fv(program_.id(), 0, 1, &atOrigin.x);
  glProgramUniform2fv(program_.id(), 1, 1, &perPixel.x);
  glProgramUniform3fv(program_.id(), 2, 1, &coefficients.x);
  out.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glBindTextureUnit(0, in.colorTexture());
  glBindSampler(0, 0);  // texelFetch only
  fullScreen_.draw(program_);
}

}  // namespace lenslab
