#include "io/ColmapModel.h"

#include "camera/ImageSize.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/ParseNumber.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "io/ColmapBinary.h"
#include "lens/effects/Distortion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string_view>

namespace lenslab {
namespace fs = std::filesystem;

const char* const kColmapModelsRendered =
    "SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV, OPENCV_FISHEYE, SIMPLE_RADIAL_FISHEYE and "
    "RADIAL_FISHEYE";

namespace {

// The models lenslab renders and their parameters, in COLMAP's order (src/colmap/sensor/models.h):
// one focal length f or two (fx, fy), the principal point cx, cy, then the distortion coefficients,
// each model's a leading part of OpenCV's k1, k2, p1, p2, k3, k4, k5, k6.
struct ModelInfo {
  const char* name;
  const char* params;
  std::size_t count;
  bool oneFocal;
  bool fisheye = false;  // the params after cx, cy are the fisheye's k1, k2, ... (on θ, Distortion.h)

  std::size_t cxIndex() const { return oneFocal ? 1 : 2; }
  std::size_t k1Index() const { return cxIndex() + 2; }  // = count for the pinholes, which have no k1
};
constexpr ModelInfo kModels[] = {
    {"SIMPLE_PINHOLE", "f, cx, cy", 3, true},
    {"PINHOLE", "fx, fy, cx, cy", 4, false},
    {"SIMPLE_RADIAL", "f, cx, cy, k", 4, true},
    {"RADIAL", "f, cx, cy, k1, k2", 5, true},
    {"OPENCV", "fx, fy, cx, cy, k1, k2, p1, p2", 8, false},
    {"FULL_OPENCV", "fx, fy, cx, cy, k1, k2, p1, p2, k3, k4, k5, k6", 12, false},
    {"OPENCV_FISHEYE", "fx, fy, cx, cy, k1, k2, k3, k4", 8, false, true},
    {"SIMPLE_RADIAL_FISHEYE", "f, cx, cy, k", 4, true, true},
    {"RADIAL_FISHEYE", "f, cx, cy, k1, k2", 5, true, true},
};

const ModelInfo* modelInfo(const std::string& name) {
  for (const ModelInfo& m : kModels)
    if (name == m.name) return &m;
  return nullptr;
}

// One line of a text file or one record of a binary one, for messages: "sparse/images.txt:12",
// "sparse/cameras.bin: camera record 3".
struct Where {
  const std::string& file;
  int line;
  int record = 0;  // binary files: the record, from 1 (line is 0)
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(line > 0 ? cat(file, ":", line, ": ", message)
                              : cat(file, ": ", record > 0 ? cat("record ", record, ": ") : std::string(), message));
  }
};

std::string_view trimmed(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    out.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return out;
}

// Fields are separated by runs of spaces or tabs (COLMAP writes single spaces; a run is forgiven).
// The first field of `rest`, removed from it with the separators before it; empty when none is left.
std::string_view takeField(std::string_view& rest) {
  const std::size_t start = std::min(rest.find_first_not_of(" \t"), rest.size());
  rest.remove_prefix(start);
  const std::size_t length = std::min(rest.find_first_of(" \t"), rest.size());
  const std::string_view field = rest.substr(0, length);
  rest.remove_prefix(length);
  return field;
}

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::string_view field = takeField(line); !field.empty(); field = takeField(line)) out.push_back(field);
  return out;
}

// How many fields a line holds, without keeping them (a POINTS2D line may hold thousands).
std::size_t fieldCount(std::string_view line) {
  std::size_t n = 0;
  while (!takeField(line).empty()) ++n;
  return n;
}

// core/NumberInput's rule (a leading '+' allowed, as COLMAP's stold allows it); the message quotes
// at most 60 characters of the field.
double number(std::string_view field, const Where& where, const std::string& what) {
  if (const auto problem = numberTextProblem(field, NumberRange{})) where.fail(cat(what, ": ", *problem));
  return *parseDouble(!field.empty() && field.front() == '+' ? field.substr(1) : field);
}

std::uint64_t whole(std::string_view field, const Where& where, const std::string& what, std::uint64_t max) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size() || value > max)
    where.fail(cat(what, " is \"", excerpt(field), "\"; give a whole number from 0 to ", max));
  return value;
}

constexpr std::uint64_t kMaxId = std::numeric_limits<std::uint32_t>::max() - 1;  // COLMAP's max is "invalid"

// A COLMAP text file read line by line. next() gives the next data line: blank lines and '#'
// comments are skipped. following() gives the line right after the last one given, whatever it
// holds: an image's POINTS2D line, which may be empty.
class DataLines {
 public:
  struct Line {
    Where where;
    std::string_view text;  // without white space at either end
  };

  DataLines(std::string_view text, const std::string& file) : lines_(splitLines(text)), file_(file) {}

  std::optional<Line> next() {
    while (std::optional<Line> line = following())
      if (!line->text.empty() && line->text.front() != '#') return line;
    return std::nullopt;
  }

  std::optional<Line> following() {
    if (next_ == lines_.size()) return std::nullopt;
    const std::size_t i = next_++;
    return Line{Where{file_, static_cast<int>(i) + 1}, trimmed(lines_[i])};
  }

 private:
  std::vector<std::string_view> lines_;
  const std::string& file_;
  std::size_t next_ = 0;
};

// The line on which each ID (or name) was first given, to refuse one given again:
// "CAMERA_ID 3 is given again (first on line 1); each camera needs its own ID".
template <class Key>
class FirstLines {
 public:
  FirstLines(const char* field, const char* rule) : field_(field), rule_(rule) {}

  void add(const Key& key, const Where& where) {
    if (const auto [it, added] = lineOf_.emplace(key, where.line); !added)
      where.fail(cat(field_, " ", key, " is given again (first on line ", it->second, "); ", rule_));
  }

 private:
  const char* field_;
  const char* rule_;
  std::map<Key, int> lineOf_;
};

[[noreturn]] void failUnknownCamera(const ColmapModel& model, const ColmapImage& image) {
  const std::string at = image.line > 0 ? cat(":", image.line, ":") : cat(": record ", image.record, ":");
  throw InputError(cat(model.imagesFile, at, " image ", image.id, " (", image.name, ") names CAMERA_ID ",
                       image.cameraId, ", which ", model.camerasFile, " does not hold"));
}

// The camera that took `image`. Throws InputError naming the image's line when the model holds none.
const ColmapCamera& cameraOf(const ColmapModel& model, const ColmapImage& image) {
  const auto camera = std::find_if(model.cameras.begin(), model.cameras.end(),
                                   [&](const ColmapCamera& c) { return c.id == image.cameraId; });
  if (camera == model.cameras.end()) failUnknownCamera(model, image);
  return *camera;
}

}  // namespace

std::vector<ColmapCamera> parseColmapCameras(const std::string& text, const std::string& file) {
  std::vector<ColmapCamera> cameras;
  FirstLines<std::uint32_t> ids("CAMERA_ID", "each camera needs its own ID");
  DataLines lines(text, file);
  while (const std::optional<DataLines::Line> line = lines.next()) {
    const Where& where = line->where;
    const std::vector<std::string_view> f = fields(line->text);
    if (f.size() < 4)
      where.fail(cat("a camera line is CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]; this one has ", f.size(), " field",
                     f.size() == 1 ? "" : "s"));
    ColmapCamera c;
    c.line = where.line;
    c.id = static_cast<std::uint32_t>(whole(f[0], where, "CAMERA_ID", kMaxId));
    c.model = std::string(f[1]);
    const std::uint64_t width = whole(f[2], where, "WIDTH", std::numeric_limits<int>::max());
    const std::uint64_t height = whole(f[3], where, "HEIGHT", std::numeric_limits<int>::max());
    if (width < 1 || height < 1)
      where.fail(cat("camera ", c.id, " is ", width, "x", height, " pixels; give a size of at least 1x1"));
    c.widthPx = static_cast<int>(width);
    c.heightPx = static_cast<int>(height);
    for (std::size_t p = 4; p < f.size(); ++p) c.params.push_back(number(f[p], where, cat("parameter ", p - 3)));
    if (const ModelInfo* m = modelInfo(c.model); m && c.params.size() != m->count)
      where.fail(cat("camera ", c.id, " is ", m->name, ", which takes ", m->count, " parameters (", m->params,
                     "), not ", c.params.size()));
    ids.add(c.id, where);
    cameras.push_back(std::move(c));
  }
  return cameras;
}

std::vector<ColmapImage> parseColmapImages(const std::string& text, const std::string& file) {
  std::vector<ColmapImage> images;
  FirstLines<std::uint32_t> ids("IMAGE_ID", "each image needs its own ID");
  FirstLines<std::string> names("NAME", "each image needs its own name");
  DataLines lines(text, file);
  while (const std::optional<DataLines::Line> line = lines.next()) {
    const Where& where = line->where;
    const std::vector<std::string_view> f = fields(line->text);
    if (f.size() != 10)
      where.fail(cat("an image line is IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (10 fields); this one has ",
                     f.size(),
                     f.size() > 10 ? " (a NAME cannot hold spaces: COLMAP reads it only up to the first)" : ""));
    ColmapImage image;
    image.line = where.line;
    image.id = static_cast<std::uint32_t>(whole(f[0], where, "IMAGE_ID", kMaxId));
    const glm::dquat q(number(f[1], where, "QW"), number(f[2], where, "QX"), number(f[3], where, "QY"),
                       number(f[4], where, "QZ"));
    const double length = glm::length(q);
    if (!(std::abs(length - 1.0) <= kQuaternionLengthTolerance))
      where.fail(cat("image ", image.id, "'s quaternion QW QX QY QZ has length ", length,
                     "; COLMAP writes unit quaternions "
                     "(lengths within ",
                     kQuaternionLengthTolerance, " of 1 are normalised)"));
    image.rotation = q / length;
    image.translation = {number(f[5], where, "TX"), number(f[6], where, "TY"), number(f[7], where, "TZ")};
    image.cameraId = static_cast<std::uint32_t>(whole(f[8], where, "CAMERA_ID", kMaxId));
    image.name = std::string(f[9]);
    ids.add(image.id, where);
    names.add(image.name, where);
    // Its POINTS2D line: the next line, whatever it holds (it may be empty). Lenslab does not use
    // the points, but a line that cannot be one means the two-line layout is broken.
    if (const std::optional<DataLines::Line> points = lines.following()) {
      if (!points->text.empty() && points->text.front() == '#')
        points->where.fail(cat("image ", image.id,
                               "'s POINTS2D line (X Y POINT3D_ID triples, or empty) is a comment; each "
                               "image takes two lines"));
      if (const std::size_t n = fieldCount(points->text); n % 3 != 0)
        points->where.fail(cat("image ", image.id, "'s POINTS2D line holds ", n,
                               " fields, not X Y POINT3D_ID triples; each "
                               "image takes two lines (the second may be empty)"));
    }
    images.push_back(std::move(image));
  }
  return images;
}

ColmapModel readColmapModel(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw InputError(
        cat("--colmap ", dir.string(),
            ": not a folder; give the folder of a COLMAP model (cameras.txt and images.txt, or cameras.bin "
            "and images.bin)"));
  ColmapModel model;
  // As COLMAP reads a model: the binary files where both are there, else the text files.
  const bool binary = fs::exists(dir / "cameras.bin", error) && fs::exists(dir / "images.bin", error);
  model.camerasFile = (dir / (binary ? "cameras.bin" : "cameras.txt")).string();
  model.imagesFile = (dir / (binary ? "images.bin" : "images.txt")).string();
  if (binary) {
    model.cameras = parseColmapCamerasBinary(
        readInputFile(model.camerasFile, "COLMAP cameras file", kMaxColmapBinaryBytes), model.camerasFile);
    model.images = parseColmapImagesBinary(readInputFile(model.imagesFile, "COLMAP images file", kMaxColmapBinaryBytes),
                                           model.imagesFile);
  } else {
    model.cameras = parseColmapCameras(readTextFile(model.camerasFile, "COLMAP cameras file"), model.camerasFile);
    model.images = parseColmapImages(readTextFile(model.imagesFile, "COLMAP images file"), model.imagesFile);
  }
  // Every image's camera, looked up in a set rather than by cameraOf: COLMAP makes a camera per
  // image by default, and a search of the cameras for each image would take their product.
  std::set<std::uint32_t> ids;
  for (const ColmapCamera& c : model.cameras) ids.insert(c.id);
  for (const ColmapImage& image : model.images)
    if (ids.count(image.cameraId) == 0) failUnknownCamera(model, image);
  return model;
}

constexpr double kMaxPrincipalPointSides = 100.0;

OpenCvLens lensOf(const ColmapCamera& c, const std::string& file) {
  const Where where{file, c.line, c.record};
  const ModelInfo* m = modelInfo(c.model);
  if (!m)
    where.fail(
        cat("camera ", c.id, " is ", c.model, ", a model lenslab does not render; it renders ", kColmapModelsRendered));
  if (c.widthPx > kMaxImageSidePx || c.heightPx > kMaxImageSidePx)
    where.fail(cat("camera ", c.id, " is ", c.widthPx, "x", c.heightPx, " pixels; lenslab renders at most ",
                   kMaxImageSidePx, " a side"));
  const std::vector<double>& p = c.params;
  OpenCvLens lens;
  OpenCvIntrinsics& k = lens.intrinsics;
  Distortion& d = lens.distortion;
  k.fx = p[0];
  k.fy = m->oneFocal ? p[0] : p[1];
  // COLMAP's pixel centres are at i + 0.5, OpenCV's at i.
  k.cx = p[m->cxIndex()] - 0.5;
  k.cy = p[m->cxIndex() + 1] - 0.5;
  k.widthPx = c.widthPx;
  k.heightPx = c.heightPx;
  // OpenCV's order: k1, k2, p1, p2, k3, k4, k5, k6; the fisheyes': k1, k2, k3, k4.
  constexpr double Distortion::*kFisheyeTerms[] = {&Distortion::k1, &Distortion::k2, &Distortion::k3, &Distortion::k4};
  d.fisheye = m->fisheye;
  for (std::size_t i = 0; m->k1Index() + i < m->count; ++i)
    d.*(m->fisheye ? kFisheyeTerms[i] : kDistortionTerms[i].value) = p[m->k1Index() + i];
  if (!(k.fx > 0.0) || !(k.fy > 0.0))
    where.fail(cat("camera ", c.id, " has focal length ", k.fx > 0.0 ? k.fy : k.fx, "; give it in pixels, > 0 (",
                   m->name, " takes ", m->params, ")"));
  // The principal point within 100 image sides of the image: a real camera's is near its centre,
  // and one 1e30 pixels out leaves no window a double can hold.
  const double side = std::max(c.widthPx, c.heightPx), reach = kMaxPrincipalPointSides * side;
  const std::pair<const char*, double> centre[] = {{"cx", k.cx + 0.5}, {"cy", k.cy + 0.5}};
  for (const auto& [name, value] : centre) {
    const double middle = 0.5 * (name[1] == 'x' ? c.widthPx : c.heightPx);
    if (!(std::abs(value - middle) <= reach))
      where.fail(cat("camera ", c.id, " has ", name, " ", value, "; give the principal point in pixels, within ",
                     kMaxPrincipalPointSides, " image sides of the image's centre (", middle - reach, " to ",
                     middle + reach, ")"));
  }
  return lens;
}

OpenCvPose poseOf(const ColmapImage& image) {
  OpenCvPose pose;
  pose.rows = rotationFromQuaternion(image.rotation);
  pose.translation = image.translation;
  return pose;
}

Camera colmapImageCamera(const ColmapModel& model, const std::string& name) {
  const auto image =
      std::find_if(model.images.begin(), model.images.end(), [&](const ColmapImage& i) { return i.name == name; });
  if (image == model.images.end()) {
    if (model.images.empty()) throw InputError(cat("--image ", name, ": ", model.imagesFile, " holds no images"));
    // The one image whose file name matches, when the request left out its folder.
    std::vector<std::string> sameFile;
    for (const ColmapImage& i : model.images)
      if (fs::path(i.name).filename() == fs::path(name).filename()) sameFile.push_back(i.name);
    if (sameFile.size() == 1)
      throw InputError(
          cat("--image ", name, ": ", model.imagesFile, " has no image named so; did you mean ", sameFile[0], "?"));
    std::string some;
    const std::size_t shown = std::min<std::size_t>(model.images.size(), 5);
    for (std::size_t i = 0; i < shown; ++i) some += (i ? ", " : "") + model.images[i].name;
    throw InputError(cat("--image ", name, ": ", model.imagesFile, " has no image named so; its ", model.images.size(),
                         " image", model.images.size() == 1 ? "" : "s", " include",
                         model.images.size() == 1 ? "s " : " ", some, model.images.size() > shown ? ", ..." : ""));
  }
  return colmapImageCamera(model, *image);
}

Camera colmapImageCamera(const ColmapModel& model, const ColmapImage& image) {
  const OpenCvLens lens = lensOf(cameraOf(model, image), model.camerasFile);
  const std::string where =
      image.line ? cat(model.imagesFile, ":", image.line) : cat(model.imagesFile, ": record ", image.record);
  return pinholeFromOpenCv(lens.intrinsics, lens.distortion, poseOf(image),
                           cat("COLMAP image ", image.name, " (", where, ")"));
}

}  // namespace lenslab
