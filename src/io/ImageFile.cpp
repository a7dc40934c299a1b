#include "io/ImageFile.h"

#include "core/Error.h"
#include "core/Text.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {
namespace fs = std::filesystem;

float srgbFromLinear(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

bool isDisplayReferred(const fs::path& path) { return lowerExtension(path) == ".png"; }

void applyDisplayForFile(const fs::path& path, Image& image, const DisplayEncoding& display) {
  if (display.isIdentity() || !isDisplayReferred(path)) return;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    float* p = &image.rgba[i];
    const glm::vec3 d = displayLinear({p[0], p[1], p[2]}, display);
    p[0] = d.r, p[1] = d.g, p[2] = d.b;
  }
}

float linearFromSrgb(float x) { return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f); }

void checkImageExtension(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".png" && ext != ".exr")
    throw InputError(
        cat(path.string(), ": unsupported image type '", ext, "'; use .png (8-bit sRGB) or .exr (linear float)"));
}

std::string encodeImage(const fs::path& path, const Image& image, const std::vector<float>* depthZ) {
  if (!depthZ) return encodeImage(path, image, std::vector<ImageChannel>{});
  return encodeImage(path, image, std::vector<ImageChannel>{{"Z", *depthZ}});
}

std::string encodeImage(const fs::path& path, const Image& image, const std::vector<ImageChannel>& extra) {
  checkImageExtension(path);
  const bool png = lowerExtension(path) == ".png";
  if (!extra.empty() && png) {
    std::string names;
    for (const ImageChannel& c : extra) names += (names.empty() ? "" : ", ") + c.name;
    throw InputError(cat(path.string(), ": channels ", names, " need .exr (PNG holds 8-bit colour only)"));
  }
  for (const ImageChannel& c : extra)
    if (c.values.size() != image.rgba.size() / 4)
      throw std::logic_error("encodeImage: a channel's and the image's sizes differ");
  auto out = OIIO::ImageOutput::create(path.filename().string());  // the format, by extension
  if (!out) throw InputError(cat(path.string(), ": cannot write it: ", oneLine(OIIO::geterror())));
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory))
    throw InputError(
        cat(path.string(), ": cannot write it: this OpenImageIO cannot encode ", lowerExtension(path), " in memory"));
  // PNG: RGB only, already over the background (an alpha channel would make viewers composite it
  // a second time). EXR: RGBA, A the coverage (the fraction of the pixel × aperture that sees a
  // surface); RGB includes the background over 1 − A, so with --background 0,0,0 it is
  // premultiplied RGBA in OpenEXR's convention, ready to composite.
  const int channels = png ? 3 : 4 + static_cast<int>(extra.size());
  OIIO::ImageSpec spec(image.width, image.height, channels, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (!extra.empty()) {
    spec.channelnames = {"R", "G", "B", "A"};
    for (const ImageChannel& c : extra) {
      if (c.name == "Z") spec.z_channel = static_cast<int>(spec.channelnames.size());
      spec.channelnames.push_back(c.name);
    }
  }
  spec.attribute("oiio:ColorSpace", png ? "sRGB" : "Linear");
  spec.attribute("Software", "lenslab");
  if (!out->open(path.filename().string(), spec))
    throw InputError(cat(path.string(), ": cannot write it: ", oneLine(out->geterror())));
  bool ok = false;
  if (png) {
    std::vector<std::uint8_t> encoded(image.rgba.size() / 4 * 3);
    for (std::size_t i = 0; i < encoded.size(); ++i)
      encoded[i] = static_cast<std::uint8_t>(std::lround(srgbFromLinear(image.rgba[i / 3 * 4 + i % 3]) * 255.0f));
    ok = out->write_image(OIIO::TypeDesc::UINT8, encoded.data());
  } else if (!extra.empty()) {
    const std::size_t n = 4 + extra.size(), pixels = image.rgba.size() / 4;
    std::vector<float> interleaved(pixels * n);
    for (std::size_t i = 0; i < pixels; ++i) {
      for (std::size_t k = 0; k < 4; ++k) interleaved[i * n + k] = image.rgba[i * 4 + k];
      for (std::size_t k = 0; k < extra.size(); ++k) interleaved[i * n + 4 + k] = extra[k].values[i];
    }
    ok = out->write_image(OIIO::TypeDesc::FLOAT, interleaved.data());
  } else {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data());
  }
  // has_error() as well: the PNG writer records some failures there and still returns true.
  ok = ok && !out->has_error();
  ok = out->close() && ok && !out->has_error();
  if (!ok) throw InputError(cat(path.string(), ": cannot write it: ", oneLine(out->geterror())));
  return std::string(bytes.begin(), bytes.end());
}

std::optional<std::string> radianceOverflowWarning(const Image& linear) {
  std::size_t pixels = 0;
  for (std::size_t i = 0; i + 3 < linear.rgba.size(); i += 4)
    pixels +=
        !std::isfinite(linear.rgba[i]) || !std::isfinite(linear.rgba[i + 1]) || !std::isfinite(linear.rgba[i + 2]);
  if (pixels == 0) return std::nullopt;
  return cat(pixels, " pixel", pixels == 1 ? "" : "s",
             " hold radiance past a float's range (above 3.4e38: written as inf in .exr, white in .png); scale the "
             "scene's lights or emission down");
}

void writeImage(OutputSet& outputs, const fs::path& path, const Image& image, const std::vector<float>* depthZ) {
  outputs.add(path, encodeImage(path, image, depthZ));
}

void writeImage(OutputSet& outputs, const fs::path& path, const Image& image,
                const std::vector<ImageChannel>& channels) {
  outputs.add(path, encodeImage(path, image, channels));
}

void writeImage(const fs::path& path, const Image& image) {
  OutputSet output;
  writeImage(output, path, image);
  output.commit();
}

Image readImage(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(cat(path.string(), ": cannot read image: ", oneLine(OIIO::geterror())));
  const OIIO::ImageSpec& spec = in->spec();
  Image image(spec.width, spec.height);
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError(cat(path.string(), ": cannot read image: ", oneLine(in->geterror())));
  const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const float* p = &pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels];
      glm::vec4 c(0.0f, 0.0f, 0.0f, 1.0f);
      for (int k = 0; k < std::min(spec.nchannels, 4); ++k) c[k] = p[k];
      if (spec.nchannels < 3) c.g = c.b = c.r;
      if (encoded)
        for (int k = 0; k < 3; ++k) c[k] = linearFromSrgb(c[k]);
      image.set(x, y, c);
    }
  return image;
}

std::vector<float> readDepthChannel(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(cat(path.string(), ": cannot read image: ", oneLine(OIIO::geterror())));
  const OIIO::ImageSpec& spec = in->spec();
  int z = -1;
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channelnames[static_cast<std::size_t>(c)] == "Z") z = c;
  if (z < 0) throw InputError(cat(path.string(), ": has no Z (depth) channel"));
  std::vector<float> depth(static_cast<std::size_t>(spec.width) * spec.height);
  if (!in->read_image(0, 0, z, z + 1, OIIO::TypeDesc::FLOAT, depth.data()))
    throw InputError(cat(path.string(), ": cannot read image: ", oneLine(in->geterror())));
  return depth;
}

std::vector<float> readChannel(const fs::path& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(cat(path.string(), ": cannot read image: ", oneLine(OIIO::geterror())));
  const OIIO::ImageSpec& spec = in->spec();
  int found = -1;
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channelnames[static_cast<std::size_t>(c)] == name) found = c;
  if (found < 0) throw InputError(cat(path.string(), ": has no channel ", name));
  std::vector<float> values(static_cast<std::size_t>(spec.width) * spec.height);
  if (!in->read_image(0, 0, found, found + 1, OIIO::TypeDesc::FLOAT, values.data()))
    throw InputError(cat(path.string(), ": cannot read image: ", oneLine(in->geterror())));
  return values;
}

std::vector<std::string> channelNames(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(cat(path.string(), ": cannot read image: ", oneLine(OIIO::geterror())));
  return in->spec().channelnames;
}

}  // namespace lenslab
