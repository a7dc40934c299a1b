#pragma once
// The environment on the GPU: its maps as float textures (texture units 5–7: the background,
// the specular levels 1 … n − 1 as an array, the diffuse map; fetched texel by texel, never
// filtered by the GPU: shaders/common/environment.glsl interpolates as the C++ does), and the
// pass that draws it behind a view.
#include "gl/FullScreenPass.h"
#include "gl/Object.h"
#include "scene/Environment.h"

#include <glm/glm.hpp>

namespace lenslab {

// The 3 × 3 matrix M with M · (x, y, 1) along the world direction of the ray through NDC (x, y)
// of a view with this clipFromWorld (perspective, or parallel with reverse-Z), pointing into the
// view: from its linear part alone (no eye position), in double, scaled to a largest entry of 1.
glm::dmat3 worldDirectionFromNdc(const glm::dmat4& clipFromWorld);

class GpuEnvironment {
 public:
  explicit GpuEnvironment(const EnvironmentLookup& lookup);  // uploads the maps (needs a context)

  // Binds the maps to their units and sets `program`'s environment uniforms (locations 100–103,
  // shaders/common/locations.glsl). `program` may leave any of them unused.
  void bind(GLuint program) const;
  // Draws the background into the bound target (`widthPx` × `heightPx`) where depth is still far
  // (reverse-Z 0), leaving alpha, depth and stencil as they are; colour × `weight`, added to what
  // is there when `add`, else replacing it. The caller's scissor and stencil test apply.
  void drawBackground(const glm::dmat4& clipFromWorld, int widthPx, int heightPx, const glm::vec3& weight,
                      bool add) const;

  const EnvironmentLookup& lookup() const { return *lookup_; }

 private:
  const EnvironmentLookup* lookup_;
  gl::Texture background_;
  gl::TextureArray specular_;
  gl::Texture diffuse_;
  gl::Program program_;
  gl::FullScreenPass fullScreen_;
};

}  // namespace lenslab
