#pragma once
// Which camera a command uses. The base camera comes from the first of these sources that gives
// one:
//   1. --camera FILE             a camera file (lecture, physical or OpenCV-intrinsics form)
//   2. --colmap DIR --image NAME that photograph's camera in a COLMAP text model (io/ColmapModel.h)
//   3. --camera-node NAME|INDEX  that glTF camera of the scene
//   4. the scene's first glTF camera
//   5. automatic framing of the scene's bounding sphere
// The first three name a camera: at most one of them may be given.
// (a new source goes into baseCamera, in its place in this order). The lens and pose options then
// override it field by field (plan/CameraOptions.h: composeCamera).
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "plan/CameraOptions.h"
#include "scene/Scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lenslab {

// The base camera, from the first source in the order above (`options` gives --colmap, --image and
// --camera-node). Throws InputError for a bad file or model, an unknown node or image, --colmap
// without --image (or the reverse), or two sources that name a camera.
BaseCamera baseCamera(const Scene& scene, const std::optional<std::filesystem::path>& cameraFile,
                      const CameraOptions& options);

// The base camera with `options` applied. `imageAspect` (--width / --height when both are given,
// else 0) is used for a glTF perspective camera that gives no aspectRatio (0 = use 3:2).
SelectedCamera chooseCamera(const Scene& scene, const std::optional<std::filesystem::path>& cameraFile,
                            const CameraOptions& options, double imageAspect);

// The scene and camera files a command uses: with no scene, the bundled `rows` scene with its
// camera file `defaultCamera` (e.g. "camera.json"; empty: none), found by assetDirectory()
// (core/DataPaths.h); an explicit --camera always wins.
struct SceneAndCamera {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> camera;
};
SceneAndCamera resolveSceneAndCamera(const std::string& sceneArgument, const std::string& cameraArgument,
                                     const std::string& defaultCamera);

}  // namespace lenslab
