#include "io/ImageCompare.h"

#include "io/ImageFile.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lenslab {

namespace {

// An OpenImageIO view of the image's own pixels (no copy): RGBA float, rows from the top.
OIIO::ImageBuf wrap(const Image& image) {
  const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  return OIIO::ImageBuf(spec, const_cast<float*>(image.rgba.data()));
}

}  // namespace

ImageDifference compareImages(const Image& a, const Image& b, double threshold) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
  // OpenImageIO's comparison (what `idiff` reports), over the colour channels only: alpha is
  // coverage and is compared where a test means to.
  const OIIO::ROI colour(0, a.width, 0, a.height, 0, 1, 0, 3);
  const auto r = OIIO::ImageBufAlgo::compare(wrap(a), wrap(b), static_cast<float>(threshold),
                                             static_cast<float>(threshold), colour);
  ImageDifference d;
  d.maxAbs = r.maxerror;
  d.rmse = r.rms_error;
  d.psnrDb = r.rms_error > 0.0 ? -20.0 * std::log10(r.rms_error) : std::numeric_limits<double>::infinity();
  const double pixels = static_cast<double>(a.width) * a.height;
  d.fractionOver = pixels > 0.0 ? static_cast<double>(r.nfail) / pixels : 0.0;
  return d;
}

Image displayEncoded(const Image& linear) {
  Image out(linear.width, linear.height);
  for (std::size_t i = 0; i < linear.rgba.size(); ++i) {
    const float v = i % 4 == 3 ? linear.rgba[i] : srgbFromLinear(linear.rgba[i]);
    out.rgba[i] = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
  }
  return out;
}

Image differenceImage(const Image& a, const Image& b, float gain) {
  Image out(a.width, a.height);
  OIIO::ImageBuf result = wrap(out);
  OIIO::ImageBufAlgo::absdiff(result, wrap(a), wrap(b));
  OIIO::ImageBufAlgo::mul(result, result, {gain, gain, gain, 0.0f});
  OIIO::ImageBufAlgo::add(result, result, {0.0f, 0.0f, 0.0f, 1.0f});  // opaque, for eyes
  return out;
}

}  // namespace lenslab
