#include "render/GpuScene.h"

#include "../../shaders/common/locations.glsl"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lenslab {
namespace {

bool usesMipmaps(Filter f) { return f != Filter::Nearest && f != Filter::Linear; }

GpuScene::GpuMesh upload(const Mesh& mesh) {
  GpuScene::GpuMesh gpu;
  gpu.vertexArray = gl::VertexArray::create();
  gpu.vertices = gl::Buffer::create();
  gpu.indices = gl::Buffer::create();
  glNamedBufferStorage(gpu.vertices.id(), static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
                       mesh.vertices.data(), 0);
  glNamedBufferStorage(gpu.indices.id(), static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), 0);
  const GLuint vao = gpu.vertexArray.id();
  glVertexArrayVertexBuffer(vao, 0, gpu.vertices.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, gpu.indices.id());
  struct Attribute {
    GLuint location;
    GLint size;
    std::size_t offset;
  };
  const Attribute attributes[] = {{ATTRIBUTE_POSITION, 3, offsetof(Vertex, position)},
                                  {ATTRIBUTE_NORMAL, 3, offsetof(Vertex, normal)},
                                  {ATTRIBUTE_UV, 2, offsetof(Vertex, uv)},
                                  {ATTRIBUTE_COLOR, 4, offsetof(Vertex, color)},
                                  {ATTRIBUTE_TANGENT, 4, offsetof(Vertex, tangent)},
                                  {ATTRIBUTE_UV1, 2, offsetof(Vertex, uv1)}};
  for (const Attribute& a : attributes) {
    glEnableVertexArrayAttrib(vao, a.location);
    glVertexArrayAttribFormat(vao, a.location, a.size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(a.offset));
    glVertexArrayAttribBinding(vao, a.location, 0);
  }
  gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
  return gpu;
}

}  // namespace

GpuScene::GpuScene(const Scene& scene) : scene_(&scene) {
  meshes_.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) meshes_.push_back(upload(mesh));

  // An image gets a mipmap chain when any texture sampling it minifies with mipmaps.
  std::vector<bool> wantsMipmaps(scene.images.size(), false);
  for (const Texture& t : scene.textures)
    if (t.image >= 0 && usesMipmaps(t.sampler.minFilter)) wantsMipmaps[static_cast<std::size_t>(t.image)] = true;

  // Images that some material reads as data (linear) rather than as colour (sRGB); an image used
  // both ways is stored twice.
  std::vector<bool> asData(scene.images.size(), false), asColour(scene.images.size(), false);
  const auto mark = [&](std::vector<bool>& uses, const TextureRef& ref) {
    if (ref.present())
      uses[static_cast<std::size_t>(scene.textures[static_cast<std::size_t>(ref.texture)].image)] = true;
  };
  for (const Material& m : scene.materials) {
    for (const TextureRef* ref : {&m.normalTexture, &m.metallicRoughnessTexture, &m.occlusionTexture})
      mark(asData, *ref);
    for (const TextureRef* ref : {&m.baseColorTexture, &m.emissiveTexture}) mark(asColour, *ref);
  }

  linearImages_.resize(scene.images.size());
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    const TextureImage& image = scene.images[i];
    const int levels =
        wantsMipmaps[i] ? 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height)))) : 1;
    const auto upload = [&](GLenum format) {
      gl::Texture texture = gl::Texture::create();
      glTextureStorage2D(texture.id(), levels, format, image.width, image.height);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                          image.rgba8.data());
      if (levels > 1) glGenerateTextureMipmap(texture.id());
      return texture;
    };
    images_.push_back(asData[i] && !asColour[i] ? gl::Texture() : upload(GL_SRGB8_ALPHA8));
    if (asData[i]) linearImages_[i] = upload(GL_RGBA8);
  }

  for (const Texture& t : scene.textures) {
    gl::Sampler sampler = gl::Sampler::create();
    Filter minFilter = t.sampler.minFilter;
    // A mipmapped filter on an image stored without mipmaps would make the texture incomplete.
    if (t.image >= 0 && !wantsMipmaps[static_cast<std::size_t>(t.image)] && usesMipmaps(minFilter))
      minFilter = Filter::Linear;
    glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(t.sampler.wrapS));
    glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(t.sampler.wrapT));
    glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(t.sampler.magFilter));
    glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    samplers_.push_back(std::move(sampler));
  }
}

void GpuScene::bindTexture(int index, GLuint unit) const {
  const Texture& t = scene_->textures[static_cast<std::size_t>(index)];
  glBindTextureUnit(unit, images_[static_cast<std::size_t>(t.image)].id());
  glBindSampler(unit, samplers_[static_cast<std::size_t>(index)].id());
}

void GpuScene::bindLinearTexture(int index, GLuint unit) const {
  const Texture& t = scene_->textures[static_cast<std::size_t>(index)];
  glBindTextureUnit(unit, linearImages_[static_cast<std::size_t>(t.image)].id());
  glBindSampler(unit, samplers_[static_cast<std::size_t>(index)].id());
}

}  // namespace lenslab
