#include "lens/CentreRays.h"

#include "lens/ExitPupil.h"
#include "lens/LensFitBundles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lenslab {

CentreRays::CentreRays(const LensCamera& camera, int channel, int radii, int pupilSamples) : camera_(camera) {
  if (radii < 2 || pupilSamples < 1) throw std::logic_error("CentreRays: at least 2 radii and 1 pupil sample");
  stepMm_ = camera.halfDiagonalMm() / (radii - 1);
  lines_.resize(static_cast<std::size_t>(radii));
  for (int i = 0; i < radii; ++i) {
    const LensFitBundle bundle =
        traceLensFitBundle(camera.pupil(channel), {i * stepMm_, 0.0}, camera.entrancePupilMm(), pupilSamples);
    Line& line = lines_[static_cast<std::size_t>(i)];
    line.share = bundle.share;
    line.a = bundle.meanA.x;
    line.b = bundle.meanB.x;
  }
}

std::optional<LensCamera::WorldRay> CentreRays::at(glm::dvec2 pixel, int widthPx, int heightPx) const {
  const glm::dvec2 film = camera_.filmMmOf(pixel, widthPx, heightPx);
  const double radius = glm::length(film);
  // Linear between the two radii either side; where either passes nothing, nothing is seen.
  const double at = std::min(radius / stepMm_, static_cast<double>(lines_.size() - 1));
  const auto i = std::min(static_cast<std::size_t>(at), lines_.size() - 2);
  const Line &lo = lines_[i], &hi = lines_[i + 1];
  if (!(lo.share > 0.0) || !(hi.share > 0.0)) return std::nullopt;
  const double t = at - static_cast<double>(i);
  const double a = lo.a + t * (hi.a - lo.a), b = lo.b + t * (hi.b - lo.b), share = lo.share + t * (hi.share - lo.share);
  // The film point's azimuth: the line lies in its meridional plane.
  const glm::dvec2 towards = radius > 0.0 ? film / radius : glm::dvec2(1.0, 0.0);
  // Leaving the first vertex's plane, as the traced rays leave the first surface (or the
  // entrance pupil's, where it lies in front of the lens): depth Z in front of the pupil is z = z_p − Z.
  const double pupilZ = camera_.entrancePupilMm(), depth = std::max(pupilZ, 0.0);
  return camera_.toWorld(glm::dvec3((a + b * depth) * towards, pupilZ - depth), glm::dvec3(b * towards, -1.0), share);
}

}  // namespace lenslab
