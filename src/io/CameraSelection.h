#pragma once
// Which camera a command uses: a camera file when given; else the scene's first glTF camera;
// else an automatic framing of the scene's bounds.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "scene/Scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lenslab {

// `imageAspect` is used for a glTF perspective camera that gives no aspectRatio (0 = use 3:2).
SelectedCamera selectCamera(const Scene& scene, const std::optional<std::filesystem::path>& cameraFile,
                            double imageAspect);

// A 35 mm lens on a 36×24 mm sensor looking at the bounds' centre from the front and a little
// above, far enough back that the bounding sphere fits the vertical field of view.
PhysicalCamera autoFramingCamera(const Bounds& bounds);

// The scene and camera files a command uses: with no scene, the bundled `rows` scene with its
// camera file `defaultCamera` (e.g. "camera.json"), found by assetDirectory() (core/DataPaths.h);
// an explicit --camera always wins.
struct SceneAndCamera {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> camera;
};
SceneAndCamera resolveSceneAndCamera(const std::string& sceneArgument, const std::string& cameraArgument,
                                     const std::string& defaultCamera);

}  // namespace lenslab
