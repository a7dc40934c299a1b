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
  std::vector<Geometry> geometries;           // by Embree geometry ID
  std::vector<ShadingLight> lights;           // positions relative to `origin` (rebase)
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

}  // namespace lenslab
