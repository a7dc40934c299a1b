#include "scene/gltf/Images.h"

#include "scene/gltf/Limits.h"
#include "scene/gltf/Problems.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <string_view>
#include <vector>

namespace lenslab::gltf {

namespace {

std::uint32_t bigEndian(Bytes bytes, std::size_t at, std::size_t count) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < count; ++i) v = v << 8 | bytes[at + i];
  return v;
}

// PNG: an 8-byte signature, then chunks (4-byte big-endian length, type, data, CRC), IHDR first
// (width, height), IEND last. Walking them finds a cut-off file without inflating anything.
ImageHeader inspectPng(Bytes b, const std::string& label) {
  ImageHeader header{ImageFormat::Png};
  for (std::size_t at = 8, index = 0;; ++index) {
    if (b.size() - at < 12 || bigEndian(b, at, 4) > b.size() - at - 12)
      refuse(label, ": PNG data ends before its IEND chunk (the file is cut off)");
    const std::uint32_t length = bigEndian(b, at, 4);
    const std::string_view type(reinterpret_cast<const char*>(&b[at + 4]), 4);
    if (index == 0) {
      if (type != "IHDR" || length != 13) refuse(label, ": PNG does not start with its IHDR chunk");
      header.width = bigEndian(b, at + 8, 4);
      header.height = bigEndian(b, at + 12, 4);
    }
    if (type == "IEND") return header;
    at += 12 + length;
  }
}

// JPEG: after SOI (FF D8), segments of FF, a marker and (but for RSTn and TEM) a 2-byte length
// that counts itself; the frame header (SOF0-SOF15 but DHT, JPG, DAC) holds height, then width.
ImageHeader inspectJpeg(Bytes b, const std::string& label) {
  for (std::size_t at = 2;;) {
    if (b.size() - at < 4) refuse(label, ": JPEG data ends before its frame header (the file is cut off)");
    if (b[at] != 0xFF) refuse(label, ": JPEG segment marker expected at byte ", at);
    const unsigned marker = b[at + 1];
    if (marker == 0xFF) {
      ++at;
      continue;
    }  // fill byte
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
      at += 2;
      continue;
    }
    if (marker == 0xD9 || marker == 0xDA) refuse(label, ": JPEG has no frame header before its image data");
    const std::uint32_t length = bigEndian(b, at + 2, 2);
    if (length < 2 || length > b.size() - at - 2)
      refuse(label, ": JPEG data ends inside a segment (the file is cut off)");
    const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame) {
      if (length < 8) refuse(label, ": JPEG frame header is too short");
      return {ImageFormat::Jpeg, bigEndian(b, at + 7, 2), bigEndian(b, at + 5, 2)};
    }
    at += 2 + length;
  }
}

// tinygltf asks stb_image for 4 channels of 8 or 16 bits (16-bit samples in host order). Fewer
// channels are expanded all the same (grey → RGB, grey + alpha → RGB + A), should that change.
std::vector<std::uint8_t> toRgba8(const tinygltf::Image& decoded, const std::string& label) {
  const auto channels = static_cast<std::size_t>(decoded.component);
  const std::size_t bytesPerSample = decoded.bits == 16 ? 2 : 1;
  const std::size_t pixels = static_cast<std::size_t>(decoded.width) * static_cast<std::size_t>(decoded.height);
  if (channels < 1 || channels > 4 || (decoded.bits != 8 && decoded.bits != 16) ||
      decoded.image.size() < pixels * channels * bytesPerSample)
    refuse(label, ": decoded to ", channels, " channels of ", decoded.bits, " bits, which lenslab cannot use");
  auto sample = [&](std::size_t pixel, std::size_t channel) -> std::uint8_t {
    const unsigned char* p = &decoded.image[(pixel * channels + channel) * bytesPerSample];
    if (bytesPerSample == 1) return *p;
    std::uint16_t v;
    std::memcpy(&v, p, 2);
    return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u);
  };
  std::vector<std::uint8_t> rgba(pixels * 4);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* out = &rgba[i * 4];
    const std::uint8_t first = sample(i, 0);
    out[0] = first;
    out[1] = channels >= 3 ? sample(i, 1) : first;
    out[2] = channels >= 3 ? sample(i, 2) : first;
    out[3] = channels == 4 ? sample(i, 3) : channels == 2 ? sample(i, 1) : 255;
  }
  return rgba;
}

}  // namespace

std::string imageLabel(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[toIndex(index)];
  std::string label = cat("image ", index);
  if (!image.name.empty()) label += cat(" \"", image.name, "\"");
  if (!image.uri.empty() && !image.uri.starts_with("data:")) label += cat(" (", image.uri, ")");
  return label;
}

// The encoded image: from its bufferView, or the bytes keepEncodedImage kept of its uri.
Bytes encodedImage(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[toIndex(index)];
  if (image.bufferView >= 0) return viewBytes(model, image.bufferView, imageLabel(model, index));
  if (image.image.empty()) refuse(imageLabel(model, index), ": cannot read the image file");
  return Bytes(image.image);
}

// The format and size an image claims, from its first bytes; refuses a PNG or JPEG that is cut
// off. Unknown formats are left to the caller: glTF extensions may bring other formats.
ImageHeader inspectImage(Bytes b, const std::string& label) {
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (b.size() >= 8 && std::equal(kPng, kPng + 8, b.begin())) return inspectPng(b, label);
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return inspectJpeg(b, label);
  return {};
}

TextureImage decodeImage(const tinygltf::Model& model, int index) {
  const std::string label = imageLabel(model, index);
  const Bytes encoded = encodedImage(model, index);
  const ImageHeader header = inspectImage(encoded, label);
  if (header.format == ImageFormat::Unknown) refuse(label, ": neither PNG nor JPEG, the image formats lenslab decodes");
  // tinygltf-2.7: the total-pixel limit (kMaxImagePixels) keeps tinygltf 2.7's pixel copy, sized
  // w*h*comp*(bits/8) in int, from overflowing on 16-bit RGBA; can go when tinygltf is upgraded to
  // one that sizes it in size_t (the per-side limit is the GPU's and stays).
  if (header.width < 1 || header.height < 1 || header.width > kMaxImageSide || header.height > kMaxImageSide ||
      std::uint64_t{header.width} * header.height > kMaxImagePixels)
    refuse(label, ": ", header.width, "x", header.height, " pixels; lenslab decodes up to ", kMaxImageSide,
           " per side and ", kMaxImagePixels, " in all");
  if (encoded.size() > INT_MAX) refuse(label, ": more than 2 GiB of encoded data");
  tinygltf::Image decoded;
  decoded.name = model.images[toIndex(index)].name;
  std::string error, warning;
  if (!tinygltf::LoadImageData(&decoded, index, &error, &warning, 0, 0, encoded.data(),
                               static_cast<int>(encoded.size()), nullptr))
    refuse(label, " could not be decoded: ", oneLine(error));
  TextureImage image;
  image.name = !decoded.name.empty()                                   ? decoded.name
               : model.images[toIndex(index)].uri.starts_with("data:") ? ""
                                                                       : model.images[toIndex(index)].uri;
  image.width = decoded.width;
  image.height = decoded.height;
  image.rgba8 = toRgba8(decoded, label);
  return image;
}

}  // namespace lenslab::gltf
