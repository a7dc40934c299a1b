#include "render/LineDrawer.h"

#include "gl/Framebuffer.h"
#include "gl/Shader.h"

#include <glm/gtc/type_ptr.hpp>

namespace lenslab {

LineDrawer::LineDrawer()
    : program_(gl::buildProgram("view/lines.vert", "view/lines.frag")), vertexArray_(gl::VertexArray::create()) {
  const GLuint vao = vertexArray_.id();
  glEnableVertexArrayAttrib(vao, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
  glVertexArrayAttribBinding(vao, 0, 0);
  glVertexArrayAttribBinding(vao, 1, 0);
}

void LineDrawer::draw(const std::vector<LineSegment>& lines, const glm::dmat4& clipFromWorld, const gl::PixelRect& r) {
  if (lines.empty() || r.empty()) return;
  // Positions relative to nothing but the world: fine in float for the scenes' metre scale.
  std::vector<float> data;
  data.reserve(lines.size() * 12);
  for (const LineSegment& l : lines) {
    for (const glm::dvec3& p : {l.from, l.to}) {
      data.insert(data.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), l.color.r,
                               l.color.g, l.color.b});
    }
  }
  if (data.size() > capacity_) {
    // Immutable storage cannot grow: a new buffer, with room to spare.
    capacity_ = data.size() * 2;
    vertices_ = gl::Buffer::create();
    glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(capacity_ * sizeof(float)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glVertexArrayVertexBuffer(vertexArray_.id(), 0, vertices_.id(), 0, 6 * sizeof(float));
  }
  glNamedBufferSubData(vertices_.id(), 0, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data());

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);  // the shifted copies must not spill out of the rectangle
  glScissor(r.x, r.y, r.width, r.height);
  const glm::mat4 clip(clipFromWorld);
  glProgramUniformMatrix4fv(program_.id(), 0, 1, GL_FALSE, glm::value_ptr(clip));
  glUseProgram(program_.id());
  glBindVertexArray(vertexArray_.id());
  for (const glm::ivec2 shift : {glm::ivec2(0, 0), glm::ivec2(1, 0), glm::ivec2(0, 1), glm::ivec2(1, 1)}) {
    glViewport(r.x + shift.x, r.y + shift.y, r.width, r.height);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(data.size() / 6));
  }
  glBindVertexArray(0);
  glDisable(GL_SCISSOR_TEST);
}

Image LineDrawer::drawOffscreen(const std::vector<LineSegment>& lines, const glm::dmat4& clipFromWorld,
                                ImageSize size) {
  const gl::RenderTarget canvas(size.widthPx, size.heightPx);
  const float transparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(canvas.drawTarget().framebuffer, GL_COLOR, 0, transparent);
  canvas.bind();
  draw(lines, clipFromWorld, {0, 0, size.widthPx, size.heightPx});
  return canvas.readColor();
}

}  // namespace lenslab
