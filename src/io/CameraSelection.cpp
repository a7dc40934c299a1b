#include "io/CameraSelection.h"

#include "camera/GltfCamera.h"
#include "core/DataPaths.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"

#include <cmath>

namespace lenslab {
namespace fs = std::filesystem;

SceneAndCamera resolveSceneAndCamera(const std::string& sceneArgument, const std::string& cameraArgument,
                                     const std::string& defaultCamera) {
  SceneAndCamera r;
  r.scene = sceneArgument;
  if (!cameraArgument.empty()) r.camera = cameraArgument;
  if (r.scene.empty()) {
    const fs::path assets = assetDirectory();  // core/DataPaths.h: installed, source tree or LENSLAB_ASSET_DIR
    r.scene = assets / "rows" / "rows.gltf";
    if (!r.camera) r.camera = assets / "rows" / defaultCamera;
  }
  return r;
}

PhysicalCamera autoFramingCamera(const Bounds& bounds) {
  PhysicalCamera c;
  const glm::dvec3 center = bounds.empty() ? glm::dvec3(0.0) : bounds.center();
  const double radius = bounds.empty() ? 1.0 : std::max(0.5 * glm::length(bounds.size()), 1e-6);
  const double halfFov = 0.5 * verticalFovRadians(c);  // at infinity focus this is atan(12/35)
  const double distance = radius / std::sin(halfFov) * 1.05;
  const glm::dvec3 direction = glm::normalize(glm::dvec3(0.0, 0.35, 1.0));
  c.eye = center + distance * direction;
  c.target = center;
  c.focusDistance = distance;
  c.nearDistance = std::max(distance - radius, distance * 1e-4) * 0.5;
  return c;
}

SelectedCamera selectCamera(const Scene& scene, const std::optional<fs::path>& cameraFile, double imageAspect) {
  SelectedCamera selected;
  if (cameraFile) {
    CameraFile file = loadCameraJson(*cameraFile);
    selected.camera = file.camera;
    selected.physical = file.physical;
    return selected;
  }
  if (!scene.cameras.empty()) {
    const SceneCamera& c = scene.cameras.front();
    // glTF cameras have no focus; put the view plane (the plane of focus) at the depth of the
    // scene's centre, no nearer than twice znear.
    const glm::dvec3 eye(c.worldFromCamera[3]);
    const glm::dvec3 forward = glm::normalize(-glm::dvec3(c.worldFromCamera[2]));
    double focus = scene.bounds.empty() ? 1.0 : glm::dot(scene.bounds.center() - eye, forward);
    focus = std::max(focus, 2.0 * c.znear);
    if (!(focus > 0.0)) focus = 1.0;
    const double aspect = c.aspectRatio > 0.0 ? c.aspectRatio : (imageAspect > 0.0 ? imageAspect : 1.5);
    const ViewSpec view =
        c.perspective ? viewSpecFromGltfPerspective(c.worldFromCamera, c.yfovRadians, aspect, c.znear, c.zfar, focus)
                      : viewSpecFromGltfOrthographic(c.worldFromCamera, c.xmag, c.ymag, c.znear, c.zfar, focus);
    selected.camera = cameraFocusedOnViewPlane(view, 0.0, cat("glTF camera 0", c.name.empty() ? "" : cat(" (", c.name, ")")));
    selected.camera.farFromScene = std::isinf(c.zfar);  // glTF: an absent zfar is an infinite projection
    validate(selected.camera.view, cat(scene.source, ": ", selected.camera.source));
    return selected;
  }
  const PhysicalCamera c = autoFramingCamera(scene.bounds);
  selected.camera = toCamera(c, "automatic framing of the scene bounds");
  selected.camera.nearFromScene = selected.camera.farFromScene = true;
  selected.physical = c;
  return selected;
}

}  // namespace lenslab
