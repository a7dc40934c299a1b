#include "gl/FullScreenPass.h"

namespace lenslab::gl {

FullScreenPass::FullScreenPass() : emptyVertexArray_(VertexArray::create()) {}

void FullScreenPass::draw(GLuint program) const {
  glUseProgram(program);
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace lenslab::gl
