#include "plan/CameraSelection.h"

#include "core/DataPaths.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraJson.h"
#include "io/ColmapModel.h"

#include <cstdlib>

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
    if (!r.camera && !defaultCamera.empty()) r.camera = assets / "rows" / defaultCamera;
  }
  return r;
}

namespace {

// --colmap DIR --image NAME: that photograph's camera, a pinhole in the OpenCV-intrinsics form.
BaseCamera colmapBaseCamera(const CameraOptions& options) {
  if (options.colmapImage.empty())
    throw InputError(
        cat("--colmap ", options.colmapDir, ": give --image NAME too, the photograph whose view to render"));
  if (options.colmapDir.empty())
    throw InputError(
        cat("--image ", options.colmapImage, ": give --colmap DIR too, the COLMAP model the image belongs to"));
  BaseCamera base;
  base.form = CameraForm::Intrinsics;
  base.name = cat("COLMAP image ", options.colmapImage, " (", options.colmapDir, ")");
  base.selected = {colmapImageCamera(readColmapModel(options.colmapDir), options.colmapImage), std::nullopt};
  return base;
}

}  // namespace

BaseCamera baseCamera(const Scene& scene, const std::optional<fs::path>& cameraFile, const CameraOptions& options) {
  const bool colmap = !options.colmapDir.empty() || !options.colmapImage.empty();
  const std::string colmapOption =
      !options.colmapDir.empty() ? cat("--colmap ", options.colmapDir) : cat("--image ", options.colmapImage);
  if (cameraFile && colmap)
    throw InputError(cat(colmapOption, " and --camera ", cameraFile->string(), " both give the camera; give one"));
  if (colmap && !options.cameraNode.empty())
    throw InputError(cat("--camera-node ", options.cameraNode, ": ", colmapOption,
                         " gives the camera already; give one or the other"));
  if (cameraFile) {
    if (!options.cameraNode.empty())
      throw InputError(cat("--camera-node ", options.cameraNode, ": --camera ", cameraFile->string(),
                           " gives the camera already; give one or the other"));
    CameraFile file = loadCameraJson(*cameraFile);
    BaseCamera base;
    base.form = file.form == CameraFile::Form::Physical     ? CameraForm::Physical
                : file.form == CameraFile::Form::Intrinsics ? CameraForm::Intrinsics
                                                            : CameraForm::Lecture;
    base.name = cameraFile->string();
    base.selected = {file.camera, file.physical};
    return base;
  }
  if (colmap) return colmapBaseCamera(options);
  if (!options.cameraNode.empty()) return gltfBaseCamera(scene, findSceneCamera(scene, options.cameraNode));
  if (!scene.cameras.empty()) return gltfBaseCamera(scene, 0);
  return framingBaseCamera(scene);
}

SelectedCamera chooseCamera(const Scene& scene, const std::optional<fs::path>& cameraFile, const CameraOptions& options,
                            double imageAspect) {
  return composeCamera(baseCamera(scene, cameraFile, options), options, imageAspect);
}

}  // namespace lenslab
