#pragma once
// capture's manifest (manifest.jsonl): one JSON line a frame, appended when the frame's files are
// in place, naming them relative to the manifest's folder, with the frame's seed, samples, time,
// lens, display, environment and its camera in OpenCV's terms (docs/capture.md); and the frame's
// files and line committed together or not at all.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"
#include "core/Aovs.h"
#include "io/AovFiles.h"
#include "io/AtomicFile.h"
#include "io/EnvironmentFile.h"
#include "io/FrameSequence.h"
#include "io/ToneMap.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lenslab {

// The manifest's default place: beside the frames, when the pattern's folder has no frame number.
// Throws InputError naming --out when the folder holds the frame number.
std::filesystem::path defaultManifest(const std::string& pattern);

// A file named in the manifest relative to the manifest's folder when it lies there.
std::string relativeTo(const std::filesystem::path& file, const std::filesystem::path& manifest);

// The images named in the manifest's lines ("file", as relativeTo writes it). A line that is not
// a JSON object with a "file" names no frame: its frame is rendered again.
std::set<std::string> manifestFiles(const std::filesystem::path& manifest);

// What a frame's line says.
struct ManifestFrame {
  int frame = 0;
  double timeSeconds = 0.0;
  std::filesystem::path imageFile;
  std::filesystem::path cameraFile;
  std::uint32_t seed = 0;
  double samples = 0.0;                  // per pixel (the mean, with a target error)
  std::optional<double> psnrEstimateDb;  // with a target error
  double seconds = 0.0;
  ImageSize size;
  const PhysicalCamera* lens;  // the frame's physical description, where it has one
  const Camera& camera;        // as rendered
  const AovOutput& aovs;
  const DisplaySettings& display;
  const std::optional<EnvironmentSummary>& environment;
  Shard shard;
};
nlohmann::json manifestLine(const ManifestFrame& frame, const std::filesystem::path& manifest);

// A frame's files and its manifest line, together or not at all (see CaptureManifest.cpp).
void commitFrame(OutputSet& outputs, const std::vector<std::filesystem::path>& files,
                 const std::filesystem::path& manifest, const std::string& line);

}  // namespace lenslab
