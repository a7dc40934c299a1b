#pragma once
// The lecture's viewing description (Foley–van Dam's VRP/VPN/VUP/PRP/window model).
//
// Conventions (FvD):
//   n = normalize(VPN)        the view plane normal, pointing toward the viewer
//   u = normalize(VUP × n)    right on the view plane
//   v = n × u                 up on the view plane
// (u, v, n) is right-handed with origin at VRP: "view-reference coordinates" (VRC).
// The view plane is n = 0. The camera looks along −n. The PRP (projection reference point, the
// lecture's focal point "fp") is given in VRC and sits on the +n side (n > 0).
// near and far are distances from the PRP along −n; far may be +infinity (perspective only).
// In lenslab the view plane is also the plane of focus (../ARCHITECTURE: the thin lens moves the
// PRP across the aperture while the window stays put).
#include <glm/glm.hpp>

#include <limits>
#include <string_view>

namespace lenslab {

enum class Projection { Perspective, Parallel };

// The window: a rectangle on the view plane in view-reference units (u, v), "minu, minv, maxu, maxv".
struct Window {
  double umin = -1.0;
  double vmin = -1.0;
  double umax = 1.0;
  double vmax = 1.0;

  double width() const { return umax - umin; }
  double height() const { return vmax - vmin; }
  glm::dvec2 center() const { return {0.5 * (umin + umax), 0.5 * (vmin + vmax)}; }
};

// A perspective camera's near distance when none is given, as a fraction of the view plane's
// distance PRP.n: the lecture form's default (PRP.n / 1000), which the forms whose scale is not
// known (an OpenCV pose, a COLMAP image) take too.
constexpr double kDefaultNearPerViewPlaneDistance = 1e-3;

struct ViewSpec {
  Projection projection = Projection::Perspective;
  glm::dvec3 vrp{0.0};            // View Reference Point: origin of the view plane's (u, v), world
  glm::dvec3 vpn{0.0, 0.0, 1.0};  // View Plane Normal, world; points toward the viewer
  glm::dvec3 vup{0.0, 1.0, 0.0};  // View UP, world; its projection on the view plane is +v
  glm::dvec3 prp{0.0, 0.0, 1.0};  // Projection Reference Point (focal point), in VRC (u, v, n)
  Window window;                  // on the view plane, VRC units
  double nearDistance = kDefaultNearPerViewPlaneDistance;        // from the PRP along −n, world units (PRP.n is 1)
  double farDistance = std::numeric_limits<double>::infinity();  // from the PRP along −n
};

// The orthonormal view basis in world coordinates.
struct ViewBasis {
  glm::dvec3 u;
  glm::dvec3 v;
  glm::dvec3 n;
};

ViewBasis viewBasis(const ViewSpec& spec);

// The widest perspective lenslab draws: window corners up to this many times PRP.n from the
// PRP's foot (a half-angle of 89.9994 degrees).
constexpr double kMaxWindowSlope = 1e5;

// The narrowest perspective lenslab draws: the window's smaller side at least this many times
// PRP.n (a field of view of 1e-12 rad). The raster places triangles in double down to about
// 1e-14 rad; below that double's 16 digits of a position no longer resolve a pixel.
constexpr double kMinWindowSlope = 1e-12;

// The nearest a perspective PRP may be to the view plane (world units). Both renderers are
// scale-free down to here; below, the default near distance (PRP.n / 1000) and the window's
// pixel steps fall into double's subnormal range and lose their digits.
constexpr double kMinPrpDistance = 1e-300;

// Throws InputError naming `where` (a file or option) and the field when the description is
// degenerate: non-finite values, zero VPN, VUP parallel to VPN, empty or inverted window, PRP on or
// behind the view plane, near >= far, near <= 0 (perspective), infinite far (parallel).
void validate(const ViewSpec& spec, std::string_view where);

// The PRP in world coordinates.
glm::dvec3 prpWorld(const ViewSpec& spec);

// Distance from the PRP to the view plane: the lecture's focal length f (= PRP.n).
inline double viewPlaneDistance(const ViewSpec& spec) { return spec.prp.z; }

// Direction of projection for parallel projection: DOP = CW − PRP, in VRC.
glm::dvec3 directionOfProjection(const ViewSpec& spec);

}  // namespace lenslab
