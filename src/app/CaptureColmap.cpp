#include "app/CaptureColmap.h"

#include "camera/Intrinsics.h"
#include "core/Text.h"
#include "io/ColmapBinary.h"
#include "io/ColmapExport.h"
#include "scene/SceneAnimation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <unordered_map>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// The folder COLMAP's NAMEs are relative to: --out's leading folders up to the first that holds
// the frame number (give it to COLMAP as --image_path).
fs::path framesFolder(const std::string& pattern) {
  fs::path folder;
  for (const fs::path& part : fs::path(pattern).parent_path()) {
    if (part.string().find('%') != std::string::npos) break;
    folder /= part;
  }
  return folder;
}

// What a pinhole model cannot hold. Blur (depth of field, axial colour, field curvature) is
// centred where the pinhole at the lens centre projects, so the geometry stays right.
void noteLeftOut(const Camera& camera, std::set<std::string>& warnings) {
  const LensEffects& e = camera.lens.effects;
  if (!camera.lens.isPinhole())
    warnings.insert(
        "the depth of field (aperture and focus) is not in the model: COLMAP's cameras are pinholes "
        "(each blur is centred where the model projects)");
  if (e.chromatic.hasAxial())
    warnings.insert("the axial colour is not in the model (it blurs, centred where the model projects)");
  if (!e.fieldCurvature.isZero())
    warnings.insert("the field curvature is not in the model (it blurs, centred where the model projects)");
  if (e.chromatic.hasLateral())
    warnings.insert(
        "the lateral colour is not in the model: it holds green's geometry, while red's and blue's "
        "images are magnified about the principal point");
}

// Whether two cameras are one lens: the same model and size, and parameters within a relative
// kColmapSameCameraTolerance (a path that keeps its lens computes fx in each frame from that
// frame's view, and the 16th digit differs).
bool sameLens(const ColmapCamera& a, const ColmapCamera& b) {
  if (a.model != b.model || a.widthPx != b.widthPx || a.heightPx != b.heightPx || a.params.size() != b.params.size())
    return false;
  for (std::size_t i = 0; i < a.params.size(); ++i)
    if (!(std::abs(a.params[i] - b.params[i]) <=
          kColmapSameCameraTolerance * std::max({1.0, std::abs(a.params[i]), std::abs(b.params[i])})))
      return false;
  return true;
}

// The key of a camera's intrinsics among those remembered: its parameters to 12 significant digits,
// so that cameras within the tolerance share it (but for one straddling a rounding step, which
// then gets an id of its own).
std::string lensKey(const ColmapCamera& c) {
  std::string key = cat(c.model, " ", c.widthPx, " ", c.heightPx);
  char digits[32];
  for (const double p : c.params) {
    std::snprintf(digits, sizeof digits, " %.12g", p == 0.0 ? 0.0 : p);
    key += digits;
  }
  return key;
}

}  // namespace

void writeColmapModel(const CaptureOptions& o, const FrameCameras& frameCameras, Scene& scene, FrameRange range,
                      const fs::path& dir, OutputSet& outputs, ProgressReporter& progress,
                      const std::function<void(const std::string&)>& warn) {
  const fs::path base = framesFolder(o.out);
  const fs::path baseFolder = fs::absolute(base.empty() ? fs::path(".") : base).lexically_normal();
  const bool binary = o.colmapFormat == "binary";
  const std::string extension = binary ? ".bin" : ".txt";
  StreamedFile cameras(outputs, dir / ("cameras" + extension)), images(outputs, dir / ("images" + extension));
  const std::int64_t frameCount = (static_cast<std::int64_t>(range.last) - range.first) / range.step + 1;
  // cameras.bin's count leads the file: written as 0 here and set once the cameras are known.
  cameras.write(binary ? colmapCountField(0) : colmapCamerasHeader());
  images.write(binary ? colmapCountField(static_cast<std::uint64_t>(frameCount))
                      : colmapImagesHeader(static_cast<std::size_t>(frameCount)));
  std::unordered_map<std::string, ColmapCamera> shared;  // at most kColmapCamerasShared, by lensKey
  std::uint32_t cameraCount = 0;
  ColmapCamera last;  // the previous frame's (id 0 before the first)
  std::set<std::string> warnings;
  const std::string imageWhere = cat("--colmap-out: --out ", o.out);  // the frames' names come from --out
  std::int64_t done = 0;
  for (std::int64_t frame64 = range.first; frame64 <= range.last; frame64 += range.step) {
    const int frame = static_cast<int>(frame64);
    // The camera file's K exactly (toIntrinsicsCameraJson computes it so), without reading the
    // file back: that checks the lens for folds, ~30 ms a frame, which the frame's own render does.
    if (frameCameras.followsNode() && !scene.animation.empty()) poseScene(scene, frameCameras.timeOf(frame));
    const FrameKey f = frameKey(frameCameras, scene, o, frame);
    const std::string where = cat("--colmap-out: ", frameCameras.name(), ": frame ", frame);
    ColmapCamera camera =
        colmapCameraOf(intrinsicsOf(f.camera.view, f.size), f.camera.lens.effects.distortion, 0, where);
    // The previous frame's camera first: a path holding its intrinsics shares one however many
    // distinct cameras came before.
    if (last.id == 0 || !sameLens(camera, last)) {
      const std::string key = lensKey(camera);
      if (const auto it = shared.find(key); it != shared.end()) {
        last = it->second;
      } else {
        camera.id = ++cameraCount;
        last = camera;
        if (shared.size() < kColmapCamerasShared) shared.emplace(key, camera);
        cameras.write(binary ? colmapCameraRecord(camera) : colmapCameraLine(camera));
      }
    }
    const std::uint32_t cameraId = last.id;
    const fs::path file = formatFramePath(o.out, frame);
    const std::string name = fs::absolute(file).lexically_normal().lexically_relative(baseFolder).generic_string();
    const ColmapImage image =
        colmapImageOf(poseOf(f.camera.view), static_cast<std::uint32_t>(frame) + 1, cameraId, name, imageWhere);
    images.write(binary ? colmapImageRecord(image) : colmapImageLines(image));
    noteLeftOut(f.camera, warnings);
    if (++done % 1024 == 0) progress.update(done, frameCount);
  }
  if (binary)
    cameras.overwrite(0, colmapCountField(cameraCount));
  else
    cameras.write(colmapCamerasFooter(cameraCount));
  cameras.close();
  images.close();
  outputs.add(dir / ("points3D" + extension), binary ? colmapPoints3DBinary() : colmapPoints3DText());
  progress.finish();
  if (!o.quiet)
    for (const std::string& w : warnings) {
      const std::string line = "lenslab: warning: --colmap-out: " + w;
      if (warn)
        warn(line);
      else
        progress.note(line);
    }
}

}  // namespace lenslab
