#pragma once
// capture's options, and each frame's camera: from the path's keys, or the scene's own camera over
// its animation; the frame's physical description, lens effects and size, from which its camera
// file is written.
#include "app/ExposureOptions.h"
#include "camera/CameraPath.h"
#include "camera/ImageSize.h"
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

struct CaptureOptions {
  std::string scene;
  std::string pathFile;
  std::string out = "frames/frame_%04d.png";
  std::string manifest;  // default: manifest.jsonl beside the frames
  std::optional<int> width;
  std::optional<int> height;
  std::string backend = "osmesa";
  std::string frames;  // "A:B"; empty = all
  std::string shard = "0/1";
  bool skipExisting = false;
  std::vector<std::string> aovs;
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

// Where each frame's camera comes from: the path's keys, or (no --path) the scene's own camera —
// a glTF camera following its node through the playing animation, or a still one (automatic
// framing, --eye/--target) — at --fps over the animation's duration. Either way each frame's
// camera is a physical description, which is what the frame's camera file is written from.
class FrameCameras {
 public:
  // Throws InputError for options the path already gives (--eye, --target, --camera-node, --fps).
  FrameCameras(const CaptureOptions& o, Scene& scene, double imageAspect);

  // Frames in the path, or in the animation at --fps.
  int frameCount(const Scene& scene) const;
  double timeOf(int frame) const { return path_ ? path_->frameTimeSeconds(frame) : frame / fps_; }
  std::string name() const { return path_ ? o_.pathFile : base_.name; }
  // Near / far given by the camera (written into its file) rather than fitted to the scene.
  bool nearGiven() const { return path_ ? !path_->nearFromScene : base_.form == CameraForm::GltfPerspective; }
  // Whether a frame's camera depends on the scene's pose (a glTF camera following its node).
  bool followsNode() const { return !path_ && !still_; }
  bool farGiven() const {
    return path_ ? !path_->farFromScene : base_.form == CameraForm::GltfPerspective && std::isfinite(base_.gltf.zfar);
  }

  // The frame's camera, the scene posed at `time` already; `where` names it in errors.
  PathKey at(const Scene& scene, double time, const std::string& where) const;

 private:
  // A still camera's physical description; throws InputError for one that has none (orthographic).
  PhysicalCamera physicalOf(const SelectedCamera& selected) const;

  const CaptureOptions& o_;
  double imageAspect_ = 0.0;
  std::optional<CameraPath> path_;
  Lens stillLens_;  // a still camera's aperture shape and barrel (the radius is its f/2N)
  double fps_ = 24.0;
  BaseCamera base_;
  std::optional<PhysicalCamera> still_;
};

// The frame's camera (the scene posed at the frame's time already) and the frame's size: what the
// frame's camera file is written from (cheap: the lens is checked when the file is read back).
struct FrameKey {
  double timeSeconds = 0.0;
  PathKey key;
  Camera camera;  // the key's camera with its lens effects
  ImageSize size;
  std::string where;
};

FrameKey frameKey(const FrameCameras& cameras, const Scene& scene, const CaptureOptions& o, int frame);

}  // namespace lenslab
