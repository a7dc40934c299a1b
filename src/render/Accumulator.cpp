#include "render/Accumulator.h"

#include "gl/Shader.h"

#include <stdexcept>

namespace lenslab {

Accumulator::Accumulator()
    : accumulate_(gl::buildProgram("common/fullscreen.vert", "accumulate/accumulate.frag")),
      resolve_(gl::buildProgram("common/fullscreen.vert", "accumulate/resolve.frag")),
      emptyVertexArray_(gl::VertexArray::create()) {}

void Accumulator::start(int widthPx, int heightPx) {
  if (!sum_ || sum_->width() != widthPx || sum_->height() != heightPx)
    sum_ = std::make_unique<gl::RenderTarget>(widthPx, heightPx);
  sum_->bind();
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, zero);
  count_ = 0;
}

namespace {

void drawFullScreen(GLuint program, GLuint vertexArray, GLuint texture) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glUseProgram(program);
  glBindTextureUnit(0, texture);
  glBindSampler(0, 0);
  glBindVertexArray(vertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace

void Accumulator::add(const gl::RenderTarget& view) {
  if (!sum_) throw std::logic_error("Accumulator::add before start");
  sum_->bind();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  drawFullScreen(accumulate_.id(), emptyVertexArray_.id(), view.colorTexture());
  glDisable(GL_BLEND);
  ++count_;
}

void Accumulator::resolve(const gl::RenderTarget& out) const {
  if (!sum_ || count_ == 0) throw std::logic_error("Accumulator::resolve with nothing added");
  out.bind();
  glDisable(GL_BLEND);
  glProgramUniform1f(resolve_.id(), 0, 1.0f / static_cast<float>(count_));
  drawFullScreen(resolve_.id(), emptyVertexArray_.id(), sum_->colorTexture());
}

}  // namespace lenslab
