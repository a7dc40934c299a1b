#include "io/AovFiles.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/AovChannels.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

static_assert(std::endian::native == std::endian::little, ".npy's '<f4' and '<i4' are written as memory holds them");

fs::path beside(const fs::path& image, const std::string& suffix) {
  fs::path p = image;
  p.replace_extension();
  return p.string() + suffix;
}

// `values` of `type` as an image file named like `name` (its extension picks the format), in memory.
std::string encodeWithOiio(const fs::path& name, const OIIO::ImageSpec& spec, OIIO::TypeDesc type, const void* values) {
  auto out = OIIO::ImageOutput::create(name.filename().string());
  if (!out) throw InputError(cat(name.string(), ": cannot write it: ", OIIO::geterror()));
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory) || !out->open(name.filename().string(), spec))
    throw InputError(cat(name.string(), ": cannot write it: ", out->geterror()));
  bool ok = out->write_image(type, values) && !out->has_error();
  ok = out->close() && ok && !out->has_error();
  if (!ok) throw InputError(cat(name.string(), ": cannot write it: ", out->geterror()));
  return std::string(bytes.begin(), bytes.end());
}

// The AOV channels alone, as a float EXR.
std::string encodeChannelExr(const fs::path& name, const std::vector<ImageChannel>& channels, int width, int height) {
  OIIO::ImageSpec spec(width, height, static_cast<int>(channels.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames.clear();
  for (const ImageChannel& c : channels) {
    if (c.name == "Z") spec.z_channel = static_cast<int>(spec.channelnames.size());
    spec.channelnames.push_back(c.name);
  }
  spec.attribute("Software", "lenslab");
  const std::size_t n = channels.size(), pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<float> interleaved(pixels * n);
  for (std::size_t i = 0; i < pixels; ++i)
    for (std::size_t k = 0; k < n; ++k) interleaved[i * n + k] = channels[k].values[i];
  return encodeWithOiio(name, spec, OIIO::TypeDesc::FLOAT, interleaved.data());
}

std::string npyHeader(const char* descr, const std::vector<std::size_t>& shape) {
  std::string dims;
  for (const std::size_t d : shape) dims += cat(dims.empty() ? "" : ", ", d);
  if (shape.size() == 1) dims += ",";  // Python's one-element tuple: (N,)
  std::string header = cat("{'descr': '", descr, "', 'fortran_order': False, 'shape': (", dims, "), }");
  // Magic (6) + version (2) + length (2) + header, padded with spaces and ended by \n to a
  // multiple of 64 bytes, so that the data is aligned (the format's own rule).
  const std::size_t total = (10 + header.size() + 1 + 63) / 64 * 64;
  header.append(total - 10 - header.size() - 1, ' ');
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  return out + header;
}

template <class T>
std::string npy(const char* descr, const std::vector<T>& values, const std::vector<std::size_t>& shape) {
  std::string out = npyHeader(descr, shape);
  const std::size_t at = out.size();
  out.resize(at + values.size() * sizeof(T));
  std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
  return out;
}

std::uint16_t unit16(double v) { return static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0)); }

// The instance ids files hold: node index + 1, 0 where nothing is hit.
std::vector<std::int32_t> instanceIds(const std::vector<float>& instance) {
  std::vector<std::int32_t> ids(instance.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::int32_t>(instance[i]) + 1;
  return ids;
}

void writeNpy(OutputSet& outputs, const fs::path& image, const AovImages& a) {
  const std::size_t h = static_cast<std::size_t>(a.heightPx), w = static_cast<std::size_t>(a.widthPx);
  if (!a.depth.empty()) outputs.add(beside(image, ".depth.npy"), encodeNpy(a.depth, {h, w}));
  if (!a.normal.empty()) outputs.add(beside(image, ".normal.npy"), encodeNpy(a.normal, {h, w, 3}));
  if (!a.albedo.empty()) outputs.add(beside(image, ".albedo.npy"), encodeNpy(a.albedo, {h, w, 3}));
  if (!a.instance.empty()) outputs.add(beside(image, ".instance.npy"), encodeNpy(instanceIds(a.instance), {h, w}));
  if (!a.flow.empty()) outputs.add(beside(image, ".flow.npy"), encodeNpy(a.flow, {h, w, 2}));
}

// KITTI's flow PNG: R = u·64 + 2¹⁵, G = v·64 + 2¹⁵, B = 1 where the flow is known.
void writeKittiFlow(OutputSet& outputs, const fs::path& image, const AovImages& a, std::vector<std::string>& warnings) {
  std::vector<std::uint16_t> out(a.flow.size() / 2 * 3, 0);
  std::size_t clamped = 0;
  for (std::size_t i = 0; i < a.flow.size() / 2; ++i) {
    const float u = a.flow[2 * i], v = a.flow[2 * i + 1];
    if (!std::isfinite(u) || !std::isfinite(v)) continue;
    const auto code = [&](float f) {
      const double c = std::round(f * 64.0 + 32768.0);
      clamped += c < 0.0 || c > 65535.0;
      return static_cast<std::uint16_t>(std::clamp(c, 0.0, 65535.0));
    };
    out[3 * i] = code(u), out[3 * i + 1] = code(v), out[3 * i + 2] = 1;
  }
  const fs::path file = beside(image, ".flow.png");
  if (clamped)
    warnings.push_back(cat(file.string(), ": ", clamped,
                           " flow components beyond ±512 px, held there (KITTI's "
                           "range); --aov-format npy or exr holds any flow"));
  outputs.add(file, encodePng16(file, out, a.widthPx, a.heightPx, 3));
}

void writePng16(OutputSet& outputs, const fs::path& image, const AovImages& a, std::vector<std::string>& warnings) {
  const int w = a.widthPx, h = a.heightPx;
  if (!a.depth.empty()) {
    std::vector<std::uint16_t> mm(a.depth.size());
    std::size_t beyond = 0;
    for (std::size_t i = 0; i < mm.size(); ++i) {
      const double d = a.depth[i];
      if (std::isinf(d)) continue;  // 0: nothing hit
      const double m = std::round(d * 1000.0);
      beyond += m > 65535.0;
      mm[i] = static_cast<std::uint16_t>(std::clamp(m, 1.0, 65535.0));
    }
    if (beyond)
      warnings.push_back(cat(beside(image, ".depth.png").string(), ": ", beyond, " pixel", beyond == 1 ? "" : "s",
                             " lie beyond 65.535 m, held at 65535 mm; --aov-format npy or exr holds any depth"));
    const fs::path file = beside(image, ".depth.png");
    outputs.add(file, encodePng16(file, mm, w, h, 1));
  }
  const auto rgb = [&](const std::vector<float>& v, const char* suffix, double offset, double scale) {
    std::vector<std::uint16_t> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = unit16((v[i] + offset) * scale);
    const fs::path file = beside(image, suffix);
    outputs.add(file, encodePng16(file, out, w, h, 3));
  };
  if (!a.normal.empty()) rgb(a.normal, ".normal.png", 1.0, 0.5);
  if (!a.albedo.empty()) rgb(a.albedo, ".albedo.png", 0.0, 1.0);
  if (!a.instance.empty()) {
    const std::vector<std::int32_t> ids = instanceIds(a.instance);
    std::vector<std::uint16_t> out(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] > 65535)
        throw InputError(cat("--aov-format png16: ", beside(image, ".instance.png").string(), ": instance id ", ids[i],
                             " (glTF node ", ids[i] - 1, ") does not fit 16 bits; give --aov-format npy (int32)"));
      out[i] = static_cast<std::uint16_t>(ids[i]);
    }
    const fs::path file = beside(image, ".instance.png");
    outputs.add(file, encodePng16(file, out, w, h, 1));
  }
  if (!a.flow.empty()) writeKittiFlow(outputs, image, a, warnings);
}

}  // namespace

AovFormat parseAovFormat(const std::string& text) {
  if (text == "exr") return AovFormat::Exr;
  if (text == "npy") return AovFormat::Npy;
  if (text == "png16") return AovFormat::Png16;
  throw InputError(cat("--aov-format ", text, ": use exr, npy or png16"));
}

NormalConvention parseNormalConvention(const std::string& text) {
  if (text == "gl") return NormalConvention::Gl;
  if (text == "opencv") return NormalConvention::OpenCv;
  throw InputError(cat("--normal-convention ", text, ": use gl or opencv"));
}

std::vector<fs::path> aovFilePaths(const AovOutput& o, const fs::path& image) {
  const AovSelection& s = o.selection;
  if (!s.any()) return {};
  if (o.format == AovFormat::Exr)
    return lowerExtension(image) == ".exr" ? std::vector<fs::path>{} : std::vector{beside(image, ".aov.exr")};
  const std::string ext = o.format == AovFormat::Npy ? ".npy" : ".png";
  std::vector<fs::path> files;
  for (const std::string& name : s.names()) files.push_back(beside(image, "." + name + ext));
  return files;
}

void applyNormalConvention(AovImages& images, NormalConvention convention) {
  if (convention == NormalConvention::Gl) return;
  // OpenCV's camera frame: x right, y down, z forward (the view direction): GL's y and z negated.
  for (std::size_t i = 0; i + 2 < images.normal.size(); i += 3) {
    images.normal[i + 1] = -images.normal[i + 1];
    images.normal[i + 2] = -images.normal[i + 2];
  }
}

std::vector<ImageChannel> writeAovFiles(OutputSet& outputs, const fs::path& image, AovImages images, const AovOutput& o,
                                        std::vector<std::string>& warnings) {
  if (!o.selection.any()) return {};
  applyNormalConvention(images, o.normals);
  switch (o.format) {
    case AovFormat::Exr:
      if (lowerExtension(image) == ".exr") return aovChannels(images);
      outputs.add(beside(image, ".aov.exr"),
                  encodeChannelExr(beside(image, ".aov.exr"), aovChannels(images), images.widthPx, images.heightPx));
      return {};
    case AovFormat::Npy: writeNpy(outputs, image, images); return {};
    case AovFormat::Png16: writePng16(outputs, image, images, warnings); return {};
  }
  return {};
}

std::string encodeNpy(const std::vector<float>& values, const std::vector<std::size_t>& shape) {
  return npy("<f4", values, shape);
}

std::string encodeNpy(const std::vector<std::int32_t>& values, const std::vector<std::size_t>& shape) {
  return npy("<i4", values, shape);
}

std::string encodePng16(const fs::path& name, const std::vector<std::uint16_t>& values, int width, int height,
                        int channels) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT16);
  spec.attribute("Software", "lenslab");
  spec.attribute("oiio:ColorSpace", "Linear");  // data, not sRGB colour
  return encodeWithOiio(name, spec, OIIO::TypeDesc::UINT16, values.data());
}

}  // namespace lenslab
