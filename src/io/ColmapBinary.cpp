#include "io/ColmapBinary.h"

#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>

namespace lenslab {
namespace {

static_assert(std::endian::native == std::endian::little, "COLMAP's binary files are little-endian, as this host");

struct ModelEntry {
  const char* name;
  int id;
  std::size_t parameterCount;
};
// COLMAP's model ids and parameter counts (src/colmap/sensor/models.h).
constexpr ModelEntry kModels[] = {{"SIMPLE_PINHOLE", 0, 3},
                                  {"PINHOLE", 1, 4},
                                  {"SIMPLE_RADIAL", 2, 4},
                                  {"RADIAL", 3, 5},
                                  {"OPENCV", 4, 8},
                                  {"OPENCV_FISHEYE", 5, 8},
                                  {"FULL_OPENCV", 6, 12},
                                  {"FOV", 7, 5},
                                  {"SIMPLE_RADIAL_FISHEYE", 8, 4},
                                  {"RADIAL_FISHEYE", 9, 5},
                                  {"THIN_PRISM_FISHEYE", 10, 12},
                                  {"RAD_TAN_THIN_PRISM_FISHEYE", 11, 16}};

constexpr std::uint64_t kMaxId = std::numeric_limits<std::uint32_t>::max() - 1;  // COLMAP's max is "invalid"

// The file's bytes read in order; every read checks that the bytes are there.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  // Record i (from 0) of kind `what` begins: messages name it from here on. Returns its number
  // from 1, as ColmapCamera::record and ColmapImage::record hold it.
  int beginRecord(const char* what, std::uint64_t i) {
    record_ = cat(what, " record ", i + 1);
    return static_cast<int>(std::min<std::uint64_t>(i + 1, std::numeric_limits<int>::max()));
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(cat(file_, ": ", record_.empty() ? std::string() : record_ + ": ", message));
  }

  template <class T>
  T read(const char* field) {
    if (bytes_.size() - at_ < sizeof(T))
      fail(cat("the file ends inside ", field, " (", bytes_.size() - at_, " of its ", sizeof(T),
               " bytes are there): it is cut short, or not COLMAP's binary format"));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  double number(const char* field) {
    const double value = read<double>(field);
    if (!std::isfinite(value)) fail(cat(field, " is ", value, "; COLMAP writes finite numbers"));
    return value;
  }
  std::uint32_t id(const char* field) {
    const std::uint32_t value = read<std::uint32_t>(field);
    if (value > kMaxId) fail(cat(field, " is ", value, ", COLMAP's invalid id"));
    return value;
  }
  // A count of records of at least `recordBytes` each: no more than the rest of the file holds
  // (checked before anything is reserved for them).
  std::uint64_t count(const char* field, std::size_t recordBytes) {
    const std::uint64_t n = read<std::uint64_t>(field);
    if (n > remaining() / recordBytes)
      fail(cat(field, " is ", n, ", but the ", remaining(), " bytes left hold at most ", remaining() / recordBytes,
               " records of ", recordBytes, " bytes or more"));
    return n;
  }
  std::string name() {
    const std::size_t end = bytes_.find('\0', at_);
    if (end == std::string_view::npos) fail("NAME has no terminating 0 byte before the file ends");
    std::string text(bytes_.substr(at_, end - at_));
    at_ = end + 1;
    return text;
  }
  void skip(std::uint64_t n) { at_ += n; }
  std::size_t remaining() const { return bytes_.size() - at_; }
  void requireEnd() {
    if (remaining() != 0) {
      record_.clear();
      fail(cat(remaining(), " bytes follow the last record; the file holds more than its count says"));
    }
  }

 private:
  std::string_view bytes_;
  const std::string& file_;
  std::size_t at_ = 0;
  std::string record_;
};

template <class T>
void append(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

}  // namespace

std::optional<ColmapModelId> colmapModelId(const std::string& name) {
  for (const ModelEntry& m : kModels)
    if (name == m.name) return ColmapModelId{m.id, m.parameterCount};
  return std::nullopt;
}

std::vector<ColmapCamera> parseColmapCamerasBinary(std::string_view bytes, const std::string& file) {
  Reader r(bytes, file);
  // The smallest record: a SIMPLE_PINHOLE's 4 + 4 + 8 + 8 + 3 × 8 bytes.
  const std::uint64_t n = r.count("the number of cameras", 48);
  std::vector<ColmapCamera> cameras;
  cameras.reserve(n);
  std::map<std::uint32_t, std::uint64_t> firstRecord;
  for (std::uint64_t i = 0; i < n; ++i) {
    ColmapCamera c;
    c.record = r.beginRecord("camera", i);
    c.id = r.id("CAMERA_ID");
    const std::int32_t modelId = r.read<std::int32_t>("MODEL_ID");
    const ModelEntry* model = nullptr;
    for (const ModelEntry& m : kModels)
      if (m.id == modelId) model = &m;
    if (!model)
      r.fail(cat("camera ", c.id, " has MODEL_ID ", modelId, ", which COLMAP does not define (0 to ",
                 std::size(kModels) - 1, ")"));
    c.model = model->name;
    const std::uint64_t width = r.read<std::uint64_t>("WIDTH"), height = r.read<std::uint64_t>("HEIGHT");
    const std::uint64_t most = std::numeric_limits<int>::max();
    if (width < 1 || height < 1 || width > most || height > most)
      r.fail(cat("camera ", c.id, " is ", width, "x", height, " pixels; give a size from 1x1 to ", most, " a side"));
    c.widthPx = static_cast<int>(width);
    c.heightPx = static_cast<int>(height);
    for (std::size_t p = 0; p < model->parameterCount; ++p) c.params.push_back(r.number("a parameter"));
    if (const auto [it, added] = firstRecord.emplace(c.id, i + 1); !added)
      r.fail(
          cat("CAMERA_ID ", c.id, " is given again (first in record ", it->second, "); each camera needs its own ID"));
    cameras.push_back(std::move(c));
  }
  r.requireEnd();
  return cameras;
}

std::vector<ColmapImage> parseColmapImagesBinary(std::string_view bytes, const std::string& file) {
  Reader r(bytes, file);
  // The smallest record: 4 + 7 × 8 + 4 bytes, a one-character name and its 0, the points' count.
  const std::uint64_t n = r.count("the number of images", 74);
  std::vector<ColmapImage> images;
  images.reserve(n);
  std::map<std::uint32_t, std::uint64_t> firstId;
  std::map<std::string, std::uint64_t> firstName;
  for (std::uint64_t i = 0; i < n; ++i) {
    ColmapImage image;
    image.record = r.beginRecord("image", i);
    image.id = r.id("IMAGE_ID");
    const double qw = r.number("QW"), qx = r.number("QX"), qy = r.number("QY"), qz = r.number("QZ");
    const glm::dquat q(qw, qx, qy, qz);
    const double length = glm::length(q);
    if (!(std::abs(length - 1.0) <= kQuaternionLengthTolerance))
      r.fail(cat("image ", image.id, "'s quaternion QW QX QY QZ has length ", length,
                 "; COLMAP writes unit quaternions (lengths within ", kQuaternionLengthTolerance,
                 " of 1 are normalised)"));
    image.rotation = q / length;
    image.translation.x = r.number("TX");
    image.translation.y = r.number("TY");
    image.translation.z = r.number("TZ");
    image.cameraId = r.id("CAMERA_ID");
    image.name = r.name();
    if (image.name.empty()) r.fail(cat("image ", image.id, " has an empty NAME"));
    // Its POINTS2D (X, Y, POINT3D_ID: 24 bytes each), which lenslab does not use.
    const std::uint64_t points = r.count("the number of POINTS2D", 24);
    r.skip(points * 24);
    if (const auto [it, added] = firstId.emplace(image.id, i + 1); !added)
      r.fail(cat("IMAGE_ID ", image.id, " is given again (first in record ", it->second,
                 "); each image needs its own ID"));
    if (const auto [it, added] = firstName.emplace(image.name, i + 1); !added)
      r.fail(cat("NAME ", image.name, " is given again (first in record ", it->second,
                 "); each image needs its own name"));
    images.push_back(std::move(image));
  }
  r.requireEnd();
  return images;
}

std::string colmapCameraRecord(const ColmapCamera& c) {
  const std::optional<ColmapModelId> model = colmapModelId(c.model);
  if (!model || model->parameterCount != c.params.size())
    throw std::logic_error(cat("colmapCameraRecord: ", c.model, " with ", c.params.size(), " parameters"));
  std::string out;
  append(out, c.id);
  append(out, static_cast<std::int32_t>(model->id));
  append(out, static_cast<std::uint64_t>(c.widthPx));
  append(out, static_cast<std::uint64_t>(c.heightPx));
  for (const double p : c.params) append(out, p);
  return out;
}

std::string colmapImageRecord(const ColmapImage& i) {
  std::string out;
  append(out, i.id);
  for (const double v :
       {i.rotation.w, i.rotation.x, i.rotation.y, i.rotation.z, i.translation.x, i.translation.y, i.translation.z})
    append(out, v);
  append(out, i.cameraId);
  out += i.name;
  out += '\0';
  append(out, std::uint64_t{0});  // no POINTS2D
  return out;
}

std::string colmapCountField(std::uint64_t count) {
  std::string out;
  append(out, count);
  return out;
}

std::string colmapPoints3DBinary() { return colmapCountField(0); }

}  // namespace lenslab
