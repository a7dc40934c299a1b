#pragma once
// The scene on the GPU: one vertex array per mesh, one texture per image (sRGB, mipmapped when its
// samplers want mipmaps), one sampler object per glTF texture. Only what Scene holds is uploaded,
// and the loader keeps only what the drawn scene uses.
#include "gl/Object.h"
#include "scene/Scene.h"

#include <vector>

namespace lenslab {

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);

  struct GpuMesh {
    gl::VertexArray vertexArray;
    gl::Buffer vertices;
    gl::Buffer indices;
    GLsizei indexCount = 0;
  };

  const Scene& scene() const { return *scene_; }
  const GpuMesh& mesh(int index) const { return meshes_[static_cast<std::size_t>(index)]; }
  // Binds texture `index` (image and sampler) to texture unit `unit`.
  void bindTexture(int index, GLuint unit) const;
  // The same for a texture that holds data, not colour (normal, metallic-roughness and occlusion
  // maps): its image stored as linear GL_RGBA8, so the sampler returns the file's values.
  void bindLinearTexture(int index, GLuint unit) const;

 private:
  const Scene* scene_;
  std::vector<GpuMesh> meshes_;
  std::vector<gl::Texture> images_;
  std::vector<gl::Texture> linearImages_;  // by image; empty where no material reads it as data
  std::vector<gl::Sampler> samplers_;
};

}  // namespace lenslab
