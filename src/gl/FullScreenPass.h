#pragma once
// One triangle that covers the viewport, for passes that compute each pixel in a fragment shader
// (accumulate, resolve, the lens remap, the gather baseline, the viewer's image display). Their
// programs use shaders/common/fullscreen.vert, which makes the positions from gl_VertexID.
#include "gl/Object.h"

namespace lenslab::gl {

class FullScreenPass {
 public:
  FullScreenPass();  // needs a current context

  // Draws the triangle with `program` into the bound framebuffer and viewport. The caller sets
  // the state the pass needs (depth test, blending, textures, uniforms) beforehand.
  void draw(GLuint program) const;
  void draw(const Program& program) const { draw(program.id()); }

 private:
  VertexArray emptyVertexArray_;  // the core profile needs one bound even without attributes
};

}  // namespace lenslab::gl
