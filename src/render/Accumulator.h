#pragma once
// Thin-lens depth of field by accumulation: each aperture view is added into a float sum, and the
// image is the sum over the count. start / add / resolve let the samples spread over frames (the
// interactive demo converges progressively).
#include "gl/Framebuffer.h"
#include "gl/Object.h"

#include <memory>

namespace lenslab {

class Accumulator {
 public:
  Accumulator();  // builds the programs (needs a current context)

  void start(int widthPx, int heightPx);   // clears the sum
  void add(const gl::RenderTarget& view);  // sum += view
  int count() const { return count_; }
  // The mean so far, into `out` (same size).
  void resolve(const gl::RenderTarget& out) const;

 private:
  gl::Program accumulate_;
  gl::Program resolve_;
  gl::VertexArray emptyVertexArray_;  // core profile needs one bound even without attributes
  std::unique_ptr<gl::RenderTarget> sum_;
  int count_ = 0;
};

}  // namespace lenslab
