#pragma once
// A linear-light RGBA float image, rows from the top. What renderers produce and files store.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace lenslab {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  // width * height * 4, row 0 at the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.0f) {}

  std::size_t offset(int x, int y) const { return (static_cast<std::size_t>(y) * width + x) * 4; }
  glm::vec4 at(int x, int y) const {
    const float* p = &rgba[offset(x, y)];
    return {p[0], p[1], p[2], p[3]};
  }
  void set(int x, int y, const glm::vec4& c) {
    float* p = &rgba[offset(x, y)];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
    p[3] = c.a;
  }
};

}  // namespace lenslab
