#pragma once
// Writes an image that is never whole in memory: blocks of pixels (a tiled render's tiles) arrive
// a strip of rows at a time, and each strip goes to the file through OpenImageIO's scanline
// interface as soon as its rows are complete. Memory: one strip, in the file's pixel type.
//
// Per pixel the same as writeImage (io/ImageFile.h): .png is 8-bit sRGB RGB (the image already
// over the background; values clamped, srgbFromLinear, rounded); .exr is linear 32-bit float RGBA.
// Atomic like writeImage: the file is written to a temporary file of an OutputSet, and appears
// (with the run's other files) when the set is committed, never partly written.
#include "camera/ImageSize.h"
#include "core/Image.h"
#include "io/AtomicFile.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace lenslab {

class StripImageWriter {
 public:
  // Opens the temporary file for `path` in `outputs`. Throws InputError naming `path` for an
  // unsupported extension or when OpenImageIO cannot create or open it.
  StripImageWriter(OutputSet& outputs, const std::filesystem::path& path, ImageSize size);
  ~StripImageWriter();
  StripImageWriter(const StripImageWriter&) = delete;
  StripImageWriter& operator=(const StripImageWriter&) = delete;

  // Pixels `block` at (x0, y0) of the image. Blocks come strip by strip from the top: the first
  // block of a strip starts at the row after the previous strip and fixes the strip's height; the
  // strip's other blocks share its rows, and together they cover it exactly once. Throws
  // std::logic_error for a block that breaks this, InputError when a write fails.
  void add(int x0, int y0, const Image& block);
  // Checks that every row was written and closes the file (checking the close and, for PNG, that
  // the file ends with its IEND chunk: OpenImageIO's PNG writer can report success after a failed
  // write). The OutputSet's commit() then puts it in place.
  void finish();

  std::int64_t bytesBuffered() const { return static_cast<std::int64_t>(strip_.size()); }

 private:
  void writeStrip();

  struct Output;  // OpenImageIO's ImageOutput
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::unique_ptr<Output> out_;
  ImageSize size_;
  bool png_ = false;
  int bytesPerPixel_ = 0;
  std::vector<std::uint8_t> strip_;  // the strip's rows, in the file's pixel type
  int stripY0_ = 0;                  // the strip's rows: [stripY0_, stripY1_)
  int stripY1_ = 0;
  std::int64_t stripPixelsAdded_ = 0;
};

}  // namespace lenslab
