#include "view/LectureDiagram.h"

#include "camera/Projection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab::view {

std::vector<DiagramLine> lectureDiagram(const Camera& camera, const std::vector<LensSample>& samples, int samplesDone,
                                        const DiagramStyle& style) {
  const DiagramColors& colors = style.colors;
  std::vector<DiagramLine> lines;
  const ViewSpec& s = camera.view;
  const ViewBasis b = viewBasis(s);
  const glm::dvec3 prp = prpWorld(s);
  const double d = viewPlaneDistance(s);
  // Marks sized by the window, so the diagram reads at any scene scale.
  const double mark = 0.02 * std::max(s.window.width(), s.window.height());
  auto onViewPlane = [&](double u, double v) { return s.vrp + u * b.u + v * b.v; };
  auto add = [&](glm::dvec3 a, glm::dvec3 c, glm::vec3 color) { lines.push_back({a, c, color}); };

  // The PRP: a small cross.
  for (const glm::dvec3& axis : {b.u, b.v, b.n}) add(prp - mark * axis, prp + mark * axis, colors.prp);

  // The window on the view plane, and its centre.
  const Window& w = s.window;
  const glm::dvec3 corners[4] = {onViewPlane(w.umin, w.vmin), onViewPlane(w.umax, w.vmin), onViewPlane(w.umax, w.vmax),
                                 onViewPlane(w.umin, w.vmax)};
  for (int i = 0; i < 4; ++i) add(corners[i], corners[(i + 1) % 4], colors.window);
  const glm::dvec3 centre = onViewPlane(w.center().x, w.center().y);
  add(centre - mark * b.u, centre + mark * b.u, colors.window);
  add(centre - mark * b.v, centre + mark * b.v, colors.window);

  // The view volume: perspective, from the PRP through the corners; parallel, along DOP.
  const double k = std::max(style.volumeDepthScale, 1.0);
  for (const glm::dvec3& c : corners) {
    if (s.projection == Projection::Perspective) {
      add(prp, prp + k * (c - prp), colors.volume);
    } else {
      const glm::dvec3 dop = centre - prp;  // DOP = CW − PRP, in world coordinates
      add(c - dop, c + (k - 1.0) * dop, colors.volume);
    }
  }

  if (camera.lens.isPinhole()) return lines;

  // The aperture in the PRP's plane (parallel to the view plane): a disk, or the blades' shape.
  const double r = camera.lens.apertureRadius * style.apertureScale;
  const std::vector<glm::dvec2> outline =
      apertureOutline(camera.lens.aperture, camera.lens.aperture.blades == 0 ? 64 : 16);
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const glm::dvec2 a = outline[i], c = outline[(i + 1) % outline.size()];
    add(prp + r * (a.x * b.u + a.y * b.v), prp + r * (c.x * b.u + c.y * b.v), colors.aperture);
  }
  // The sample points: the PRP moves to each of them for one scene pass.
  const double dot = std::min(0.06 * r, mark);
  auto lensPoint = [&](const LensSample& sample) {
    const glm::dvec2 p =
        camera.lens.aperture.isRound() ? sample.lens : apertureFromDisk(sample.lens, camera.lens.aperture);
    return prp + r * (p.x * b.u + p.y * b.v);
  };
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const glm::dvec3 p = lensPoint(samples[i]);
    const glm::vec3 color = static_cast<int>(i) < samplesDone ? colors.sampleDone : colors.samplePending;
    add(p - dot * b.u, p + dot * b.u, color);
    add(p - dot * b.v, p + dot * b.v, color);
  }
  // A few rays from aperture points through the window centre: they meet on the plane of focus
  // (at infinity focus the window moves with the PRP, so the rays leave parallel instead).
  const int count = std::min(style.rayCount, static_cast<int>(samples.size()));
  for (int i = 0; i < count; ++i) {
    const LensSample& sample = samples[static_cast<std::size_t>(i) * samples.size() / static_cast<std::size_t>(count)];
    const glm::dvec3 from = lensPoint(sample);
    const glm::dvec3 through = camera.focusAtInfinity() ? centre + (from - prp) : centre;
    add(from, from + k * (through - from) * (d > 0.0 ? 1.0 : 0.0), colors.ray);
  }
  return lines;
}

double readableApertureScale(const Camera& camera, double fraction) {
  if (camera.lens.isPinhole()) return 1.0;
  const double wanted = 0.5 * fraction * camera.view.window.height();
  return std::max(1.0, wanted / camera.lens.apertureRadius);
}

}  // namespace lenslab::view
