#include "gl/Framebuffer.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace lenslab::gl {

RenderTarget::RenderTarget(int widthPx, int heightPx)
    : width_(widthPx),
      height_(heightPx),
      color_(Texture::create()),
      depth_(Texture::create()),
      framebuffer_(Framebuffer::create()) {
  glTextureStorage2D(color_.id(), 1, GL_RGBA32F, width_, height_);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width_, height_);
  for (GLuint t : {color_.id(), depth_.id()}) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("render target " + std::to_string(width_) + "x" + std::to_string(height_) +
                             " is incomplete (status " + std::to_string(status) + ")");
}

void DrawTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
}

Image RenderTarget::readColor() const {
  Image image(width_, height_);
  std::vector<float> bottomUp(image.rgba.size());
  glGetTextureImage(color_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)),
                    bottomUp.data());
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y)
    std::memcpy(&image.rgba[static_cast<std::size_t>(y) * row],
                &bottomUp[static_cast<std::size_t>(height_ - 1 - y) * row], row * sizeof(float));
  return image;
}

std::vector<float> RenderTarget::readDepth() const {
  std::vector<float> bottomUp(static_cast<std::size_t>(width_) * height_);
  glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)),
                    bottomUp.data());
  std::vector<float> topDown(bottomUp.size());
  const std::size_t row = static_cast<std::size_t>(width_);
  for (int y = 0; y < height_; ++y)
    std::memcpy(&topDown[static_cast<std::size_t>(y) * row], &bottomUp[static_cast<std::size_t>(height_ - 1 - y) * row],
                row * sizeof(float));
  return topDown;
}

}  // namespace lenslab::gl
