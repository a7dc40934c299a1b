#pragma once
// capture --colmap-out: the COLMAP model of a capture's frames (cameras, images, points3D; text
// or binary, --colmap-format), written as it is made so that memory does not grow with the frame
// count.
#include "app/FrameCameras.h"
#include "io/AtomicFile.h"
#include "io/FrameSequence.h"
#include "io/Progress.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace lenslab {

// The cameras of every frame of `range` (its step included) as a COLMAP model in `dir`,
// written into temporary files of `outputs` (they appear at its commit(), before the first frame):
// whichever frames this shard renders, the model is the whole range's, a pure function of the
// frames' cameras (the path's keys, or the scene's camera over its animation), the range and the
// size options, so every shard writes the same bytes. One lens shares one CAMERA_ID (intrinsics
// within kColmapSameCameraTolerance, written as its first frame has them), among the first
// kColmapCamerasShared distinct ones and the previous frame's (past them each new one has its
// own). IMAGE_ID is the frame number + 1 (stable whatever the range). Throws InputError for a lens no
// COLMAP model holds; warns once for each effect a pinhole model leaves out. A glTF camera
// following its node poses `scene` at each frame's time. `progress` counts the frames; the
// warnings go to `warn` when given, else to `progress`.
void writeColmapModel(const CaptureOptions& o, const FrameCameras& frameCameras, Scene& scene, FrameRange range,
                      const std::filesystem::path& dir, OutputSet& outputs, ProgressReporter& progress,
                      const std::function<void(const std::string&)>& warn = {});

// Two frames' cameras are one lens (one CAMERA_ID) when their model and size are the same and each
// parameter is within this relative tolerance (of the larger magnitude, at least 1): frames of a
// path that keeps its lens differ in the 16th digit, computed from each frame's own view.
constexpr double kColmapSameCameraTolerance = 1e-9;

// How many distinct cameras the model remembers to share their CAMERA_ID: memory stays bounded
// for a path whose intrinsics change every frame (a zoom), which gets a camera a frame.
constexpr std::size_t kColmapCamerasShared = 4096;

}  // namespace lenslab
