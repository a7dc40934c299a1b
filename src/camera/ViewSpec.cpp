#include "camera/ViewSpec.h"

#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lenslab {
namespace {

bool finite(const glm::dvec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

[[noreturn]] void fail(std::string_view where, std::string_view message) {
  throw InputError(cat(where, ": ", message));
}

}  // namespace

ViewBasis viewBasis(const ViewSpec& spec) {
  const glm::dvec3 n = glm::normalize(spec.vpn);
  const glm::dvec3 u = glm::normalize(glm::cross(spec.vup, n));
  const glm::dvec3 v = glm::cross(n, u);
  return {u, v, n};
}

void validate(const ViewSpec& spec, std::string_view where) {
  if (!finite(spec.vrp)) fail(where, "vrp must be three finite numbers");
  if (!finite(spec.vpn)) fail(where, "vpn must be three finite numbers");
  if (!finite(spec.vup)) fail(where, "vup must be three finite numbers");
  if (!finite(spec.prp)) fail(where, "prp must be three finite numbers");
  const Window& w = spec.window;
  if (!(std::isfinite(w.umin) && std::isfinite(w.vmin) && std::isfinite(w.umax) && std::isfinite(w.vmax)))
    fail(where, "window must be four finite numbers [umin, vmin, umax, vmax]");

  const double vpnLength = glm::length(spec.vpn);
  if (!(vpnLength > 0.0)) fail(where, "vpn is the zero vector; give the view plane normal, pointing toward the viewer");
  const double vupLength = glm::length(spec.vup);
  if (!(vupLength > 0.0)) fail(where, "vup is the zero vector; give an up direction not parallel to vpn");
  // sin of the angle between VUP and VPN: u = VUP × n is undefined when they are parallel.
  const double sine = glm::length(glm::cross(spec.vup / vupLength, spec.vpn / vpnLength));
  if (sine < 1e-9)
    fail(where,
         "vup is parallel to vpn, so the view plane's u axis is undefined; give an up direction not parallel to vpn");

  if (!(w.umax > w.umin))
    fail(where, cat("window is empty or inverted: umax (", w.umax, ") must exceed umin (", w.umin, ")"));
  if (!(w.vmax > w.vmin))
    fail(where, cat("window is empty or inverted: vmax (", w.vmax, ") must exceed vmin (", w.vmin, ")"));

  const double prpN = spec.prp.z;
  if (spec.projection == Projection::Perspective) {
    if (prpN == 0.0)
      fail(where,
           "prp lies on the view plane (prp.n = 0); a perspective projection needs the PRP at n > 0, on the viewer's "
           "side");
    if (prpN < 0.0)
      fail(where, cat("prp.n is ", prpN, "; the PRP must be on the viewer's side of the view plane (n > 0)"));
    if (prpN < kMinPrpDistance)
      fail(where, cat("prp.n is ", prpN, "; the PRP must be at least ", kMinPrpDistance, " from the view plane"));
    if (!(spec.nearDistance > 0.0) || !std::isfinite(spec.nearDistance))
      fail(where, cat("near is ", spec.nearDistance, "; a perspective camera needs 0 < near < far"));
    // Window corners (from the PRP's foot) up to kMaxWindowSlope × PRP.n: a half-angle of 89.9994°.
    // Beyond, the projection is all but degenerate (every pixel looks along the view plane) and
    // float clipping cannot keep a near plane that leaves anything in view.
    const double reach = std::max({std::abs(w.umin - spec.prp.x), std::abs(w.umax - spec.prp.x),
                                   std::abs(w.vmin - spec.prp.y), std::abs(w.vmax - spec.prp.y)});
    if (!(reach <= kMaxWindowSlope * prpN))
      fail(where, cat("the window reaches ", reach, " from the PRP's foot at PRP distance ", prpN,
                      ", a field of view of nearly 180 degrees; keep it within ", kMaxWindowSlope,
                      " times prp.n (move the PRP away from the view plane or shrink the window)"));
    const double side = std::min(w.width(), w.height());
    if (side < kMinWindowSlope * prpN)
      fail(where, cat("the field of view is ", side / prpN, " rad (a window side of ", side, " at PRP distance ", prpN,
                      "); the narrowest lenslab draws is ", kMinWindowSlope,
                      " rad (a shorter focal length, larger sensor or wider yfov)"));
  } else {
    if (!(prpN > 0.0))
      fail(where,
           cat("prp.n is ", prpN, "; a parallel projection needs n > 0 so that DOP = CW - PRP points into the scene"));
    if (!std::isfinite(spec.nearDistance)) fail(where, "near must be a finite number");
    if (!std::isfinite(spec.farDistance))
      fail(where, "far must be finite for a parallel projection (its depth is linear)");
  }
  if (std::isnan(spec.farDistance)) fail(where, "far is NaN; give a number or \"infinity\"");
  if (!(spec.farDistance > spec.nearDistance))
    fail(where, cat("near (", spec.nearDistance, ") must be less than far (", spec.farDistance, ")"));
}

glm::dvec3 prpWorld(const ViewSpec& spec) {
  const ViewBasis b = viewBasis(spec);
  return spec.vrp + spec.prp.x * b.u + spec.prp.y * b.v + spec.prp.z * b.n;
}

glm::dvec3 directionOfProjection(const ViewSpec& spec) {
  const glm::dvec2 cw = spec.window.center();
  return glm::dvec3(cw.x, cw.y, 0.0) - spec.prp;
}

}  // namespace lenslab
