#pragma once
// The ray caster's geometry in Embree, and how its precision is kept (raycast/RayCaster.cpp's
// shading reads it). Embree works in float: the scene's triangles are stored relative to an origin
// near the camera's lens centre and in units of a power of two near the scene's size, and each ray
// starts where it enters the scene's bounds, so that float's relative error applies to sizes within
// the scene, not to its distance from (0,0,0) or from the camera (docs/stability.md).
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/Ray.h"
#include "core/Error.h"
#include "scene/Scene.h"
#include "scene/ShadingLights.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

namespace lenslab {

struct EmbreeScene {
  // Makes the Embree device (LENSLAB_EMBREE_CONFIG, when set, is its configuration); the scene
  // is built on first use, relative to that camera (rebase). `scene` must outlive it.
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  const Scene* scene = nullptr;
  RTCDevice device = nullptr;
  RTCScene rtcScene = nullptr;
  struct Geometry {
    int instance;
    const float* relativePositions;  // Embree's vertex buffer: 3 floats per vertex, (world − origin) / scale
    glm::mat3 normalFromModel;
    bool mirrored;
    glm::mat3 tangentFromModel;  // worldFromModel's linear part, scaled to its largest entry (scene.vert)
  };
  std::vector<Geometry> geometries;  // by Embree geometry ID
  std::vector<ShadingLight> lights;  // positions relative to `origin` (rebase)
  // Embree works in float. Its geometry is stored relative to `origin` (the point of the scene's
  // bounds nearest the camera's lens centre, subtracted in double), and each ray starts where it
  // enters the bounds: a scene 1e7 from the world origin, or a telephoto's subject 1e9 from the
  // camera, keeps the precision it has at the origin, float's relative error applying to sizes
  // within the scene and not to its distance from (0,0,0) or from the camera.
  glm::dvec3 origin{std::numeric_limits<double>::quiet_NaN()};
  // ... and in units of `scale` world units, a power of two near the scene's size, so that a scene
  // of 1e-12 or 1e-30 metres reaches Embree at the size of a metre: Embree runs with denormals
  // flushed to zero, and its triangle test multiplies edge by edge by edge (a 1e-13 scene already
  // underflows there). Scaling by a power of two rounds nothing; t values scale by it as well.
  double scale = 1.0;
  std::mutex rebaseMutex;

  void release();
  // (Re)builds the Embree scene with its geometry relative to `newOrigin`, unless it already is.
  void rebase(const glm::dvec3& newOrigin);
  // The origin the geometry is kept relative to for `camera`: the point of the bounds nearest its
  // lens centre (the lens centre itself when it is inside them).
  glm::dvec3 originFor(const Camera& camera, ImageSize size) const;

  static bool finite(const glm::dvec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
  // Embree's RayK::valid(), which it asserts before tracing.
  static bool embreeTakes(const RTCRay& r);
  static InputError unfiniteRay(const Camera& camera, glm::dvec2 pixel);
  // [enter, exit] of `ray` (relative to `origin`) through the scene's bounds, widened by a margin
  // so that a surface on a face of the box is never missed; empty (enter > exit) on a miss.
  std::pair<double, double> boundsSpan(const Ray& ray) const;
};

// Inline: both run for every ray, inside the shading loop.
inline bool EmbreeScene::embreeTakes(const RTCRay& r) {
  constexpr float kLarge = 1.8e18f;  // Embree's FLT_LARGE is 1.844e18
  for (const float v : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z})
    if (!(std::abs(v) <= kLarge)) return false;
  return r.tnear >= 0.0f && r.tnear <= r.tfar;
}

inline std::pair<double, double> EmbreeScene::boundsSpan(const Ray& ray) const {
  const glm::dvec3 lo = scene->bounds.min - origin, hi = scene->bounds.max - origin;
  const double pad = 1e-4 * glm::length(hi - lo) + 1e-6 * glm::length(glm::abs(lo) + glm::abs(hi)) + 1e-30;
  double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double o = ray.origin[a], d = ray.direction[a];
    if (d == 0.0) {
      if (o < lo[a] - pad || o > hi[a] + pad) return {1.0, 0.0};
      continue;
    }
    const double t0 = (lo[a] - pad - o) / d, t1 = (hi[a] + pad - o) / d;
    enter = std::max(enter, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  return {enter, exit};
}

}  // namespace lenslab
