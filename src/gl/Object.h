#pragma once
// Move-only owners of GL objects (after Magnum): the destructor deletes, moving empties the
// source, an empty owner holds 0. No bare GLuint leaves src/gl and src/render.
#include <glad/gl.h>

#include <utility>

namespace lenslab::gl {

template <class Kind>
class Object {
 public:
  Object() = default;
  static Object create() {
    Object o;
    o.id_ = Kind::create();
    return o;
  }
  explicit Object(GLuint adopted) : id_(adopted) {}
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Kind::destroy(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct BufferKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct Texture2DKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct Texture2DArrayKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct SamplerKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct FramebufferKind {
  static GLuint create() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return id;
  }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct ProgramKind {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderKind {
  static GLuint create() { return 0; }  // shaders are made with a stage: adopt glCreateShader(stage)
  static void destroy(GLuint id) { glDeleteShader(id); }
};

using Buffer = Object<BufferKind>;
using VertexArray = Object<VertexArrayKind>;
using Texture = Object<Texture2DKind>;
using TextureArray = Object<Texture2DArrayKind>;
using Sampler = Object<SamplerKind>;
using Framebuffer = Object<FramebufferKind>;
using Program = Object<ProgramKind>;
using Shader = Object<ShaderKind>;

}  // namespace lenslab::gl
