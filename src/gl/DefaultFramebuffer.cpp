#include "gl/DefaultFramebuffer.h"

#include <glad/gl.h>

#include <vector>

namespace lenslab::gl {

void bindDefaultFramebuffer(int widthPx, int heightPx) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, widthPx, heightPx);
  glDisable(GL_SCISSOR_TEST);
}

void clearDefaultFramebuffer(int widthPx, int heightPx, const glm::vec4& color) {
  bindDefaultFramebuffer(widthPx, heightPx);
  glClearBufferfv(GL_COLOR, 0, &color.r);
}

Image readDefaultFramebuffer(int widthPx, int heightPx) {
  const std::size_t width = static_cast<std::size_t>(widthPx);
  std::vector<unsigned char> rgba(width * static_cast<std::size_t>(heightPx) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, widthPx, heightPx, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image image(widthPx, heightPx);
  for (int y = 0; y < heightPx; ++y) {
    for (int x = 0; x < widthPx; ++x) {
      // GL rows start at the bottom.
      const unsigned char* p =
          &rgba[(static_cast<std::size_t>(heightPx - 1 - y) * width + static_cast<std::size_t>(x)) * 4];
      image.set(x, y, {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, 1.0f});
    }
  }
  return image;
}

}  // namespace lenslab::gl
