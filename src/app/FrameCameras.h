#pragma once
// capture's options, and each frame's camera: from the path's keys, or the scene's own camera over
// its animation; the frame's physical description, lens effects and size, from which its camera
// file is written.
#include "app/AovOutputs.h"
#include "app/ExposureSettings.h"
#include "camera/CameraPath.h"
#include "camera/ImageSize.h"
#include "core/NumberInput.h"
#include "io/CameraList.h"
#include "io/EnvironmentFile.h"
#include "plan/CameraOptions.h"
#include "plan/UserOptions.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Frames per second of a sequence without a path (capture --fps, lenslab.Sequence's fps=).
inline constexpr NumberRange kFramesPerSecondRange{.min = 1e-3, .max = 1e4, .unit = "frames per second"};

struct CaptureOptions {
  std::string scene;
  std::string pathFile;
  std::string cameraFile;   // --camera FILE: a still camera in any form
  std::string camerasFile;  // --cameras FILE.jsonl: a camera a frame (io/CameraList.h)
  // A camera a frame given as objects (the Python package's cameras=[...]), named "cameras".
  std::optional<std::vector<ListedCamera>> cameraList;
  std::string out = "frames/frame_%04d.png";
  std::string manifest;  // default: manifest.jsonl beside the frames
  std::optional<int> width;
  std::optional<int> height;
  std::string backend = "osmesa";
  std::string frames;  // "A:B"; empty = all
  std::string shard = "0/1";
  bool skipExisting = false;
  AovRequest aovs;
  bool quiet = false;
  LensOptions lens;
  CameraOptions camera;
  std::optional<double> fps;  // frames per second without --path
  std::optional<glm::vec3> background;
  std::string colmapOut;              // --colmap-out DIR: the frames' cameras as a COLMAP model
  std::string colmapFormat = "text";  // --colmap-format: text (cameras.txt, ...) or binary (cameras.bin, ...)
  ExposureOptions exposure;           // PNG frames only; physical settings take each frame's f-number
  EnvironmentRequest environment;
};

// One frame's camera: its physical description and lens where its source has one (a physical
// path or camera file, a glTF camera, automatic framing), else the camera itself (a calibrated
// camera in the OpenCV form, a lecture-form view, a COLMAP image).
struct FrameCamera {
  std::optional<PathKey> physical;
  Camera view;  // without a physical description
};

// Where each frame's camera comes from: the path's keys (--path), a list of cameras (--cameras, or
// every image of --colmap DIR), or the scene's own camera — --camera FILE, a glTF camera
// following its node through the playing animation, or a still one (automatic framing,
// --eye/--target) — at --fps over the animation's duration.
class FrameCameras {
 public:
  // Throws InputError for options the path already gives (--eye, --target, --camera-node, --fps).
  FrameCameras(const CaptureOptions& o, Scene& scene, double imageAspect);

  // Frames in the path or list, or in the animation at --fps.
  int frameCount(const Scene& scene) const;
  double timeOf(int frame) const;
  std::string name() const;
  // A physical frame's near / far given by the camera (written into its file) rather than fitted
  // to the scene (any other frame's camera says so itself).
  bool nearGiven() const { return path_ ? !path_->nearFromScene : base_.form == CameraForm::GltfPerspective; }
  // Whether a frame's camera depends on the scene's pose (a glTF camera following its node).
  bool followsNode() const { return !path_ && !list_ && !still_ && !stillView_; }
  bool farGiven() const {
    return path_ ? !path_->farFromScene : base_.form == CameraForm::GltfPerspective && std::isfinite(base_.gltf.zfar);
  }

  // The frame's camera, the scene posed at `time` already; `where` names it in errors.
  FrameCamera at(const Scene& scene, int frame, double time, const std::string& where) const;

 private:
  // A still camera's physical description; throws InputError for one that has none (orthographic).
  PhysicalCamera physicalOf(const SelectedCamera& selected) const;

  const CaptureOptions& o_;
  double imageAspect_ = 0.0;
  std::optional<CameraPath> path_;
  std::optional<std::vector<ListedCamera>> list_;
  std::string listName_;
  Lens stillLens_;  // a still camera's aperture shape and barrel (the radius is its f/2N)
  double fps_ = 24.0;
  BaseCamera base_;
  std::optional<PhysicalCamera> still_;
  std::optional<Camera> stillView_;  // --camera in the lecture or OpenCV form
};

// The frame's camera (the scene posed at the frame's time already) and the frame's size: what the
// frame's camera file is written from (cheap: the lens is checked when the file is read back).
struct FrameKey {
  double timeSeconds = 0.0;
  std::optional<PathKey> key;  // the physical description, where the frame's camera has one
  Camera camera;               // as rendered, its lens effects and the lens options applied
  ImageSize size;
  std::string where;
};

FrameKey frameKey(const FrameCameras& cameras, const Scene& scene, const CaptureOptions& o, int frame);

// The flow AOV of `frame` (camera `now` at `size`, `scene` posed at the frame's time) to frame + 1
// of `frameCount` (camera/OpticalFlow.h): the scene is posed at the next frame's time for its
// nodes' motion and camera, then back. `surfaces` holds the frame's depth and instance AOVs.
std::vector<float> flowToNextFrame(const FrameCameras& cameras, Scene& scene, const CaptureOptions& o, int frame,
                                   int frameCount, const Camera& now, ImageSize size, const AovImages& surfaces);

}  // namespace lenslab
