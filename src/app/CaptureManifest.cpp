#include "app/CaptureManifest.h"

#include "camera/Intrinsics.h"
#include "core/Error.h"
#include "core/Text.h"
#include "io/AovChannels.h"
#include "io/Interrupt.h"
#include "io/JsonLines.h"

#include <cmath>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

nlohmann::json distanceJson(double d) { return std::isinf(d) ? nlohmann::json("infinity") : nlohmann::json(d); }

// K, distCoeffs, R and t of the frame's camera in OpenCV's conventions, for vision tools that read
// the manifest rather than the camera files (distCoeffs only where the lens is all OpenCV's; a
// fisheye's cv::fisheye D as "distortion": {"model": "fisheye", "k1" … "k4"}), with the image size,
// focus and aperture: a camera file `render --camera` reads (docs/camera-files.md).
nlohmann::json openCvJson(const Camera& camera, ImageSize size) {
  const OpenCvIntrinsics k = intrinsicsOf(camera.view, size);
  const OpenCvPose pose = poseOf(camera.view);
  nlohmann::json j;
  j["K"] = {{k.fx, 0.0, k.cx}, {0.0, k.fy, k.cy}, {0.0, 0.0, 1.0}};
  const Distortion& d = camera.lens.effects.distortion;
  if (d.isOpenCv()) j["dist"] = d.distCoeffs();
  if (d.fisheye) j["distortion"] = {{"model", "fisheye"}, {"k1", d.k1}, {"k2", d.k2}, {"k3", d.k3}, {"k4", d.k4}};
  j["R"] = nlohmann::json::array();
  for (const glm::dvec3& row : pose.rows) j["R"].push_back({row.x, row.y, row.z});
  j["t"] = {pose.translation.x, pose.translation.y, pose.translation.z};
  j["width"] = size.widthPx;
  j["height"] = size.heightPx;
  j["focus_distance"] = distanceJson(camera.focusDistance());
  if (camera.lens.apertureRadius > 0.0) j["aperture_radius"] = camera.lens.apertureRadius;
  return j;
}

}  // namespace

fs::path defaultManifest(const std::string& pattern) {
  const fs::path folder = fs::path(pattern).parent_path();
  if (folder.string().find('%') != std::string::npos)
    throw InputError(
        cat("--out ", pattern, ": the frame number is in the folder; give --manifest FILE for the manifest"));
  return folder / "manifest.jsonl";
}

std::string relativeTo(const fs::path& file, const fs::path& manifest) {
  const fs::path folder = manifest.parent_path().empty() ? fs::path(".") : manifest.parent_path();
  const fs::path rel =
      fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal());
  if (!rel.empty() && rel.begin()->string() != "..") return rel.string();
  return file.string();
}

std::set<std::string> manifestFiles(const fs::path& manifest) {
  std::set<std::string> files;
  for (const std::string& text : readCompleteLines(manifest)) {
    const nlohmann::json line = nlohmann::json::parse(text, nullptr, false);
    if (line.is_object() && line.contains("file") && line["file"].is_string())
      files.insert(line["file"].get<std::string>());
  }
  return files;
}

// A frame's files and its manifest line, together or not at all: the files are renamed into
// place, then the line appended. An interruption between the two removes the files (they are in
// io/Interrupt.h's list until the line is written); a failed line removes them here; a kill
// leaves files without a line, which --skip-existing renders again.
void commitFrame(OutputSet& outputs, const std::vector<fs::path>& files, const fs::path& manifest,
                 const std::string& line) {
  std::vector<std::uint64_t> handles;
  {
    const InterruptDeferral deferral;
    outputs.commit();
    for (const fs::path& f : files) handles.push_back(removeOnInterrupt(f, RemovalKind::File));
  }
  const InterruptDeferral deferral;
  try {
    appendLine(manifest, line);
  } catch (...) {
    std::error_code ignored;
    for (const fs::path& f : files) fs::remove(f, ignored);
    for (const std::uint64_t h : handles) forgetRemoveOnInterrupt(h);
    throw;
  }
  for (const std::uint64_t h : handles) forgetRemoveOnInterrupt(h);
}

nlohmann::json manifestLine(const ManifestFrame& f, const fs::path& manifest) {
  nlohmann::json line;
  line["frame"] = f.frame;
  line["time"] = f.timeSeconds;
  line["file"] = relativeTo(f.imageFile, manifest);
  line["camera"] = relativeTo(f.cameraFile, manifest);
  line["seed"] = f.seed;
  line["samples"] = f.samples;
  if (f.psnrEstimateDb) line["psnr_estimate_db"] = *f.psnrEstimateDb;
  line["seconds"] = f.seconds;
  line["width"] = f.size.widthPx;
  line["height"] = f.size.heightPx;
  if (f.lens) {
    line["focal_length_mm"] = f.lens->focalLengthMm;
    line["f_number"] = distanceJson(f.lens->fNumber);
  }
  line["focus_distance"] = distanceJson(f.lens ? f.lens->focusDistance : f.camera.focusDistance());
  if (f.aovs.selection.any()) {
    line["aov"] = f.aovs.selection.names();
    line["normal_convention"] = f.aovs.normals == NormalConvention::Gl ? "gl" : "opencv";
    const std::vector<fs::path> files = aovFilePaths(f.aovs, f.imageFile);
    if (f.aovs.format == AovFormat::Exr) {
      // Every channel of the EXR that holds them, in the order written: the frame's, after its
      // colour, or IMAGE.aov.exr's alone.
      nlohmann::json channels = files.empty() ? nlohmann::json{"R", "G", "B", "A"} : nlohmann::json::array();
      for (const std::string& c : aovChannelNames(f.aovs.selection)) channels.push_back(c);
      line["channels"] = channels;
    }
    if (!files.empty()) {
      nlohmann::json named = nlohmann::json::object();
      const std::vector<std::string> names = f.aovs.selection.names();
      for (std::size_t i = 0; i < files.size(); ++i)
        named[f.aovs.format == AovFormat::Exr ? std::string("exr") : names[i]] = relativeTo(files[i], manifest);
      line["aov_files"] = named;
    }
  }
  const Exposure& e = f.display.exposure;
  if (!f.display.encoding.isIdentity() || e.meterReading) {
    line["display"] = {{"exposure_stops", e.stops},
                       {"exposure", describe(e)},
                       {"exposure_source", e.source},
                       {"used_ev100", ev100ForScale(e.scale)},
                       {"view_transform", viewTransformName(f.display.encoding.transform)}};
    // The frame's own reading, whichever exposure the sequence holds (null: no light to meter).
    if (e.meterReading)
      line["display"]["metered_ev100"] =
          e.meterReading->ev100 ? nlohmann::json(*e.meterReading->ev100) : nlohmann::json();
  }
  if (f.environment)
    line["environment"] = {{"file", f.environment->file},
                           {"intensity", f.environment->intensity},
                           {"rotation_deg", f.environment->rotationDegrees}};
  line["opencv"] = openCvJson(f.camera, f.size);
  line["shard"] = cat(f.shard.index, "/", f.shard.count);
  return line;
}

}  // namespace lenslab
