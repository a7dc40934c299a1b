#pragma once
// The lens post pass: distortion and lateral chromatic aberration applied to the finished
// (accumulated) true perspective image, through lookup tables of the inverse lens model
// (camera/LensMap.h). The tables are rebuilt only when the lens, the window or the sizes change,
// not per frame.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/LensMap.h"
#include "gl/Framebuffer.h"
#include "gl/Object.h"

#include <vector>

namespace lenslab {

class LensPass {
 public:
  LensPass();  // needs a current context

  // Makes the tables for this camera and image size; a no-op when nothing changed since the last call.
  void prepare(const Camera& camera, ImageSize size, const Overscan& overscan);
  // Remaps `undistorted` (the overscanned render) into `out` (the image size).
  void apply(const gl::RenderTarget& undistorted, const gl::RenderTarget& out);
  int tablesBuilt() const { return tablesBuilt_; }  // how many times prepare rebuilt the tables

 private:
  gl::Program program_;
  gl::Program perChannelProgram_;  // the lateral-colour variant, built on first use
  gl::VertexArray emptyVertexArray_;
  std::vector<gl::Texture> tables_;  // RG32F texture coordinates: green, or red, green, blue
  std::vector<double> key_;          // what the tables were made for
  int tablesBuilt_ = 0;
};

}  // namespace lenslab
