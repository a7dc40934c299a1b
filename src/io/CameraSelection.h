#pragma once
// Which camera a command uses. The base camera comes from the first of these sources that gives
// one:
//   1. --camera FILE             a camera file (lecture, physical or OpenCV-intrinsics form)
//   2. --camera-node NAME|INDEX  that glTF camera of the scene
//   3. the scene's first glTF camera
//   4. automatic framing of the scene's bounding sphere
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

// The base camera, from the first source in the order above. Throws InputError for a bad file, an
// unknown --camera-node, or both a file and a node.
BaseCamera baseCamera(const Scene& scene, const std::optional<std::filesystem::path>& cameraFile, const std::string& cameraNode);

// The base camera with `options` applied. `imageAspect` (--width / --height when both are given,
// else 0) is used for a glTF perspective camera that gives no aspectRatio (0 = use 3:2).
SelectedCamera chooseCamera(const Scene& scene, const std::optional<std::filesystem::path>& cameraFile,
                            const CameraOptions& options, double imageAspect);

// The scene and camera files a command uses: with no scene, the bundled `rows` scene with its
// camera file `defaultCamera` (e.g. "camera.json"; empty: none); an explicit --camera always wins.
struct SceneAndCamera {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> camera;
};
SceneAndCamera resolveSceneAndCamera(const std::string& sceneArgument, const std::string& cameraArgument,
                                     const std::string& defaultCamera);

// Where the bundled assets are: LENSLAB_ASSET_DIR in the environment, else the source tree's
// assets/ (compiled in as LENSLAB_DEFAULT_ASSET_DIR).
std::filesystem::path assetDirectory();

}  // namespace lenslab
