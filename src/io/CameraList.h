#pragma once
// Camera lists: the cameras of a sequence given one by one rather than as a path, replayed frame
// by frame by `capture`. Frame N of the sequence is the list's N-th camera.
//   --cameras FILE.jsonl   a JSON-lines file, one camera a line, each line either
//                          - a camera file's object in any form (io/CameraJson.h), with an optional
//                            "time": seconds (default: the line's frame / fps), or
//                          - a line of a capture manifest (it has "frame" and "camera"): that frame's
//                            camera file, found relative to the manifest's folder, at the line's
//                            "time"; the lines are taken in frame order, and of two lines for one
//                            frame (a rerun) the later.
//                          Blank lines are skipped.
//   --colmap DIR           every image of a COLMAP model (io/ColmapModel.h), in IMAGE_ID order, at
//                          frame / fps.
#include "io/CameraJson.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

struct ListedCamera {
  double timeSeconds = 0.0;
  CameraFile file;    // the camera, and its physical description where it has one
  std::string where;  // "cams.jsonl:3", or the COLMAP image
};

// Throws InputError naming the file and line: a line that is not a JSON object, a bad camera, a
// "time" that is not a finite number ≥ 0, a manifest line whose camera file cannot be read, or a
// list with no cameras.
std::vector<ListedCamera> loadCameraList(const std::filesystem::path& file, double fps);

// Every image of the COLMAP model in `dir`, by IMAGE_ID.
std::vector<ListedCamera> loadColmapCameras(const std::filesystem::path& dir, double fps);

}  // namespace lenslab
