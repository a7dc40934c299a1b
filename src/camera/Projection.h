#pragma once
// From the world to the image, in the lecture's steps. Transforms are named destinationFromSource,
// so chains read right to left: clipFromWorld = clipFromEye * eyeFromView * viewFromWorld.
//
//   world ──viewFromWorld──► VRC (u, v, n; origin VRP)
//         ──eyeFromView────► eye: origin at the PRP, X = u, Y = v, Z = depth along −n
//                            (the lecture's frame, in which u = f·X/Z and v = f·Y/Z)
//         ──clipFromEye────► GL clip space; x, y from the lecture's 1/f matrix and the window,
//                            z from a reverse-Z depth mapping (1 at near, 0 at far)
//
// Depth precision: clipFromWorld is built for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) with a
// float depth buffer cleared to 0 and depth test GREATER ("reverse-Z"). Floating point is densest
// near 0, which reverse-Z assigns to far depths, so relative depth precision is about 2^-24
// everywhere between near and far, and far = infinity is exact (z_ndc = near / Z).
#include "camera/ViewSpec.h"

#include <glm/glm.hpp>

namespace lenslab {

glm::dmat4 viewFromWorld(const ViewSpec& spec);
glm::dmat4 worldFromView(const ViewSpec& spec);

// Moves the origin to the PRP and turns −n into +Z depth (a reflection: the eye frame is
// left-handed, as the lecture draws it, with Z growing away from the viewer).
glm::dmat4 eyeFromView(const ViewSpec& spec);

// The lecture's perspective projection matrix for focal length f (PRP at the origin, view plane at
// Z = f):
//   | 1 0 0   0 |
//   | 0 1 0   0 |
//   | 0 0 1   0 |
//   | 0 0 1/f 0 |
// After the homogeneous divide a point (X, Y, Z) lands at (f·X/Z, f·Y/Z, f) on the view plane.
glm::dmat4 lecturePerspective(double f);

// GL clip coordinates from eye coordinates. Perspective: rows x, y and w are the lecture matrix
// followed by the window→NDC map (the window may be off-centre: oblique projection). The lecture
// matrix sends every point to z' = f, so it keeps no depth; the z row is replaced by the reverse-Z
// mapping z_ndc = near·(far − Z) / (Z·(far − near)) (near / Z when far is infinite).
// Parallel: points move along DOP = CW − PRP onto the view plane (a shear when the PRP is not over
// the window centre), z_ndc = (far − Z) / (far − near).
glm::dmat4 clipFromEye(const ViewSpec& spec);

glm::dmat4 clipFromWorld(const ViewSpec& spec);

// Normalised device x, y in [-1, 1] from window (u, v), and back.
glm::dvec2 ndcFromWindow(const Window& window, glm::dvec2 uv);
glm::dvec2 windowFromNdc(const Window& window, glm::dvec2 ndc);

// Continuous pixel coordinates (origin at the image's top-left corner, +x right, +y down, pixel
// centres at i + 0.5) from window (u, v), and back.
glm::dvec2 pixelFromWindow(const Window& window, glm::dvec2 uv, int widthPx, int heightPx);
glm::dvec2 windowFromPixel(const Window& window, glm::dvec2 pixel, int widthPx, int heightPx);

// Normalised image coordinates (lens/LensEffects.h) of window point (u, v) of a perspective view:
// (u − PRP.u, v − PRP.v) / PRP.n, the point's position on a view plane at unit distance measured
// from the principal point; (X/Z, Y/Z) of the eye frame. And back.
glm::dvec2 normalisedFromWindow(const ViewSpec& spec, glm::dvec2 uv);
glm::dvec2 windowFromNormalised(const ViewSpec& spec, glm::dvec2 normalised);

// Depth (the lecture's Z: world units from the PRP along −n) of a reverse-Z depth-buffer value;
// +infinity for 0 (nothing drawn there, the far plane at infinity).
double depthFromReverseZ(const ViewSpec& spec, double zNdc);

// The lecture's formula applied directly (no matrices): where a world point lands on the view plane,
// in window (u, v). Perspective: u = PRP.u + f·X/Z, v = PRP.v + f·Y/Z. Parallel: along DOP.
glm::dvec2 projectToWindow(const ViewSpec& spec, const glm::dvec3& worldPoint);

}  // namespace lenslab
