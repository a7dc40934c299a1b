#include "view/GlDraw.h"

#include "gl/Shader.h"

#include <glm/gtc/type_ptr.hpp>

namespace lenslab::view {

ImageDrawer::ImageDrawer()
    : program_(gl::buildProgram("common/fullscreen.vert", "view/display.frag")),
      emptyVertexArray_(gl::VertexArray::create()),
      linear_(gl::Sampler::create()) {
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(linear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void ImageDrawer::draw(GLuint texture, const PixelRect& r, float gain) const {
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
  glUseProgram(program);
  glBindTextureUnit(0, texture);
  glBindSampler(0, linear_.id());
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindSampler(0, 0);
}

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

void LineDrawer::draw(const std::vector<DiagramLine>& lines, const glm::dmat4& clipFromWorld, const PixelRect& r) {
  if (lines.empty() || r.empty()) return;
  // Positions relative to nothing but the world: fine in float for the scenes' metre scale.
  std::vector<float> data;
  data.reserve(lines.size() * 12);
  for (const DiagramLine& l : lines) {
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

}  // namespace lenslab::view
