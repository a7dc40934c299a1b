#include "render/ImageDrawer.h"

#include "gl/Shader.h"

namespace lenslab {

ImageDrawer::ImageDrawer()
    : program_(gl::buildProgram("common/fullscreen.vert", "view/display.frag")), linear_(gl::Sampler::create()) {
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void ImageDrawer::draw(const gl::ImageTexture& image, const gl::PixelRect& rect, float gain,
                       const DisplayEncoding& display) const {
  drawTexture(image.id(), rect, gain, display);
}

void ImageDrawer::draw(const gl::RenderTarget& image, const gl::PixelRect& rect, float gain,
                       const DisplayEncoding& display) const {
  drawTexture(image.colorTexture(), rect, gain, display);
}

void ImageDrawer::drawTexture(GLuint texture, const gl::PixelRect& r, float gain,
                              const DisplayEncoding& display) const {
  if (r.empty()) return;
  glViewport(r.x, r.y, r.width, r.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const GLuint program = program_.id();
  glProgramUniform4f(program, 0, static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.width),
                     static_cast<float>(r.height));
  glProgramUniform1i(program, 1, 1);
  glProgramUniform1f(program, 2, gain);
  glProgramUniform1f(program, 3, display.exposureScale);
  glProgramUniform1i(program, 4, static_cast<int>(display.transform));
  glBindTextureUnit(0, texture);
  glBindSampler(0, linear_.id());
  fullScreen_.draw(program_);
  glBindSampler(0, 0);
}

}  // namespace lenslab
