#include "io/CameraSelection.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"

#include <cstdlib>

namespace lenslab {
namespace fs = std::filesystem;

fs::path assetDirectory() {
  if (const char* env = std::getenv("LENSLAB_ASSET_DIR"); env && *env) return env;
  return LENSLAB_DEFAULT_ASSET_DIR;
}

SceneAndCamera resolveSceneAndCamera(const std::string& sceneArgument, const std::string& cameraArgument,
                                     const std::string& defaultCamera) {
  SceneAndCamera r;
  r.scene = sceneArgument;
  if (!cameraArgument.empty()) r.camera = cameraArgument;
  if (r.scene.empty()) {
    r.scene = assetDirectory() / "rows" / "rows.gltf";
    if (!r.camera && !defaultCamera.empty()) r.camera = assetDirectory() / "rows" / defaultCamera;
  }
  return r;
}

BaseCamera baseCamera(const Scene& scene, const std::optional<fs::path>& cameraFile, const std::string& cameraNode) {
  if (cameraFile) {
    if (!cameraNode.empty())
      throw InputError(cat("--camera-node ", cameraNode, ": --camera ", cameraFile->string(), " gives the camera already; give one or the other"));
    CameraFile file = loadCameraJson(*cameraFile);
    BaseCamera base;
    base.form = file.form == CameraFile::Form::Physical ? CameraForm::Physical
                : file.form == CameraFile::Form::Intrinsics ? CameraForm::Intrinsics
                                                            : CameraForm::Lecture;
    base.name = cameraFile->string();
    base.selected = {file.camera, file.physical};
    return base;
  }
  if (!cameraNode.empty()) return gltfBaseCamera(scene, findSceneCamera(scene, cameraNode));
  if (!scene.cameras.empty()) return gltfBaseCamera(scene, 0);
  return framingBaseCamera(scene);
}

SelectedCamera chooseCamera(const Scene& scene, const std::optional<fs::path>& cameraFile, const CameraOptions& options,
                            double imageAspect) {
  return composeCamera(baseCamera(scene, cameraFile, options.cameraNode), options, imageAspect);
}

}  // namespace lenslab
