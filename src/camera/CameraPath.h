#pragma once
// A camera path for headless capture: physical cameras keyed in time, and the camera at any time
// between them (issue #14's `lenslab capture --path`).
//
// "smooth" (the default):
//   eye, target   centripetal Catmull–Rom splines (knots spaced by √distance: no cusps and no
//                 loops within a segment, Yuksel, Schaefer and Keyser 2011); the path passes
//                 through every key
//   up            interpolated, then made orthogonal to the view direction and unit length
//   focus         in inverse distance 1/z_f: blur grows with |1/z − 1/z_f|, so a rack focus that
//                 is even in 1/z_f looks even to the eye
//   f-number      in stops, log2 N
//                 (focus and stops by monotone cubic Hermite interpolation, Fritsch–Carlson: no
//                 overshoot, so focus moves one way between two keys)
//   focal length, sensor, near, far and the lens effects: linearly
// "linear": every quantity piecewise linear in time (focus still in 1/z_f, f-number in stops).
// Outside the keys' times the first or last key holds.
//
// Keys in the lecture or OpenCV form (a calibrated K, R and t; camera/ViewPath.h) are interpolated
// as a pinhole's pose and intrinsics instead: a path holds keys of one kind.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "lens/Lens.h"

#include <optional>
#include <string_view>
#include <vector>

namespace lenslab {

struct PathKey {
  double timeSeconds = 0.0;
  PhysicalCamera camera;
  // The lens beyond the physical description: its effects, and its aperture shape and barrel, one
  // each for the whole path (the keys must agree, io/CameraPathJson). Its radius is not read: the
  // camera's f/2N is (toCamera(PhysicalCamera, Lens, …)).
  Lens lens;
};

// A key in the lecture or OpenCV-intrinsics form: the camera as its file gives it (perspective).
struct ViewPathKey {
  double timeSeconds = 0.0;
  Camera camera;
};

enum class PathInterpolation { Smooth, Linear };

struct CameraPath {
  double fps = 24.0;
  std::vector<PathKey> keys;          // physical keys, or
  std::vector<ViewPathKey> viewKeys;  // keys in the lecture or OpenCV form (camera/ViewPath.h)
  PathInterpolation interpolation = PathInterpolation::Smooth;
  std::optional<int> frames;  // given: this many; else floor(last time × fps) + 1
  // No key gives near (far): each frame's is fitted to the scene, as a camera file's would be.
  // Keys that leave it out while others give it take the physical default.
  bool nearFromScene = true;
  bool farFromScene = true;

  int frameCount() const;
  bool holdsViews() const { return !viewKeys.empty(); }
  double lastKeyTimeSeconds() const;
  double frameTimeSeconds(int frame) const { return frame / fps; }
};

// The frames of `durationSeconds` at `fps`: floor(duration × fps) + 1 (frame k at k / fps). Throws
// InputError naming `where` beyond kMaxFrames, which an int frame number must hold.
constexpr double kMaxFrames = 1e7;
int frameCountFor(double durationSeconds, double fps, std::string_view where);

// Throws InputError naming `where` and the key: no keys, fps not positive and finite, times not
// finite or not strictly increasing, a frame count below 1, or f-numbers that mix a pinhole
// (infinity) with a lens (stops cannot span them).
void validate(const CameraPath& path, std::string_view where);

// The camera at `timeSeconds` (a valid path).
PathKey cameraAt(const CameraPath& path, double timeSeconds);

// One centripetal Catmull–Rom segment from p1 (u = 0) to p2 (u = 1), with neighbours p0 and p3.
glm::dvec3 centripetalCatmullRom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
                                 double u);

// The segment [index, index + 1] of strictly increasing `times` (at least two) that holds t, and
// where in it, u from 0 to 1 (clamped: before the first key u = 0 of the first segment).
struct PathSegment {
  std::size_t index = 0;
  double u = 0.0;
};
PathSegment segmentAt(const std::vector<double>& times, double t);

// The smooth path through `points` (one a key) on segment k at u: centripetal Catmull–Rom, the
// ends' missing neighbours reflected through their neighbour.
glm::dvec3 splineThrough(const std::vector<glm::dvec3>& points, std::size_t k, double u);

// a at u = 0 to b at u = 1 (a + (b − a)·u: a value both keys share is held exactly).
inline double lerp(double a, double b, double u) { return a + (b - a) * u; }
// The same for a distance that may be +infinity (a far plane): infinity stays there, and between a
// finite and an infinite one the finite holds.
double lerpDistance(double a, double b, double u);

// Monotone cubic Hermite interpolation (Fritsch–Carlson) of values y at strictly increasing x.
double monotoneCubic(const std::vector<double>& x, const std::vector<double>& y, double at);

}  // namespace lenslab
