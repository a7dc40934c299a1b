#include "camera/CameraPath.h"

#include "camera/ViewPath.h"
#include "core/Error.h"
#include "core/Text.h"
#include "lens/effects/LensEffectRegistry.h"

#include <algorithm>
#include <cmath>

namespace lenslab {
namespace {

glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double u) { return a + (b - a) * u; }

// A neighbour beyond the ends: the end point reflected through its neighbour.
glm::dvec3 pointOr(const std::vector<glm::dvec3>& p, std::ptrdiff_t i) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.size());
  if (i < 0) return 2.0 * p[0] - p[std::min<std::ptrdiff_t>(1, n - 1)];
  if (i >= n)
    return 2.0 * p[static_cast<std::size_t>(n - 1)] - p[static_cast<std::size_t>(std::max<std::ptrdiff_t>(n - 2, 0))];
  return p[static_cast<std::size_t>(i)];
}

// Up made orthogonal to the view direction and unit length: the view it gives is the same (the
// view basis is built that way), and an interpolated up is comparable with a key's.
// Where eye meets target, or up lies along the view direction, there is no such up: `up` is
// returned as it is, for validate to name what is wrong (not NaNs from normalising zero).
glm::dvec3 orthonormalUp(const PhysicalCamera& c, const glm::dvec3& up) {
  const glm::dvec3 forward = c.target - c.eye;
  if (!(glm::length(forward) > 0.0)) return up;
  const glm::dvec3 view = glm::normalize(forward);
  const glm::dvec3 across = up - glm::dot(up, view) * view;
  if (!(glm::length(across) > 1e-9 * glm::length(up))) return up;
  return glm::normalize(across);
}

// Every frame's camera, as capture will build it, checked before the first frame is drawn: the
// keys can each be valid while the interpolation between them is not (an eye that passes through
// its target, ups that turn by 180° and cancel half way).
void validateFrames(const CameraPath& path, std::string_view where) {
  const int frames = path.frameCount();
  for (int frame = 0; frame < frames; ++frame) {
    const double t = path.frameTimeSeconds(frame);
    const std::string at = cat(where, ": frame ", frame, " (t = ", t, " s)");
    const PhysicalCamera c = cameraAt(path, t).camera;
    const double distance = glm::length(c.target - c.eye);
    const double scale = std::max({glm::length(c.eye), glm::length(c.target), 1.0});
    if (!(distance > 1e-9 * scale))
      throw InputError(cat(
          at,
          ": eye meets target (the path's eye passes through its target there); move the keys' eye or target apart"));
    if (!(glm::length(c.up) > 0.0) ||
        glm::length(glm::cross(glm::normalize(c.up), (c.target - c.eye) / distance)) < 1e-9)
      throw InputError(
          cat(at,
              ": up is parallel to the view direction (or the keys' ups turn by 180° and cancel); add a key "
              "between them or give an up across the view"));
    validate(c, at);
  }
}

void validateKeyTimes(const std::vector<double>& times, std::string_view where) {
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (!std::isfinite(t) || t < 0.0)
      throw InputError(cat(where, ": keys[", i, "].time ", t, " must be a finite time in seconds, 0 or more"));
    if (i > 0 && !(t > times[i - 1]))
      throw InputError(cat(where, ": keys[", i, "].time ", t, " must be later than keys[", i - 1, "].time ",
                           times[i - 1], " (keys in order, no time twice)"));
  }
}

}  // namespace

double lerpDistance(double a, double b, double u) {
  if (std::isinf(a) && std::isinf(b)) return a;
  if (std::isinf(a)) return b;
  if (std::isinf(b)) return a;
  return lerp(a, b, u);
}

PathSegment segmentAt(const std::vector<double>& times, double t) {
  const auto after = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t k = static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(after - times.begin() - 1, 0, static_cast<std::ptrdiff_t>(times.size()) - 2));
  const double u = (t - times[k]) / (times[k + 1] - times[k]);
  return {k, std::clamp(u, 0.0, 1.0)};
}

glm::dvec3 splineThrough(const std::vector<glm::dvec3>& p, std::size_t k, double u) {
  const std::ptrdiff_t i = static_cast<std::ptrdiff_t>(k);
  return centripetalCatmullRom(pointOr(p, i - 1), p[k], p[k + 1], pointOr(p, i + 2), u);
}

int frameCountFor(double durationSeconds, double fps, std::string_view where) {
  const double frames = durationSeconds * fps;
  if (!(frames <= kMaxFrames)) throw InputError(cat(where, ": ", frames, " frames (duration × fps): at most 10^7"));
  return static_cast<int>(std::floor(frames + 1e-9)) + 1;
}

double CameraPath::lastKeyTimeSeconds() const {
  if (!viewKeys.empty()) return viewKeys.back().timeSeconds;
  return keys.empty() ? 0.0 : keys.back().timeSeconds;
}

int CameraPath::frameCount() const {
  if (frames) return *frames;
  if (keys.empty() && viewKeys.empty()) return 0;
  return frameCountFor(lastKeyTimeSeconds(), fps, "camera path");
}

void validate(const CameraPath& path, std::string_view where) {
  if (!(path.fps > 0.0) || !std::isfinite(path.fps))
    throw InputError(cat(where, ": fps ", path.fps, " must be a positive number of frames per second"));
  if (path.keys.empty() && path.viewKeys.empty())
    throw InputError(cat(where, ": keys: give at least one key ({\"time\": 0, <a camera>})"));
  if (!path.keys.empty() && !path.viewKeys.empty())
    throw InputError(
        cat(where, ": keys: give every key in the physical form, or every key in the lecture or OpenCV form"));
  std::vector<double> times;
  for (const PathKey& key : path.keys) times.push_back(key.timeSeconds);
  for (const ViewPathKey& key : path.viewKeys) times.push_back(key.timeSeconds);
  validateKeyTimes(times, where);
  if (path.frames && *path.frames < 1) throw InputError(cat(where, ": frames ", *path.frames, " must be 1 or more"));
  if (!path.frames) frameCountFor(path.lastKeyTimeSeconds(), path.fps, where);
  if (path.holdsViews()) {
    validateViewFrames(path, where);
    return;
  }
  for (std::size_t i = 0; i < path.keys.size(); ++i) {
    if (std::isinf(path.keys[i].camera.fNumber) != std::isinf(path.keys[0].camera.fNumber))
      throw InputError(cat(where, ": keys[", i,
                           "].f_number: a pinhole (no f_number) and a lens cannot be interpolated in stops; "
                           "give every key an f_number, or none"));
    validate(path.keys[i].camera, cat(where, ": keys[", i, "]"));
  }
  validateFrames(path, where);
}

glm::dvec3 centripetalCatmullRom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3,
                                 double u) {
  // Barry–Goldman's pyramid with knots spaced by √|p_i+1 − p_i|. Coincident points get a tiny
  // spacing, which leaves the segment its straight line.
  const auto spacing = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::max(std::sqrt(glm::length(b - a)), 1e-12);
  };
  const double t0 = 0.0, t1 = t0 + spacing(p0, p1), t2 = t1 + spacing(p1, p2), t3 = t2 + spacing(p2, p3);
  if (glm::length(p2 - p1) == 0.0) return p1;
  const double t = lerp(t1, t2, u);
  const glm::dvec3 a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
  const glm::dvec3 a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
  const glm::dvec3 a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
  const glm::dvec3 b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
  const glm::dvec3 b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
  return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

double monotoneCubic(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const std::size_t n = x.size();
  if (n == 1) return y[0];
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  std::vector<double> slope(n - 1), m(n);
  for (std::size_t i = 0; i + 1 < n; ++i) slope[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  m[0] = slope[0];
  m[n - 1] = slope[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) m[i] = slope[i - 1] * slope[i] <= 0.0 ? 0.0 : (slope[i - 1] + slope[i]) / 2.0;
  // Fritsch–Carlson: where a tangent would overshoot, scale the pair back into the monotone region.
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (slope[i] == 0.0) {
      m[i] = m[i + 1] = 0.0;
      continue;
    }
    const double a = m[i] / slope[i], b = m[i + 1] / slope[i];
    const double r = a * a + b * b;
    if (r > 9.0) {
      const double s = 3.0 / std::sqrt(r);
      m[i] = s * a * slope[i];
      m[i + 1] = s * b * slope[i];
    }
  }
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
  const double h = x[k + 1] - x[k], u = (at - x[k]) / h;
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
               h11 = u * u * (u - 1);
  return h00 * y[k] + h10 * h * m[k] + h01 * y[k + 1] + h11 * h * m[k + 1];
}

PathKey cameraAt(const CameraPath& path, double timeSeconds) {
  const std::vector<PathKey>& keys = path.keys;
  const auto held = [&](const PathKey& key) {
    PathKey out{timeSeconds, key.camera, key.lens};
    out.camera.up = orthonormalUp(key.camera, key.camera.up);
    return out;
  };
  if (keys.size() == 1 || timeSeconds <= keys.front().timeSeconds) return held(keys.front());
  if (timeSeconds >= keys.back().timeSeconds) return held(keys.back());
  std::vector<double> times, inverseFocus, stops;
  for (const PathKey& key : keys) times.push_back(key.timeSeconds);
  const auto [k, u] = segmentAt(times, timeSeconds);
  const PhysicalCamera& a = keys[k].camera;
  const PhysicalCamera& b = keys[k + 1].camera;
  const bool smooth = path.interpolation == PathInterpolation::Smooth;

  PathKey out;
  out.timeSeconds = timeSeconds;
  // Each lens effect as its module interpolates it (lens/effects/).
  out.lens = interpolateLens(keys[k].lens, keys[k + 1].lens, u);
  PhysicalCamera& c = out.camera;
  std::vector<glm::dvec3> eyes, targets;
  for (const PathKey& key : keys) {
    inverseFocus.push_back(1.0 / key.camera.focusDistance);  // 0 at infinity
    stops.push_back(std::log2(key.camera.fNumber));
    eyes.push_back(key.camera.eye);
    targets.push_back(key.camera.target);
  }
  c.eye = smooth ? splineThrough(eyes, k, u) : lerp(a.eye, b.eye, u);
  c.target = smooth ? splineThrough(targets, k, u) : lerp(a.target, b.target, u);
  // Up: interpolated, then the part along the view direction removed (a camera rolls only as the
  // keys say).
  c.up = orthonormalUp(c, lerp(orthonormalUp(a, a.up), orthonormalUp(b, b.up), u));
  const double inverse =
      smooth ? monotoneCubic(times, inverseFocus, timeSeconds) : lerp(inverseFocus[k], inverseFocus[k + 1], u);
  c.focusDistance = inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
  c.fNumber = std::isinf(a.fNumber)
                  ? a.fNumber
                  : std::exp2(smooth ? monotoneCubic(times, stops, timeSeconds) : lerp(stops[k], stops[k + 1], u));
  c.focalLengthMm = lerp(a.focalLengthMm, b.focalLengthMm, u);
  c.sensorMm = glm::dvec2(lerp(a.sensorMm.x, b.sensorMm.x, u), lerp(a.sensorMm.y, b.sensorMm.y, u));
  c.nearDistance = lerp(a.nearDistance, b.nearDistance, u);
  c.farDistance = lerpDistance(a.farDistance, b.farDistance, u);
  return out;
}

}  // namespace lenslab
