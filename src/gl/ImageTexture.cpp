#include "gl/ImageTexture.h"

#include <stdexcept>

namespace lenslab::gl {

ImageTexture::ImageTexture(int widthPx, int heightPx)
    : texture_(Texture::create()), width_(widthPx), height_(heightPx) {
  glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, widthPx, heightPx);
}

void ImageTexture::upload(const Image& image) {
  if (image.width != width_ || image.height != height_) throw std::logic_error("ImageTexture::upload: size differs");
  for (int y = 0; y < image.height; ++y)  // one row at a time, flipped
    glTextureSubImage2D(texture_.id(), 0, 0, image.height - 1 - y, image.width, 1, GL_RGBA, GL_FLOAT,
                        &image.rgba[image.offset(0, y)]);
}

void ImageTexture::copyColor(const RenderTarget& source) {
  if (source.width() != width_ || source.height() != height_)
    throw std::logic_error("ImageTexture::copyColor: size differs");
  glCopyImageSubData(source.colorTexture(), GL_TEXTURE_2D, 0, 0, 0, 0, texture_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width_,
                     height_, 1);
}

}  // namespace lenslab::gl
