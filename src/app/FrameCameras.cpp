#include "app/FrameCameras.h"

#include "camera/GltfCamera.h"
#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraPathJson.h"
#include "plan/CameraSelection.h"
#include "scene/SceneAnimation.h"

#include <cmath>

namespace lenslab {

FrameCameras::FrameCameras(const CaptureOptions& o, Scene& scene, double imageAspect)
    : o_(o), imageAspect_(imageAspect) {
  if (!o.pathFile.empty()) {
    if (o.camera.changesPose())
      throw InputError(cat(o.camera.eye ? "--eye" : "--target", ": --path ", o.pathFile,
                           " gives each frame's eye and target; leave the option out, or edit the path's keys"));
    if (!o.camera.cameraNode.empty())
      throw InputError(cat("--camera-node ", o.camera.cameraNode, ": --path ", o.pathFile,
                           " gives each frame's camera; give one or the other"));
    if (o.fps) throw InputError(cat("--fps ", *o.fps, ": --path ", o.pathFile, " gives its own fps; edit it there"));
    path_ = loadCameraPath(o.pathFile);
    return;
  }
  fps_ = o.fps.value_or(24.0);
  // A still camera is chosen at the animation's start, whichever frames this process renders.
  if (!scene.animation.empty()) poseScene(scene, 0.0);
  base_ = baseCamera(scene, std::nullopt, o.camera);
  if (base_.form != CameraForm::GltfPerspective) {
    const SelectedCamera still = composeCamera(base_, o.camera, imageAspect_);
    still_ = physicalOf(still);
    // Its aperture shape and barrel go into every frame; its lens effects do not.
    stillLens_ = still.camera.lens;
    stillLens_.effects = {};
  }
}

int FrameCameras::frameCount(const Scene& scene) const {
  if (path_) return path_->frameCount();
  return frameCountFor(animationDurationSeconds(scene), fps_, cat(base_.name, " over the animation at --fps ", fps_));
}

PathKey FrameCameras::at(const Scene& scene, double time, const std::string& where) const {
  if (path_) {
    PathKey key = cameraAt(*path_, time);
    validate(key.camera, where);
    if (o_.camera.changesLens()) key.camera = withCameraOptions(key.camera, o_.camera, where);  // the command line wins
    return key;
  }
  if (still_) return {time, *still_, stillLens_};
  // A glTF camera where its node is at this time, its focus on the scene's centre then.
  const BaseCamera base = gltfBaseCamera(scene, base_.gltfIndex);
  return {time, gltfPhysicalCamera(base, o_.camera, imageAspect_), {}};
}

PhysicalCamera FrameCameras::physicalOf(const SelectedCamera& selected) const {
  if (selected.physical) return *selected.physical;
  const std::string why =
      base_.form == CameraForm::GltfOrthographic ? cat(base_.name, " is orthographic") : selected.camera.source;
  throw InputError(
      cat(why,
          "; capture writes each frame's camera as a perspective lens (OpenCV intrinsics and a focus), which "
          "this camera is not: give --path, or a perspective camera"));
}

FrameKey frameKey(const FrameCameras& cameras, const Scene& scene, const CaptureOptions& o, int frame) {
  FrameKey k;
  k.timeSeconds = cameras.timeOf(frame);
  k.where = cat(cameras.name(), ": frame ", frame, " (", k.timeSeconds, " s)");
  k.key = cameras.at(scene, k.timeSeconds, k.where);
  k.key.lens.aperture = withApertureOptions(k.key.lens.aperture, o.lens);  // --blades / --squeeze over every frame's
  const double focalLength = k.key.camera.focalLengthMm * kMetresPerMillimetre;
  k.key.lens.effects = withLensEffectOptions(k.key.lens.effects, o.lens, focalLength, k.where);
  if (!o.lens.changesLensEffects()) {
    k.camera = toCamera(k.key.camera, k.key.lens, k.where);
  } else {
    k.camera = toCamera(k.key.camera, k.key.lens, cat(k.where, " with ", describeLensEffectOptions(o.lens)));
    validateLensEffects(k.camera, k.camera.source, focalLength);
  }
  k.size = resolveImageSize(k.camera, o.width, o.height);
  return k;
}

}  // namespace lenslab
