#include "io/StripImageWriter.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/ImageFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace lenslab {
namespace fs = std::filesystem;

struct StripImageWriter::Output {
  std::unique_ptr<OIIO::ImageOutput> image;
};

StripImageWriter::StripImageWriter(OutputSet& outputs, const fs::path& path, ImageSize size)
    : target_((checkImageExtension(path), path)),
      out_(std::make_unique<Output>()),
      size_(size),
      png_(lowerExtension(path) == ".png") {
  temporary_ = outputs.addStreamed(path);
  const std::string temporary = temporary_.string();
  out_->image = OIIO::ImageOutput::create(temporary);
  if (!out_->image) throw InputError(cat(path.string(), ": cannot write it: ", oneLine(OIIO::geterror())));
  // As writeImage: PNG RGB only, already over the background; EXR RGBA, A the coverage.
  const int channels = png_ ? 3 : 4;
  bytesPerPixel_ = png_ ? 3 : 4 * static_cast<int>(sizeof(float));
  OIIO::ImageSpec spec(size.widthPx, size.heightPx, channels, png_ ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.attribute("oiio:ColorSpace", png_ ? "sRGB" : "Linear");
  spec.attribute("Software", "lenslab");
  if (!out_->image->open(temporary, spec))
    throw InputError(cat(path.string(), ": cannot write it: ", oneLine(out_->image->geterror())));
}

StripImageWriter::~StripImageWriter() {
  // Not finished (an exception on the way): close quietly; the OutputSet removes the temporary file.
  if (out_ && out_->image) out_->image->close();
}

void StripImageWriter::add(int x0, int y0, const Image& block) {
  if (!out_->image) throw std::logic_error("StripImageWriter::add after finish");
  if (stripPixelsAdded_ == 0) {
    // A new strip: the rows after the last one.
    if (y0 != stripY1_ || block.height < 1 || y0 + block.height > size_.heightPx)
      throw std::logic_error(cat("StripImageWriter: a strip must start at row ", stripY1_, ", not ", y0));
    stripY0_ = y0;
    stripY1_ = y0 + block.height;
    strip_.assign(static_cast<std::size_t>(size_.widthPx) * static_cast<std::size_t>(block.height) *
                      static_cast<std::size_t>(bytesPerPixel_),
                  0);
  } else if (y0 != stripY0_ || y0 + block.height != stripY1_) {
    throw std::logic_error(cat("StripImageWriter: a block at rows ", y0, " to ", y0 + block.height,
                               " is not in the strip being written (rows ", stripY0_, " to ", stripY1_, ")"));
  }
  if (x0 < 0 || x0 + block.width > size_.widthPx) throw std::logic_error("StripImageWriter: a block outside the image");
  for (int y = 0; y < block.height; ++y) {
    std::uint8_t* row =
        &strip_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(size_.widthPx) + static_cast<std::size_t>(x0)) *
                static_cast<std::size_t>(bytesPerPixel_)];
    const float* from = &block.rgba[block.offset(0, y)];
    if (png_) {
      // Exactly writeImage's encoding of each channel.
      for (int x = 0; x < block.width; ++x)
        for (int c = 0; c < 3; ++c)
          row[3 * x + c] = static_cast<std::uint8_t>(std::lround(srgbFromLinear(from[4 * x + c]) * 255.0f));
    } else {
      std::memcpy(row, from, static_cast<std::size_t>(block.width) * 4 * sizeof(float));
    }
  }
  stripPixelsAdded_ += std::int64_t{block.width} * block.height;
  const std::int64_t stripPixels = std::int64_t{size_.widthPx} * (stripY1_ - stripY0_);
  if (stripPixelsAdded_ > stripPixels) throw std::logic_error("StripImageWriter: blocks overlap");
  if (stripPixelsAdded_ == stripPixels) writeStrip();
}

void StripImageWriter::writeStrip() {
  const OIIO::TypeDesc type = png_ ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  if (!out_->image->write_scanlines(stripY0_, stripY1_, 0, type, strip_.data()) || out_->image->has_error())
    throw InputError(cat(target_.string(), ": cannot write it: ", oneLine(out_->image->geterror())));
  stripPixelsAdded_ = 0;
}

void StripImageWriter::finish() {
  if (!out_->image) throw std::logic_error("StripImageWriter::finish twice");
  if (stripPixelsAdded_ != 0 || stripY1_ != size_.heightPx)
    throw std::logic_error(cat("StripImageWriter::finish with rows ", stripY1_, " of ", size_.heightPx, " written"));
  const bool closed = out_->image->close() && !out_->image->has_error();
  const std::string error = closed ? std::string() : oneLine(out_->image->geterror());
  out_->image.reset();
  if (!closed) throw InputError(cat(target_.string(), ": cannot write it: ", error));
  strip_.clear();
  strip_.shrink_to_fit();
  if (png_) {
    // A PNG that was cut short (a full disk that the writer did not report) lacks its last chunk.
    static const unsigned char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    std::ifstream in(temporary_, std::ios::binary | std::ios::ate);
    unsigned char tail[12] = {};
    const bool ok = in && in.tellg() >= 12 && in.seekg(-12, std::ios::end) &&
                    in.read(reinterpret_cast<char*>(tail), 12) &&
                    std::equal(std::begin(tail), std::end(tail), std::begin(kIend));
    if (!ok) throw InputError(cat(target_.string(), ": cannot write it: the PNG was cut short (is the disk full?)"));
  }
}

}  // namespace lenslab
