#include "io/CameraList.h"

#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "io/ColmapModel.h"
#include "io/JsonDocument.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// A line's "time", through the number layer: seconds from the animation's start, as --time takes.
constexpr NumberRange kFrameTimeSeconds{.min = 0.0, .max = 1e9, .unit = "seconds"};
double frameTime(const nlohmann::json& line, const std::string& where) {
  return checkedNumber(cat(where, ": \"time\""), line["time"].get<double>(), kFrameTimeSeconds);
}

// A manifest line's frame: its camera file (relative to the manifest's folder) at its time.
ListedCamera manifestCamera(const nlohmann::json& line, const fs::path& list, const std::string& where) {
  if (!line["camera"].is_string())
    throw InputError(cat(where, ": \"camera\" must be the frame's camera file (a manifest line's), not ",
                         line["camera"].type_name()));
  const fs::path relative = line["camera"].get<std::string>();
  const fs::path file = relative.is_absolute() ? relative : list.parent_path() / relative;
  if (!fs::exists(file))
    throw InputError(cat(where, ": \"camera\": ", file.string(),
                         " is not there; a manifest is replayed from its frames' camera files, which stay beside "
                         "the frames"));
  ListedCamera c;
  c.file = loadCameraJson(file);
  c.where = cat(where, " (", file.string(), ")");
  if (!line.contains("time") || !line["time"].is_number())
    throw InputError(cat(where, ": \"time\": a manifest line gives its frame's time in seconds"));
  c.timeSeconds = frameTime(line, where);
  return c;
}

}  // namespace

std::vector<ListedCamera> loadCameraList(const fs::path& file, double fps) {
  const std::string text = readTextFile(file, "camera list (JSON lines)");
  std::istringstream in(text);
  std::string row;
  std::vector<ListedCamera> cameras;
  std::map<long long, ListedCamera> manifestFrames;  // by frame: a later line for a frame replaces an earlier
  int lineNumber = 0;
  while (std::getline(in, row)) {
    ++lineNumber;
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (row.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string where = cat(file.string(), ":", lineNumber);
    nlohmann::json line = parseJsonDocument(row, where);
    if (!line.is_object())
      throw InputError(cat(where, ": give a camera as a JSON object (a camera file's keys), not ", line.type_name()));
    if (line.contains("frame") && line.contains("camera")) {
      if (!line["frame"].is_number_integer() || line["frame"].get<long long>() < 0)
        throw InputError(cat(where, ": \"frame\" must be a frame number, 0 or more (a manifest line's)"));
      ListedCamera c = manifestCamera(line, file, where);
      manifestFrames[line["frame"].get<long long>()] = std::move(c);
      continue;
    }
    ListedCamera c;
    c.where = where;
    c.timeSeconds = static_cast<double>(cameras.size()) / fps;
    if (line.contains("time")) {
      if (!line["time"].is_number()) throw InputError(cat(where, ": \"time\": give a number of seconds"));
      c.timeSeconds = frameTime(line, where);
      line.erase("time");
    }
    c.file = parseCameraJson(line.dump(), where);
    cameras.push_back(std::move(c));
  }
  if (!manifestFrames.empty() && !cameras.empty())
    throw InputError(
        cat(file.string(), ": mixes a manifest's lines with camera lines; give a manifest, or a list of cameras"));
  for (auto& [frame, camera] : manifestFrames) cameras.push_back(std::move(camera));
  if (cameras.empty())
    throw InputError(cat(file.string(), ": holds no cameras; give one camera (a JSON object) a line"));
  return cameras;
}

std::vector<ListedCamera> loadColmapCameras(const fs::path& dir, double fps) {
  ColmapModel model = readColmapModel(dir);
  if (model.images.empty())
    throw InputError(cat("--colmap ", dir.string(), ": ", model.imagesFile, " holds no images to render"));
  std::sort(model.images.begin(), model.images.end(),
            [](const ColmapImage& a, const ColmapImage& b) { return a.id < b.id; });
  std::vector<ListedCamera> cameras;
  for (const ColmapImage& image : model.images) {
    ListedCamera c;
    c.timeSeconds = static_cast<double>(cameras.size()) / fps;
    c.file.form = CameraFile::Form::Intrinsics;
    c.file.camera = colmapImageCamera(model, image);
    c.where = c.file.camera.source;
    cameras.push_back(std::move(c));
  }
  return cameras;
}

}  // namespace lenslab
