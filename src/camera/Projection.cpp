#include "camera/Projection.h"

#include <cmath>
#include <limits>

namespace lenslab {

// GLM matrices are column-major: m[column][row].
namespace {

glm::dmat4 fromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2, const glm::dvec4& r3) {
  return glm::transpose(glm::dmat4(r0, r1, r2, r3));
}

}  // namespace

glm::dmat4 viewFromWorld(const ViewSpec& spec) {
  const ViewBasis b = viewBasis(spec);
  // Rows are u, v, n: the rotation that takes world directions into VRC, after moving VRP to 0.
  return fromRows({b.u, -glm::dot(b.u, spec.vrp)}, {b.v, -glm::dot(b.v, spec.vrp)}, {b.n, -glm::dot(b.n, spec.vrp)},
                  {0.0, 0.0, 0.0, 1.0});
}

glm::dmat4 worldFromView(const ViewSpec& spec) {
  const ViewBasis b = viewBasis(spec);
  return glm::dmat4(glm::dvec4(b.u, 0.0), glm::dvec4(b.v, 0.0), glm::dvec4(b.n, 0.0), glm::dvec4(spec.vrp, 1.0));
}

glm::dmat4 eyeFromView(const ViewSpec& spec) {
  const glm::dvec3& p = spec.prp;
  return fromRows({1.0, 0.0, 0.0, -p.x}, {0.0, 1.0, 0.0, -p.y}, {0.0, 0.0, -1.0, p.z}, {0.0, 0.0, 0.0, 1.0});
}

glm::dmat4 lecturePerspective(double f) {
  return fromRows({1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}, {0.0, 0.0, 1.0 / f, 0.0});
}

glm::dmat4 clipFromEye(const ViewSpec& spec) {
  const Window& w = spec.window;
  const double nearZ = spec.nearDistance;
  const double farZ = spec.farDistance;
  const double sx = 2.0 / w.width();
  const double sy = 2.0 / w.height();

  if (spec.projection == Projection::Perspective) {
    const double f = viewPlaneDistance(spec);
    // After the lecture matrix, h = (X, Y, Z, Z/f) and h.xy / h.w is the point on the view plane
    // relative to the principal point (the foot of the PRP). Window→NDC on that point:
    //   x_ndc = sx·(PRP.u + h.x/h.w − umin) − 1, so x_clip = sx·h.x + (sx·(PRP.u − umin) − 1)·h.w
    const double ox = sx * (spec.prp.x - w.umin) - 1.0;
    const double oy = sy * (spec.prp.y - w.vmin) - 1.0;
    const glm::dmat4 ndcFromImage =
        fromRows({sx, 0.0, 0.0, ox}, {0.0, sy, 0.0, oy}, {0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0});
    glm::dmat4 clip = ndcFromImage * lecturePerspective(f);
    // z row (eye coordinates, scaled like w = Z/f): z_clip / w_clip = A + B / Z.
    double a = 0.0;
    double b = nearZ;
    if (std::isfinite(farZ)) {
      a = -nearZ / (farZ - nearZ);
      b = nearZ * farZ / (farZ - nearZ);
    }
    clip[0][2] = 0.0;
    clip[1][2] = 0.0;
    clip[2][2] = a / f;
    clip[3][2] = b / f;
    return clip;
  }

  // Parallel: a point at depth Z (n = PRP.n − Z) moves along DOP to the view plane:
  //   u = X + PRP.u + (n / PRP.n)·(CW.u − PRP.u) = X + CW.u − (Z / PRP.n)·(CW.u − PRP.u)
  const glm::dvec2 cw = w.center();
  const double pn = spec.prp.z;
  const double shearU = -(cw.x - spec.prp.x) / pn;
  const double shearV = -(cw.y - spec.prp.y) / pn;
  const double depthScale = -1.0 / (farZ - nearZ);
  return fromRows({sx, 0.0, sx * shearU, sx * (cw.x - w.umin) - 1.0},
                  {0.0, sy, sy * shearV, sy * (cw.y - w.vmin) - 1.0}, {0.0, 0.0, depthScale, farZ / (farZ - nearZ)},
                  {0.0, 0.0, 0.0, 1.0});
}

glm::dmat4 clipFromWorld(const ViewSpec& spec) { return clipFromEye(spec) * eyeFromView(spec) * viewFromWorld(spec); }

glm::dvec2 ndcFromWindow(const Window& window, glm::dvec2 uv) {
  return {2.0 * (uv.x - window.umin) / window.width() - 1.0, 2.0 * (uv.y - window.vmin) / window.height() - 1.0};
}

glm::dvec2 windowFromNdc(const Window& window, glm::dvec2 ndc) {
  return {window.umin + 0.5 * (ndc.x + 1.0) * window.width(), window.vmin + 0.5 * (ndc.y + 1.0) * window.height()};
}

glm::dvec2 pixelFromWindow(const Window& window, glm::dvec2 uv, int widthPx, int heightPx) {
  return {(uv.x - window.umin) / window.width() * widthPx, (window.vmax - uv.y) / window.height() * heightPx};
}

glm::dvec2 windowFromPixel(const Window& window, glm::dvec2 pixel, int widthPx, int heightPx) {
  return {window.umin + pixel.x / widthPx * window.width(), window.vmax - pixel.y / heightPx * window.height()};
}

glm::dvec2 normalisedFromWindow(const ViewSpec& spec, glm::dvec2 uv) {
  return (uv - glm::dvec2(spec.prp.x, spec.prp.y)) / spec.prp.z;
}

glm::dvec2 windowFromNormalised(const ViewSpec& spec, glm::dvec2 normalised) {
  return glm::dvec2(spec.prp.x, spec.prp.y) + normalised * spec.prp.z;
}

double depthFromReverseZ(const ViewSpec& spec, double zNdc) {
  const double nearZ = spec.nearDistance, farZ = spec.farDistance;
  if (spec.projection == Projection::Parallel) return farZ - zNdc * (farZ - nearZ);
  if (!(zNdc > 0.0)) return std::numeric_limits<double>::infinity();
  if (std::isinf(farZ)) return nearZ / zNdc;
  // z_ndc = near·(far − Z) / (Z·(far − near))  ⇒  Z = near·far / (z_ndc·(far − near) + near)
  return nearZ * farZ / (zNdc * (farZ - nearZ) + nearZ);
}

glm::dvec2 projectToWindow(const ViewSpec& spec, const glm::dvec3& worldPoint) {
  const glm::dvec3 p = glm::dvec3(viewFromWorld(spec) * glm::dvec4(worldPoint, 1.0));
  if (spec.projection == Projection::Perspective) {
    const double f = viewPlaneDistance(spec);
    const double bigX = p.x - spec.prp.x;
    const double bigY = p.y - spec.prp.y;
    const double bigZ = spec.prp.z - p.z;  // depth in front of the PRP
    return {spec.prp.x + f * bigX / bigZ, spec.prp.y + f * bigY / bigZ};
  }
  const glm::dvec3 dop = directionOfProjection(spec);
  const double t = -p.z / dop.z;  // reach n = 0 along DOP
  return {p.x + t * dop.x, p.y + t * dop.y};
}

}  // namespace lenslab
