#pragma once
// The ray caster's one render loop, for every lens (raycast/RayCaster.h): each pixel's stratified
// samples (pixel position × lens point, in the map's lens domain), each channel's ray asked of the
// frame's image map (camera/ImageMap.h), shaded, weighted by the ray's weight, averaged, times
// the map's gain at the pixel; alpha is the rays' weighted coverage. A new lens model is a new
// map: this loop does not change. Rows in bands spread over the cores by TBB.
#include "camera/ImageMap.h"
#include "core/Image.h"
#include "lens/AperturePattern.h"
#include "raycast/RayCaster.h"

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>

namespace lenslab {
namespace render_loop {

// Rows in bands of 16, each band's rows spread over the cores by TBB; `progress` between bands,
// from the calling thread.
template <class Rows>
void inBands(ImageSize size, const std::function<void(int, int)>& progress, const Rows& rows) {
  constexpr int kBand = 16;
  for (int band = 0; band < size.heightPx; band += kBand) {
    const int end = std::min(band + kBand, size.heightPx);
    tbb::parallel_for(tbb::blocked_range<int>(band, end),
                      [&](const tbb::blocked_range<int>& r) { rows(r.begin(), r.end()); });
    if (progress) progress(end, size.heightPx);
  }
}

// The lens points of a pixel's samples in the map's domain: the stratified sample's point of the
// unit disk (Shirley–Chiu concentric), or for a box around a real lens's exit pupil points of the
// R2 sequence with a random rotation per pixel (Cranley–Patterson): evenly spread over the box for
// any count, and unbiased.
class LensPoints {
 public:
  LensPoints(LensDomain domain, std::uint32_t seed) : square_(domain == LensDomain::Square) {
    if (square_)
      rotation_ = glm::dvec2(makeApertureSamples(AperturePattern::Random, 1, seed ^ 0x9e3779b9u)[0].pixel) + 0.5;
  }
  glm::dvec2 at(const LensSample& s, std::size_t i) const {
    if (!square_) return s.lens;
    constexpr double kPlastic = 1.32471795724474602596;
    const glm::dvec2 step(1.0 / kPlastic, 1.0 / (kPlastic * kPlastic));
    return glm::fract(rotation_ + static_cast<double>(i + 1) * step);
  }

 private:
  bool square_;
  glm::dvec2 rotation_{0.0};
};

// A different stratified set per pixel, so that the noise does not repeat across pixels.
inline std::uint32_t pixelSeed(std::uint32_t seed, int x, int y, int widthPx) {
  return seed * 2654435761u ^ static_cast<std::uint32_t>(std::int64_t{y} * widthPx + x) * 40503u;
}

}  // namespace render_loop

// The image `map` sees: `shade(ray, rayAt, footprintPx, pixel)` is what a ray (relative to
// `origin`) sees, with `rayAt(offset)` the same sample's ray from `offset` pixels over (ray
// differentials for its textures), returning the colour and coverage (RayCaster's Hit).
// `progress(rowsDone, rows)` between bands of rows, from the calling thread.
// `Map` is the map's own type where the caller knows it (its calls then direct, and inline where
// the map defines them so), else ImageMap.
template <class Map, class Shade>
Image renderThroughMap(const Map& map, const RaycastOptions& options, const std::function<void(int, int)>& progress,
                       const glm::dvec3& origin, const Shade& shade) {
  using render_loop::inBands;
  using render_loop::LensPoints;
  using render_loop::pixelSeed;
  const ImageSize size = map.size();
  Image image(size.widthPx, size.heightPx);
  const int spp = std::max(1, options.samplesPerPixel);
  // The samples' pixel positions are stratified, one stratum of 1/√spp × 1/√spp pixels each: that
  // is the area a sample stands for, so its texture lookups filter over that and no more.
  const double footprintPx = 1.0 / std::sqrt(static_cast<double>(spp));
  const int channels = map.rayChannels();
  inBands(size, progress, [&](int yBegin, int yEnd) {
    for (int y = yBegin; y < yEnd; ++y)
      for (int x = 0; x < size.widthPx; ++x) {
        const std::uint32_t seed = pixelSeed(options.seed, x, y, size.widthPx);
        const auto samples = makeApertureSamples(AperturePattern::Concentric, spp, seed);
        const LensPoints lens(map.lensDomain(), seed);
        // A map that solves an inverse per film point starts each sample's from the pixel centre's.
        std::optional<CameraRay> centre[3];
        for (int c = 0; c < channels; ++c) centre[c] = map.start({x + 0.5, y + 0.5}, channels == 3 ? c : 1);
        glm::dvec3 sum(0.0);
        double covered = 0.0,
               weights = 0.0;  // Σ coverage (Hit::coverage) and Σ weight of the rays: alpha is their ratio
        for (std::size_t i = 0; i < samples.size(); ++i) {
          const glm::dvec2 pixel(x + 0.5 + samples[i].pixel.x, y + 0.5 + samples[i].pixel.y);
          for (int c = 0; c < channels; ++c) {
            const std::optional<CameraRay> r =
                map.ray(pixel, lens.at(samples[i], i), channels == 3 ? c : 1, centre[c] ? &*centre[c] : nullptr);
            // Outside what the lens passes, or stopped by the barrel: no light (background
            // included: the pixel darkens), and no part of the coverage, which is over the rays
            // that pass (as a real lens's rims stop rays before they have a direction).
            if (!r || r->blocked) continue;
            weights += r->weight / channels;
            Ray ray = r->ray;
            ray.origin -= origin;
            // The texture's ray differentials: the same lens point, the film point one footprint over.
            const auto rayAt = [&](glm::dvec2 offset) {
              Ray n = map.footprintRay(*r, offset);
              n.origin -= origin;
              return n;
            };
            const auto hit = shade(ray, rayAt, footprintPx, r->pixel);
            if (channels == 3)
              sum[c] += r->weight * hit.color[c];
            else
              sum += r->weight * glm::dvec3(hit.color);
            covered += r->weight * hit.coverage / channels;
          }
        }
        const double n = static_cast<double>(samples.size());
        image.set(x, y,
                  glm::vec4(glm::vec3(map.gainAt({x + 0.5, y + 0.5}) * sum / n),
                            static_cast<float>(weights > 0.0 ? covered / weights : 0.0)));
      }
  });
  return image;
}

}  // namespace lenslab
