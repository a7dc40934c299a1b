#include "camera/LensMap.h"

#include "camera/ImageMap.h"

#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <stdexcept>

namespace lenslab {
namespace {

constexpr Channel kChannels[] = {Channel::Red, Channel::Green, Channel::Blue};

// Runs `rows(first, last)` over bands of [0, height) on every core (TBB; an exception in a band
// reaches the caller).
void forEachRowBand(int height, const std::function<void(int, int)>& rows) {
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 8),
                    [&](const tbb::blocked_range<int>& band) { rows(band.begin(), band.end()); });
}

// Calls `slice(first, last)` over consecutive slices of [0, height), one after the other: about 20
// (a table for a large tile takes tens of seconds, and the caller reports after each), each of at
// least 8 rows per core so that every core has work in each; `rowsPerSlice` > 0 fixes the size
// instead (height: one slice).
void forEachSlice(int height, const std::function<void(int, int)>& slice, int rowsPerSlice = 0) {
  const int rows = rowsPerSlice > 0 ? rowsPerSlice : std::max(height / 20, 8 * tbb::this_task_arena::max_concurrency());
  for (int first = 0; first < height; first += rows) slice(first, std::min(height, first + rows));
}

}  // namespace

// The channels whose mapping differs: all three with lateral colour, else green alone.
std::vector<Channel> remappedChannels(const LensEffects& effects) {
  if (effects.chromatic.hasLateral()) return {Channel::Red, Channel::Green, Channel::Blue};
  return {Channel::Green};
}

double NormalisedRect::cornerRadius() const {
  return std::max({glm::length(min), glm::length(max), glm::length(glm::dvec2(min.x, max.y)),
                   glm::length(glm::dvec2(max.x, min.y))});
}

NormalisedRect normalisedWindow(const ViewSpec& view) {
  const Window& w = view.window;
  return {normalisedFromWindow(view, {w.umin, w.vmin}), normalisedFromWindow(view, {w.umax, w.vmax})};
}

std::vector<double> extremeFocusShifts(const Camera& camera) {
  const LensEffects& e = camera.lens.effects;
  const double corner =
      camera.view.projection == Projection::Perspective ? normalisedWindow(camera.view).cornerRadius() : 0.0;
  std::vector<double> shifts;
  for (const double channel : {0.0, e.chromatic.inverseFocusShiftRed, e.chromatic.inverseFocusShiftBlue})
    for (const double curve : {0.0, e.fieldCurvature.inverseFocusPerRadius2 * corner * corner})
      shifts.push_back(channel + curve);
  return shifts;
}

namespace {

// Every coefficient of every effect is a finite number.
bool allFinite(const LensEffects& e) {
  bool finite = true;
  for (const DistortionTerm& t : kDistortionTerms) finite = finite && std::isfinite(e.distortion.*t.value);
  for (const double v : {e.chromatic.lateralRed, e.chromatic.lateralBlue, e.chromatic.inverseFocusShiftRed,
                         e.chromatic.inverseFocusShiftBlue, e.fieldCurvature.inverseFocusPerRadius2, e.vignetting.a1,
                         e.vignetting.a2, e.vignetting.a3})
    finite = finite && std::isfinite(v);
  return finite;
}

}  // namespace

namespace {

// The distortion maps the image one to one: no fold inside it, and a fisheye's image short of 90°.
void validateDistortion(const Camera& camera, const std::string& where) {
  const LensEffects& e = camera.lens.effects;
  const Distortion& d = e.distortion;
  // The distorted region to check: the window, and for lateral colour the part of green's image
  // that each channel's window shows (scaled by 1 / (1 + lateral)).
  const NormalisedRect rect = normalisedWindow(camera.view);
  glm::dvec2 lo = rect.min, hi = rect.max;
  for (const Channel c : kChannels) {
    const double s = 1.0 / (1.0 + e.chromatic.lateral(c));
    lo = glm::min(lo, rect.min * s);
    hi = glm::max(hi, rect.max * s);
  }
  if (const auto reach = d.fisheyeReach(); reach && !reach->folds) {
    const double extent = NormalisedRect{lo, hi}.cornerRadius();
    if (!(reach->distortedRadius > extent))
      throw InputError(cat(where, ": the fisheye's image reaches 90° from the optical axis at normalised radius ",
                           reach->distortedRadius, ", ", std::lround(100.0 * reach->distortedRadius / extent),
                           "% of the way from the centre to the farthest corner (radius ", extent, "; ",
                           distortionTermsText(d),
                           "); lenslab's cameras see less than 90° from the axis, so give a longer focal length "
                           "in pixels or a smaller image"));
  }
  if (const auto fold = findFoldOver(d, lo, hi)) {
    const double along = glm::length(fold->distorted) / rect.cornerRadius();
    throw InputError(cat(where, ": distortion folds over inside the image: at normalised radius ",
                         glm::length(fold->undistorted), " (true position ", fold->undistorted.x, ", ",
                         fold->undistorted.y, "), ", std::lround(100.0 * along),
                         "% of the way from the centre to the farthest corner, the distorted radius stops growing, "
                         "so two points of the scene would land on one pixel (",
                         distortionTermsText(d), "); use weaker coefficients or a narrower field of view"));
  }
}

}  // namespace

void validateLensEffects(const Camera& camera, const std::string& where, std::optional<double> focalLength) {
  const LensEffects& e = camera.lens.effects;
  if (e.isZero()) return;
  if (camera.view.projection != Projection::Perspective)
    throw InputError(cat(where,
                         ": distortion, chromatic aberration, field curvature and vignetting need a perspective "
                         "projection (they act on the angle from the optical axis); this camera is parallel"));
  if (!allFinite(e)) throw InputError(cat(where, ": lens effect coefficients must be finite numbers"));
  // The gain is a polynomial in the distorted radius, the pixel's own place on the film: it must
  // stay positive out to the window's farthest corner (a fit to a real lens can turn down past
  // the field it was fitted over, and a pixel cannot receive negative light).
  const double filmCorner = normalisedWindow(camera.view).cornerRadius();
  if (const auto zero = vignettingZeroWithin(e.vignetting, filmCorner * filmCorner)) {
    const Vignetting& g = e.vignetting;
    throw InputError(cat(where, ": vignetting (a1 = ", g.a1, ", a2 = ", g.a2, ", a3 = ", g.a3,
                         ") reaches gain 0 at normalised radius ", std::sqrt(*zero), ", ",
                         std::lround(100.0 * std::sqrt(*zero) / filmCorner),
                         "% of the way from the centre to the farthest corner (radius ", filmCorner,
                         "); the gain 1 + a1 r^2 + a2 r^4 + a3 r^6 must stay above 0 over the whole image"));
  }
  if (const double largest = vignettingLargestGain(e.vignetting, filmCorner * filmCorner);
      !(largest <= kMaxVignettingGain)) {
    const Vignetting& g = e.vignetting;
    throw InputError(cat(where, ": vignetting (a1 = ", g.a1, ", a2 = ", g.a2, ", a3 = ", g.a3, ") reaches gain ",
                         largest, " inside the image (out to normalised radius ", filmCorner,
                         "); the gain 1 + a1 r^2 + a2 r^4 + a3 r^6 "
                         "is relative to the centre's 1 and must stay at most ",
                         kMaxVignettingGain));
  }
  // Each plane of focus the effects add (a channel's, the curved surface's at the corner) must be
  // one the lens can form an image of: beyond its focal length. Without a focal length, beyond the
  // aperture radius: no lens is faster than f/0.5 (f ≥ R). A plane nearer than that is no lens's,
  // and at 1e-200 its rays overflow (a window shifted by 1e200 aperture radii).
  const double phi = camera.inverseFocusDistance();
  const double corner = normalisedWindow(camera.view).cornerRadius();
  const double nearest = focalLength ? *focalLength : camera.lens.apertureRadius;
  for (const auto& [name, shift] : {std::pair{"chromatic.focus_distance_red", e.chromatic.inverseFocusShiftRed},
                                    std::pair{"chromatic.focus_distance_blue", e.chromatic.inverseFocusShiftBlue},
                                    std::pair{"field_curvature.corner_focus_distance",
                                              e.fieldCurvature.inverseFocusPerRadius2 * corner * corner}}) {
    const double inverse = phi + shift;
    if (shift == 0.0 || !(nearest > 0.0) || !(inverse * nearest >= 1.0)) continue;
    throw InputError(cat(
        where, ": ", name, " is ", 1.0 / inverse, "; it must be beyond ",
        focalLength ? cat("the focal length (", *focalLength, " world units), or the lens forms no real image there")
                    : cat("the aperture radius (", camera.lens.apertureRadius,
                          " world units): no lens is faster than "
                          "f/0.5, so none with this aperture forms a real image nearer"),
        "; \"infinity\" is allowed"));
  }
  for (const auto& [name, value] :
       {std::pair{"lateral_red", e.chromatic.lateralRed}, std::pair{"lateral_blue", e.chromatic.lateralBlue}})
    if (!(std::abs(value) < 0.5))
      throw InputError(
          cat(where, ": chromatic.", name, " = ", value,
              " is a relative magnification of the channel; use a value in (-0.5, 0.5), typically below 0.01"));
  validateDistortion(camera, where);
}

double ThinLensMap::forwardLinearisationErrorPx() const {
  const LensEffects& effects = camera_.lens.effects;
  if (!effects.needsRemap()) return 0.0;
  const int width = size_.widthPx, height = size_.heightPx;
  // Pixel (image orientation) → normalised, and back: the rendered view has the image's pitch.
  const auto normalised = [&](glm::dvec2 pixel) { return normalisedFromPixel(pixel); };
  const auto pixel = [&](glm::dvec2 n) { return pixelFromNormalised(n); };
  const double scale =
      1.0 + std::max({0.0, std::abs(effects.chromatic.lateralRed), std::abs(effects.chromatic.lateralBlue)});
  // Where the lens puts the view's point q (view pixels), in output pixels.
  const auto forward = [&](glm::dvec2 q) { return pixel(effects.distortion.distort(normalised(q))); };
  // The error is smooth over the image: a grid of up to 129 × 129 points, the border included.
  const int nx = std::min(width, 128), ny = std::min(height, 128);
  std::vector<double> worstPerRow(static_cast<std::size_t>(ny) + 1, 0.0);
  forEachRowBand(ny + 1, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      glm::dvec2 guess(0.0);
      for (int i = 0; i <= nx; ++i) {
        const glm::dvec2 out(width * static_cast<double>(i) / nx, height * static_cast<double>(j) / ny);
        const glm::dvec2 truth = undistortNormalised(Channel::Green, normalised(out), i == 0 ? normalised(out) : guess);
        guess = truth;
        // The forward table's texel: its centre's image and central differences over one texel.
        const glm::dvec2 q = pixel(truth);
        const glm::dvec2 p = forward(q);
        const glm::dvec2 dx = forward(q + glm::dvec2(0.5, 0.0)) - forward(q - glm::dvec2(0.5, 0.0));
        const glm::dvec2 dy = forward(q + glm::dvec2(0.0, 0.5)) - forward(q - glm::dvec2(0.0, 0.5));
        double& worst = worstPerRow[static_cast<std::size_t>(j)];
        for (const double sx : {-0.5, 0.5})
          for (const double sy : {-0.5, 0.5})
            worst = std::max(worst, glm::length(forward(q + glm::dvec2(sx, sy)) - (p + sx * dx + sy * dy)));
      }
    }
  });
  return scale * *std::max_element(worstPerRow.begin(), worstPerRow.end());
}

void ThinLensMap::validateForwardLinearisation() const {
  const Camera& camera = camera_;
  const ImageSize size = size_;
  const double errorPx = forwardLinearisationErrorPx();
  if (errorPx <= kMaxForwardLinearisationErrorPx) return;
  const std::string coefficients = distortionTermsText(camera.lens.effects.distortion);
  // The error shrinks in proportion to the pixel pitch (a second-order term over one pixel).
  const double widthFor = std::ceil(size.widthPx * errorPx / kMaxForwardLinearisationErrorPx);
  throw InputError(
      cat(camera.source, ": distortion (", coefficients, ") bends ", size.widthPx, "x", size.heightPx,
          " px so sharply that the raster, which carries each rendered pixel's samples by the lens's linear map "
          "over that pixel, would land them up to ",
          errorPx, " px from where the lens puts them (the limit is ", kMaxForwardLinearisationErrorPx,
          " px at any resolution: further, they fall in the wrong pixel); render at "
          "about --width ",
          widthFor, " or more, use weaker coefficients, or lenslab raycast (exact per ray)"));
}

ThinLensMap ThinLensMap::overscanned() const {
  const Camera& camera = camera_;
  Overscan o{camera, size_, {0, 0}};
  if (!camera.lens.effects.needsRemap()) return ThinLensMap(camera, size_, std::move(o));
  const int width = size_.widthPx, height = size_.heightPx;
  // The output image's border maps to the border of the region it shows (no fold inside), so the
  // border's true positions bound everything the post pass samples.
  glm::dvec2 lo(0.0), hi(width, height);
  const auto visit = [&](glm::dvec2 pixel) {
    for (const Channel c : remappedChannels(camera.lens.effects)) {
      const glm::dvec2 distorted = normalisedFromPixel(pixel);
      const glm::dvec2 p = pixelFromNormalised(undistortNormalised(c, distorted, distorted));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  for (int i = 0; i <= 2 * width; ++i) {
    visit({0.5 * i, 0.0});
    visit({0.5 * i, height});
  }
  for (int j = 0; j <= 2 * height; ++j) {
    visit({0.0, 0.5 * j});
    visit({width, 0.5 * j});
  }
  // Two more pixels for the lens pass's footprint (the per-view gather reaches about 1.5 texels,
  // the field-curvature warp's Catmull–Rom 2); the same on both sides keeps the window's centre.
  const double padX = std::max(-lo.x, hi.x - width), padY = std::max(-lo.y, hi.y - height);
  return paddedBy(
      {static_cast<int>(std::ceil(std::max(0.0, padX))) + 2, static_cast<int>(std::ceil(std::max(0.0, padY))) + 2});
}

ThinLensMap ThinLensMap::paddedBy(glm::ivec2 padPx) const {
  Overscan o{camera_, size_, padPx};
  const int width = size_.widthPx, height = size_.heightPx;
  o.size = {width + 2 * o.padPx.x, height + 2 * o.padPx.y};
  // No limit on the size here: a render larger than one GL target is made in tiles (plan/TilePlan.h).
  const Window& w = camera_.view.window;
  const glm::dvec2 pitch(w.width() / width, w.height() / height);
  Window& ow = o.camera.view.window;
  ow.umin -= o.padPx.x * pitch.x;
  ow.umax += o.padPx.x * pitch.x;
  ow.vmin -= o.padPx.y * pitch.y;
  ow.vmax += o.padPx.y * pitch.y;
  return ThinLensMap(camera_, size_, std::move(o));
}

void ThinLensMap::fillRemapRows(Channel c, int firstRow, int lastRow, glm::vec2* out) const {
  const Overscan& overscan = overscan_;
  const int width = size_.widthPx, height = size_.heightPx;
  const glm::dvec2 inner(overscan.size.widthPx, overscan.size.heightPx);
  const glm::dvec2 pad(overscan.padPx);
  // Rows are independent: bands on every core (a 4K table is 8 million Newton solves).
  forEachRowBand(lastRow - firstRow, [&](int first, int last) {
    for (int band = first; band < last; ++band) {
      const int row = firstRow + band;
      const int y = height - 1 - row;  // GL rows run up, image rows down
      glm::dvec2 guess(0.0);
      for (int x = 0; x < width; ++x) {
        const glm::dvec2 distorted = normalisedFromPixel({x + 0.5, y + 0.5});
        // Neighbouring pixels' solutions are close: start from the previous one.
        const glm::dvec2 truth = undistortNormalised(c, distorted, x == 0 ? distorted : guess);
        guess = truth;
        const glm::dvec2 p = pixelFromNormalised(truth) + pad;
        out[static_cast<std::size_t>(band) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
            glm::vec2(p.x / inner.x, 1.0 - p.y / inner.y);
      }
    }
  });
}

RemapTable ThinLensMap::remapTable(const RowProgress& progress) const {
  RemapTable table{size_, {}};
  const int width = size_.widthPx, height = size_.heightPx;
  const std::vector<Channel> channels = remappedChannels(camera_.lens.effects);
  const int rows = static_cast<int>(channels.size()) * height;
  for (const Channel c : channels) {
    std::vector<glm::vec2> map(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const int done = static_cast<int>(table.channels.size()) * height;
    forEachSlice(
        height,
        [&](int first, int last) {
          fillRemapRows(c, first, last, &map[static_cast<std::size_t>(first) * static_cast<std::size_t>(width)]);
          if (progress) progress(done + last, rows);
        },
        progress ? 0 : height);
    table.channels.push_back(std::move(map));
  }
  return table;
}

double ThinLensMap::fillForwardRows(int firstRow, int lastRow, glm::vec4* position, glm::vec4* jacobian) const {
  const int width = size_.widthPx, height = size_.heightPx;
  const int viewWidth = overscan_.size.widthPx, viewHeight = overscan_.size.heightPx;
  // View position (GL) → normalised → green's distorted position → output position (GL).
  const auto forward = [&](glm::dvec2 q) {
    const glm::dvec2 p = outputFromRenderPixel({q.x, viewHeight - q.y});
    return glm::dvec2(p.x, height - p.y);
  };
  std::vector<double> halfExtent(static_cast<std::size_t>(lastRow - firstRow), 0.0);  // per row, then the largest
  forEachRowBand(lastRow - firstRow, [&](int first, int last) {
    for (int band = first; band < last; ++band) {
      const int y = firstRow + band;
      for (int x = 0; x < viewWidth; ++x) {
        const glm::dvec2 q(x + 0.5, y + 0.5);
        const glm::dvec2 p = forward(q);
        // Central differences over one texel: exact for the quadratic part of the map.
        const glm::dvec2 dx = forward(q + glm::dvec2(0.5, 0.0)) - forward(q - glm::dvec2(0.5, 0.0));
        const glm::dvec2 dy = forward(q + glm::dvec2(0.0, 0.5)) - forward(q - glm::dvec2(0.0, 0.5));
        const double det = dx.x * dy.y - dy.x * dx.y;
        const std::size_t i =
            static_cast<std::size_t>(band) * static_cast<std::size_t>(viewWidth) + static_cast<std::size_t>(x);
        position[i] = glm::vec4(p.x, p.y, std::abs(det), 0.0);
        jacobian[i] = glm::vec4(dx.x, dx.y, dy.x, dy.y);
        // The pre-image of an output pixel ([-½, ½]² about p) is J⁻¹ of it: its half-extent per axis.
        if (p.x > -1.0 && p.x < width + 1.0 && p.y > -1.0 && p.y < height + 1.0 && det > 0.0) {
          const double hx = 0.5 * (std::abs(dy.y) + std::abs(dy.x)) / det;
          const double hy = 0.5 * (std::abs(dx.y) + std::abs(dx.x)) / det;
          double& h = halfExtent[static_cast<std::size_t>(band)];
          h = std::max({h, hx, hy});
        }
      }
    }
  });
  return halfExtent.empty() ? 0.0 : *std::max_element(halfExtent.begin(), halfExtent.end());
}

double ThinLensMap::forwardReachPx(double largestHalfExtentPx) const {
  const Chromatic& chromatic = camera_.lens.effects.chromatic;
  // Red and blue are green's image magnified by (1 + lateral): their pre-images are smaller or
  // larger by that factor.
  const double smallestScale = std::min({1.0, 1.0 + chromatic.lateralRed, 1.0 + chromatic.lateralBlue});
  return largestHalfExtentPx * 1.01 / smallestScale + 1.0;
}

glm::dvec2 ThinLensMap::forwardPrincipalPointPx() const {
  const glm::dvec2 principal = pixelFromNormalised({0.0, 0.0});
  return {principal.x, size_.heightPx - principal.y};
}

ForwardTable ThinLensMap::forwardTable(const RowProgress& progress) const {
  ForwardTable table;
  table.size = overscan_.size;
  const int viewWidth = overscan_.size.widthPx, viewHeight = overscan_.size.heightPx;
  const std::size_t texels = static_cast<std::size_t>(viewWidth) * static_cast<std::size_t>(viewHeight);
  table.position.resize(texels);
  table.jacobian.resize(texels);
  double halfExtent = 0.0;
  forEachSlice(
      viewHeight,
      [&](int first, int last) {
        const std::size_t at = static_cast<std::size_t>(first) * static_cast<std::size_t>(viewWidth);
        halfExtent = std::max(halfExtent, fillForwardRows(first, last, &table.position[at], &table.jacobian[at]));
        if (progress) progress(last, viewHeight);
      },
      progress ? 0 : viewHeight);
  table.reachPx = forwardReachPx(halfExtent);
  table.principalPointPx = forwardPrincipalPointPx();
  return table;
}

}  // namespace lenslab
