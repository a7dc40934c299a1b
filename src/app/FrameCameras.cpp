#include "app/FrameCameras.h"

#include "camera/GltfCamera.h"
#include "camera/LensMap.h"
#include "camera/OpticalFlow.h"
#include "camera/ViewPath.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/CameraPathJson.h"
#include "plan/CameraSelection.h"
#include "scene/SceneAnimation.h"

#include <cmath>
#include <map>

namespace lenslab {
namespace {

// The option that names the frames' cameras (--path, --cameras, --colmap DIR), or empty.
std::string sequenceSource(const CaptureOptions& o) {
  if (!o.pathFile.empty()) return cat("--path ", o.pathFile);
  if (!o.camerasFile.empty()) return cat("--cameras ", o.camerasFile);
  if (o.cameraList) return "cameras";
  if (!o.camera.colmapDir.empty() && o.camera.colmapImage.empty()) return cat("--colmap ", o.camera.colmapDir);
  return "";
}

// A path or list gives every frame's camera: no option may name or move one camera for all.
void refuseStillOptions(const CaptureOptions& o, const std::string& source) {
  const auto refuse = [&](const std::string& option, const std::string& what) {
    throw InputError(cat(option, ": ", source, " gives ", what, "; give one or the other"));
  };
  if (!o.cameraFile.empty()) refuse(cat("--camera ", o.cameraFile), "each frame's camera");
  if (!o.pathFile.empty() && !o.camerasFile.empty()) refuse(cat("--cameras ", o.camerasFile), "each frame's camera");
  if (!o.camera.cameraNode.empty()) refuse(cat("--camera-node ", o.camera.cameraNode), "each frame's camera");
  if (o.pathFile.empty() && o.camera.changesPose())
    refuse(o.camera.eye ? "--eye" : "--target", "each frame's eye and target");
  if (o.pathFile.empty() && o.camera.changesLens())
    refuse(o.camera.describe(), "each frame's lens (as K, not a focal length in mm)");
  if ((!o.pathFile.empty() || !o.camerasFile.empty()) && (!o.camera.colmapDir.empty() || !o.camera.colmapImage.empty()))
    refuse(o.camera.colmapDir.empty() ? cat("--image ", o.camera.colmapImage) : cat("--colmap ", o.camera.colmapDir),
           "each frame's camera");
  if (o.fps && !o.pathFile.empty()) refuse(cat("--fps ", *o.fps), "its own fps (edit it there)");
}

}  // namespace

FrameCameras::FrameCameras(const CaptureOptions& o, Scene& scene, double imageAspect)
    : o_(o), imageAspect_(imageAspect) {
  fps_ = o.fps.value_or(24.0);
  if (const std::string source = sequenceSource(o); !source.empty()) {
    refuseStillOptions(o, source);
    if (!o.pathFile.empty()) {
      if (o.camera.changesPose())
        throw InputError(cat(o.camera.eye ? "--eye" : "--target", ": --path ", o.pathFile,
                             " gives each frame's eye and target; leave the option out, or edit the path's keys"));
      path_ = loadCameraPath(o.pathFile);
      if (path_->holdsViews() && o.camera.changesLens())
        throw InputError(cat(o.camera.describe(), ": --path ", o.pathFile,
                             "'s keys give K, not a focal length in mm or an f-number; edit the keys"));
      return;
    }
    listName_ = source;
    if (o.cameraList && o.cameraList->empty()) throw InputError("cameras: an empty list; give at least one camera");
    list_ = o.cameraList            ? *o.cameraList
            : o.camerasFile.empty() ? loadColmapCameras(o.camera.colmapDir, fps_)
                                    : loadCameraList(o.camerasFile, fps_);
    return;
  }
  // A still camera is chosen at the animation's start, whichever frames this process renders.
  if (!scene.animation.empty()) poseScene(scene, 0.0);
  const std::optional<std::filesystem::path> file =
      o.cameraFile.empty() ? std::nullopt : std::optional<std::filesystem::path>(o.cameraFile);
  base_ = baseCamera(scene, file, o.camera);
  if (base_.form != CameraForm::GltfPerspective) {
    const SelectedCamera still = composeCamera(base_, o.camera, imageAspect_);
    if (still.physical) {
      still_ = *still.physical;
      // Its aperture shape, barrel and lens effects go into every frame (the radius is its f/2N).
      stillLens_ = still.camera.lens;
    } else if (still.camera.view.projection == Projection::Perspective) {
      stillView_ = still.camera;
    } else {
      const std::string why =
          base_.form == CameraForm::GltfOrthographic ? cat(base_.name, " is orthographic") : still.camera.source;
      throw InputError(cat(why,
                           ": a parallel projection; capture writes each frame's camera as a perspective lens "
                           "(OpenCV intrinsics and a focus), which this camera is not: give --path, or a "
                           "perspective camera"));
    }
  }
}

int FrameCameras::frameCount(const Scene& scene) const {
  if (path_) return path_->frameCount();
  if (list_) return static_cast<int>(list_->size());
  return frameCountFor(animationDurationSeconds(scene), fps_, cat(name(), " over the animation at --fps ", fps_));
}

double FrameCameras::timeOf(int frame) const {
  if (path_) return path_->frameTimeSeconds(frame);
  if (list_) return (*list_)[static_cast<std::size_t>(frame)].timeSeconds;
  return frame / fps_;
}

std::string FrameCameras::name() const {
  if (path_) return o_.pathFile;
  if (list_) return listName_;
  return base_.name;
}

FrameCamera FrameCameras::at(const Scene& scene, int frame, double time, const std::string& where) const {
  if (path_ && path_->holdsViews()) return {std::nullopt, viewCameraAt(*path_, time, where)};
  if (path_) {
    PathKey key = cameraAt(*path_, time);
    validate(key.camera, where);
    if (o_.camera.changesLens()) key.camera = withCameraOptions(key.camera, o_.camera, where);  // the command line wins
    return {key, {}};
  }
  if (list_) {
    const ListedCamera& listed = (*list_)[static_cast<std::size_t>(frame)];
    if (listed.file.physical) return {PathKey{time, *listed.file.physical, listed.file.camera.lens}, {}};
    if (listed.file.camera.view.projection != Projection::Perspective)
      throw InputError(
          cat(listed.where, ": a parallel projection; capture writes each frame's camera as a perspective lens"));
    return {std::nullopt, listed.file.camera};
  }
  if (still_) return {PathKey{time, *still_, stillLens_}, {}};
  if (stillView_) return {std::nullopt, *stillView_};
  // A glTF camera where its node is at this time, its focus on the scene's centre then.
  const BaseCamera base = gltfBaseCamera(scene, base_.gltfIndex);
  return {PathKey{time, gltfPhysicalCamera(base, o_.camera, imageAspect_), {}}, {}};
}

FrameKey frameKey(const FrameCameras& cameras, const Scene& scene, const CaptureOptions& o, int frame) {
  FrameKey k;
  k.timeSeconds = cameras.timeOf(frame);
  k.where = cat(cameras.name(), ": frame ", frame, " (", k.timeSeconds, " s)");
  FrameCamera c = cameras.at(scene, frame, k.timeSeconds, k.where);
  if (!c.physical) {
    // --blades, --squeeze and the lens-effect options, as render applies them to a camera file's.
    c.view.source = k.where;
    k.camera = applyLensOptions(SelectedCamera{c.view, std::nullopt}, o.lens).camera;
    k.size = resolveImageSize(k.camera, o.width, o.height);
    return k;
  }
  PathKey& key = *c.physical;
  key.lens.aperture = withApertureOptions(key.lens.aperture, o.lens);  // --blades / --squeeze over every frame's
  const double focalLength = key.camera.focalLengthMm * kMetresPerMillimetre;
  key.lens.effects = withLensEffectOptions(key.lens.effects, o.lens, focalLength, k.where);
  if (!o.lens.changesLensEffects()) {
    k.camera = toCamera(key.camera, key.lens, k.where);
  } else {
    k.camera = toCamera(key.camera, key.lens, cat(k.where, " with ", describeLensEffectOptions(o.lens)));
    validateLensEffects(k.camera, k.camera.source, focalLength);
  }
  k.key = key;
  k.size = resolveImageSize(k.camera, o.width, o.height);
  return k;
}

std::vector<float> flowToNextFrame(const FrameCameras& cameras, Scene& scene, const CaptureOptions& o, int frame,
                                   int frameCount, const Camera& now, ImageSize size, const AovImages& surfaces) {
  const ThinLensMap nowMap(now, size);
  if (frame + 1 >= frameCount) return opticalFlow(nowMap, surfaces, nullptr, {});
  std::map<int, glm::dmat4> before;  // every instance of a node shares its transform
  for (const Instance& i : scene.instances)
    if (i.gltfNode >= 0) before[i.gltfNode] = i.worldFromModel;
  const bool moves = !scene.animation.empty();
  if (moves) poseScene(scene, cameras.timeOf(frame + 1));
  NodeMotion motion;
  if (moves)
    for (const Instance& i : scene.instances)
      if (i.gltfNode >= 0) motion[i.gltfNode] = i.worldFromModel * glm::inverse(before[i.gltfNode]);
  const FrameKey next = frameKey(cameras, scene, o, frame + 1);
  if (moves) poseScene(scene, cameras.timeOf(frame));
  const ThinLensMap nextMap(next.camera, next.size);
  return opticalFlow(nowMap, surfaces, &nextMap, motion);
}

}  // namespace lenslab
