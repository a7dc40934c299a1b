#include "raycast/TextureSampler.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lenslab {
namespace {

float decode(std::uint8_t v) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float x = static_cast<float>(i) / 255.0f;
      t[static_cast<std::size_t>(i)] = x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table[v];
}

std::uint8_t encode(float linear) {
  const float x = std::clamp(linear, 0.0f, 1.0f);
  const float s = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

int wrap(int i, int size, Wrap mode) {
  switch (mode) {
    case Wrap::ClampToEdge: return std::clamp(i, 0, size - 1);
    case Wrap::MirroredRepeat: {
      const int period = 2 * size;
      int m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case Wrap::Repeat:
    default: return ((i % size) + size) % size;
  }
}

bool mipmapped(Filter f) { return f != Filter::Nearest && f != Filter::Linear; }

// A texel coordinate moved by whole periods of its wrap mode into [0, period) (clamped ones into
// a texel of the edge), in double: a scaled or offset uv (KHR_texture_transform) can lie 10^20
// texels out, where a cast to int overflows. The wrap sees the same texel and the bilinear
// weights the same fraction; a coordinate that is not finite reads the level's middle (at such
// coordinates the footprint is the whole texture, and the coarsest level is its average).
double reduced(double x, int size, Wrap mode) {
  if (!std::isfinite(x)) return 0.5 * size;
  if (mode == Wrap::ClampToEdge) return std::clamp(x, -1.0, size + 1.0);
  const double period = mode == Wrap::MirroredRepeat ? 2.0 * size : static_cast<double>(size);
  return x - period * std::floor(x / period);
}

}  // namespace

TextureSampler::TextureSampler(const TextureImage& image, bool mipmaps, bool srgb) {
  // Level 0 keeps the file's 8-bit sRGB values; each next level averages 2×2 in linear light and
  // is stored back as 8-bit sRGB (as the GPU's SRGB8_ALPHA8 mip levels are). Data images
  // (srgb false) average and store their 8-bit values as they are (GL_RGBA8).
  const auto decodeChannel = [srgb](std::uint8_t v) { return srgb ? decode(v) : static_cast<float>(v) / 255.0f; };
  const auto encodeChannel = [srgb](float v) {
    return srgb ? encode(v) : static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  std::vector<std::uint8_t> bytes = image.rgba8;
  int w = image.width, h = image.height;
  while (true) {
    Level level;
    level.width = w;
    level.height = h;
    level.texels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::size_t i = 0; i < level.texels.size(); ++i)
      level.texels[i] = {decodeChannel(bytes[i * 4]), decodeChannel(bytes[i * 4 + 1]), decodeChannel(bytes[i * 4 + 2]),
                         static_cast<float>(bytes[i * 4 + 3]) / 255.0f};
    levels_.push_back(std::move(level));
    if (!mipmaps || (w == 1 && h == 1)) break;
    const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
    std::vector<std::uint8_t> next(static_cast<std::size_t>(nw) * static_cast<std::size_t>(nh) * 4);
    const Level& src = levels_.back();
    for (int y = 0; y < nh; ++y)
      for (int x = 0; x < nw; ++x) {
        glm::vec4 sum(0.0f);
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            sum += src.texels[static_cast<std::size_t>(std::min(2 * y + dy, h - 1) * w + std::min(2 * x + dx, w - 1))];
        sum *= 0.25f;
        std::uint8_t* out =
            &next[(static_cast<std::size_t>(y) * static_cast<std::size_t>(nw) + static_cast<std::size_t>(x)) * 4];
        out[0] = encodeChannel(sum.r);
        out[1] = encodeChannel(sum.g);
        out[2] = encodeChannel(sum.b);
        out[3] = static_cast<std::uint8_t>(std::lround(std::clamp(sum.a, 0.0f, 1.0f) * 255.0f));
      }
    bytes = std::move(next);
    w = nw;
    h = nh;
  }
}

glm::vec4 TextureSampler::bilinear(const Level& level, const Sampler& s, glm::vec2 uv, bool linear) const {
  const double x = reduced(static_cast<double>(uv.x) * level.width, level.width, s.wrapS),
               y = reduced(static_cast<double>(uv.y) * level.height, level.height, s.wrapT);
  auto texel = [&](int i, int j) {
    return level
        .texels[static_cast<std::size_t>(wrap(j, level.height, s.wrapT) * level.width + wrap(i, level.width, s.wrapS))];
  };
  if (!linear) return texel(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  const double fx = x - 0.5, fy = y - 0.5;
  const int i0 = static_cast<int>(std::floor(fx)), j0 = static_cast<int>(std::floor(fy));
  const float a = static_cast<float>(fx - i0), b = static_cast<float>(fy - j0);
  return (1 - a) * (1 - b) * texel(i0, j0) + a * (1 - b) * texel(i0 + 1, j0) + (1 - a) * b * texel(i0, j0 + 1) +
         a * b * texel(i0 + 1, j0 + 1);
}

glm::vec4 TextureSampler::sample(const Sampler& s, glm::vec2 uv, glm::vec2 dUvDx, glm::vec2 dUvDy) const {
  const Level& base = levels_.front();
  const glm::vec2 size(static_cast<float>(base.width), static_cast<float>(base.height));
  // In double: a footprint 10^30 texels wide squares past float. One that is not finite (the
  // difference of two overflowed coordinates) covers the whole texture.
  const double rho =
      std::max(glm::length(glm::dvec2(dUvDx) * glm::dvec2(size)), glm::length(glm::dvec2(dUvDy) * glm::dvec2(size)));
  const float lambda = !std::isfinite(rho) ? 1000.0f : rho > 0.0 ? static_cast<float>(std::log2(rho)) : -1000.0f;
  if (lambda <= 0.0f) return bilinear(base, s, uv, s.magFilter != Filter::Nearest);
  if (!mipmapped(s.minFilter) || levels() == 1)
    return bilinear(base, s, uv,
                    s.minFilter != Filter::Nearest && s.minFilter != Filter::NearestMipmapNearest &&
                        s.minFilter != Filter::NearestMipmapLinear);
  const bool linearWithin = s.minFilter == Filter::LinearMipmapNearest || s.minFilter == Filter::LinearMipmapLinear;
  const int maxLevel = levels() - 1;
  if (s.minFilter == Filter::NearestMipmapNearest || s.minFilter == Filter::LinearMipmapNearest) {
    const int d = std::clamp(static_cast<int>(std::ceil(lambda + 0.5f)) - 1, 0, maxLevel);
    return bilinear(levels_[static_cast<std::size_t>(d)], s, uv, linearWithin);
  }
  const int d1 = std::clamp(static_cast<int>(std::floor(lambda)), 0, maxLevel);
  const int d2 = std::min(d1 + 1, maxLevel);
  const float t = lambda >= static_cast<float>(maxLevel) ? 0.0f : lambda - std::floor(lambda);
  return (1.0f - t) * bilinear(levels_[static_cast<std::size_t>(d1)], s, uv, linearWithin) +
         t * bilinear(levels_[static_cast<std::size_t>(d2)], s, uv, linearWithin);
}

}  // namespace lenslab
