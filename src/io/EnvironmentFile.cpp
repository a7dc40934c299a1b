#include "io/EnvironmentFile.h"

#include "core/Error.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "io/AtomicFile.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// Bump when the prefiltering or this file's layout changes: older entries are then stale.
constexpr int kCacheVersion = 2;  // 2: specular levels spaced from roughness 0.045
constexpr char kMagic[8] = {'L', 'E', 'N', 'S', 'E', 'N', 'V', '1'};

// FNV-1a, 64 bits: enough to tell files and entries apart, not a defence against forgery.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 0xcbf29ce484222325ull) {
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << v;
  return s.str();
}

const char* const kEnvironmentWhat = "environment image (.hdr or .exr)";

// The fewest bytes a Radiance .hdr of this size can hold after its header: each scanline at
// least a 4-byte run-length header and, per channel of RGBE, one 2-byte run per 127 texels
// (the most a run holds). A header that claims more than its file can hold is refused before a
// texel is allocated.
std::uintmax_t fewestHdrBytes(int width, int height) {
  return static_cast<std::uintmax_t>(height) * (4u + 4u * 2u * ((static_cast<std::uintmax_t>(width) + 126u) / 127u));
}

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
bool take(std::string_view& in, T& v) {
  if (in.size() < sizeof v) return false;
  std::memcpy(&v, in.data(), sizeof v);
  in.remove_prefix(sizeof v);
  return true;
}

void putImage(std::string& out, const EnvironmentImage& image) {
  put(out, static_cast<std::int32_t>(image.width));
  put(out, static_cast<std::int32_t>(image.height));
  out.append(reinterpret_cast<const char*>(image.rgb.data()), image.rgb.size() * sizeof(glm::vec3));
}

bool takeImage(std::string_view& in, EnvironmentImage& image) {
  std::int32_t w = 0, h = 0;
  if (!take(in, w) || !take(in, h) || w < 1 || h < 1 || w > (1 << 16) || h > (1 << 16)) return false;
  const std::size_t bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * sizeof(glm::vec3);
  if (in.size() < bytes) return false;
  image.width = w;
  image.height = h;
  image.rgb.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::memcpy(image.rgb.data(), in.data(), bytes);
  in.remove_prefix(bytes);
  return true;
}

void checkEnvironmentExtension(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".hdr" && ext != ".exr")
    throw InputError(cat(
        path.string(), ": an environment is a .hdr or .exr file (equirectangular, linear radiance), not '", ext, "'"));
}

// What image format `bytes` hold, by their first bytes ("" when none lenslab names).
std::string imageFormatOf(std::string_view bytes) {
  const std::pair<std::string_view, const char*> formats[] = {{"#?", "Radiance HDR"}, {"\x76\x2f\x31\x01", "OpenEXR"},
                                                              {"\x89PNG", "PNG"},     {"\xFF\xD8\xFF", "JPEG"},
                                                              {"II*\0", "TIFF"},      {"MM\0*", "TIFF"},
                                                              {"GIF8", "GIF"},        {"BM", "BMP"}};
  for (const auto& [magic, name] : formats)
    if (bytes.starts_with(magic)) return name;
  return "";
}

// The file holds what its name says: a PNG renamed .hdr would be decoded as its own 8-bit sRGB
// values and taken for linear radiance, silently.
void checkEnvironmentContent(const fs::path& path, std::string_view bytes) {
  const std::string expected = lowerExtension(path) == ".hdr" ? "Radiance HDR" : "OpenEXR";
  const std::string found = imageFormatOf(bytes);
  if (found == expected) return;
  throw InputError(cat(path.string(), ": the file is ", found.empty() ? "not" : cat("a ", found, " image, not"),
                       " the ", expected,
                       " image its name says; an environment is linear radiance in a .hdr or .exr file"));
}

}  // namespace

EnvironmentImage readEnvironmentImage(const fs::path& path) {
  checkEnvironmentExtension(path);
  return decodeEnvironmentImage(path, readInputFile(path, kEnvironmentWhat, kMaxEnvironmentFileBytes));
}

EnvironmentImage decodeEnvironmentImage(const fs::path& path, const std::string& bytes) {
  checkEnvironmentExtension(path);
  checkEnvironmentContent(path, bytes);
  // Decoded from the bytes the bounded reader read, not from the path again: what was checked is
  // what is decoded.
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  auto in = OIIO::ImageInput::open(path.string(), nullptr, &memory);
  if (!in) throw InputError(cat(path.string(), ": cannot read the environment: ", oneLine(OIIO::geterror())));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 3 && spec.nchannels != 4)
    throw InputError(
        cat(path.string(), ": the environment has ", spec.nchannels, " channels; it must have 3 (RGB) or 4 (RGBA)"));
  if (spec.width != 2 * spec.height || spec.height < 2)
    throw InputError(cat(path.string(), ": the environment is ", spec.width, " × ", spec.height,
                         "; an equirectangular image is twice as wide as high, at least 4 × 2"));
  if (spec.width > kMaxEnvironmentWidthPx)
    throw InputError(cat(path.string(), ": the environment claims ", spec.width, " × ", spec.height,
                         " texels; lenslab reads at most ", kMaxEnvironmentWidthPx, " × ", kMaxEnvironmentWidthPx / 2));
  if (lowerExtension(path) == ".hdr" && bytes.size() < fewestHdrBytes(spec.width, spec.height))
    throw InputError(cat(path.string(), ": the header claims ", spec.width, " × ", spec.height,
                         " texels, but the file's ", bytes.size(), " bytes cannot hold them (at least ",
                         fewestHdrBytes(spec.width, spec.height),
                         "); the file is cut short or not what its header says"));
  const std::size_t texels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  std::vector<float> pixels;
  EnvironmentImage image{spec.width, spec.height, {}};
  try {
    pixels.resize(texels * static_cast<std::size_t>(spec.nchannels));
    image.rgb.resize(texels);
  } catch (const std::bad_alloc&) {
    throw InputError(cat(path.string(), ": the environment's ", spec.width, " × ", spec.height, " texels need ",
                         (texels * (static_cast<std::size_t>(spec.nchannels) + 3) * sizeof(float)) >> 20,
                         " MiB, more memory than is free (or than ulimit -v allows); give a smaller environment"));
  }
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError(cat(path.string(), ": cannot read the environment: ", oneLine(in->geterror())));
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const float* p = &pixels[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels];
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || p[k] < 0.0f)
          throw InputError(cat(path.string(), ": pixel (", x, ", ", y, ") holds ", p[k],
                               "; an environment's radiance is finite and ≥ 0"));
      image.at(x, y) = {p[0], p[1], p[2]};
    }
  return image;
}

std::optional<fs::path> environmentCacheFolder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg && fs::path(xdg).is_absolute()) return fs::path(xdg) / "lenslab";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".cache" / "lenslab";
  return std::nullopt;
}

std::string environmentCacheKey(const std::string& fileBytes, const PrefilterSettings& settings) {
  return cat("lenslab environment v", kCacheVersion, "; contents ", hex(fnv1a(fileBytes)), " (", fileBytes.size(),
             " bytes); ", settings.key());
}

std::string encodeEnvironmentCache(const std::string& key, const PrefilteredEnvironment& maps) {
  std::string out(kMagic, sizeof kMagic);
  put(out, static_cast<std::uint32_t>(key.size()));
  out += key;
  putImage(out, maps.background);
  putImage(out, maps.diffuse);
  put(out, static_cast<std::int32_t>(maps.specular.size()));
  for (const EnvironmentImage& level : maps.specular) putImage(out, level);
  put(out, fnv1a(out));
  return out;
}

std::optional<PrefilteredEnvironment> decodeEnvironmentCache(const std::string& key, const std::string& bytes) {
  std::uint64_t checksum = 0;
  if (bytes.size() < sizeof kMagic + sizeof checksum) return std::nullopt;
  std::string_view body(bytes.data(), bytes.size() - sizeof checksum);
  std::memcpy(&checksum, bytes.data() + body.size(), sizeof checksum);
  if (fnv1a(body) != checksum || std::memcmp(body.data(), kMagic, sizeof kMagic) != 0) return std::nullopt;
  body.remove_prefix(sizeof kMagic);
  std::uint32_t keySize = 0;
  if (!take(body, keySize) || body.size() < keySize || body.substr(0, keySize) != key) return std::nullopt;
  body.remove_prefix(keySize);
  PrefilteredEnvironment maps;
  std::int32_t levels = 0;
  if (!takeImage(body, maps.background) || !takeImage(body, maps.diffuse) || !take(body, levels) || levels < 1 ||
      levels > 64)
    return std::nullopt;
  maps.specular.resize(static_cast<std::size_t>(levels));
  for (EnvironmentImage& level : maps.specular)
    if (!takeImage(body, level) || level.width != maps.specular.front().width ||
        level.height != maps.specular.front().height)
      return std::nullopt;
  if (!body.empty()) return std::nullopt;
  return maps;
}

LoadedEnvironment loadEnvironment(const fs::path& path, const PrefilterSettings& settings,
                                  const std::optional<fs::path>& cacheFolder) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  // The extension first, so that a typo fails before the file is read.
  checkEnvironmentExtension(path);
  const std::string bytes = readInputFile(path, kEnvironmentWhat, kMaxEnvironmentFileBytes);
  checkEnvironmentContent(path, bytes);  // before the cache: an entry made from it is no proof
  const std::string key = environmentCacheKey(bytes, settings);
  LoadedEnvironment loaded;
  std::optional<fs::path> entry;
  if (cacheFolder) {
    entry = *cacheFolder / ("environment-" + hex(fnv1a(key)) + ".bin");
    std::error_code ec;
    if (fs::is_regular_file(*entry, ec)) {
      try {
        if (std::optional<PrefilteredEnvironment> maps = decodeEnvironmentCache(
                key, readInputFile(*entry, "environment cache entry", 4 * kMaxEnvironmentFileBytes))) {
          loaded.maps = std::make_shared<const PrefilteredEnvironment>(std::move(*maps));
          loaded.fromCache = true;
          loaded.seconds = elapsed();
          return loaded;
        }
      } catch (const InputError& e) {
        loaded.warning = cat("environment cache ", entry->string(), " not read: ", e.what());
      }
    }
  } else {
    loaded.warning = "environment cache: neither XDG_CACHE_HOME nor HOME is set, so the prefiltered maps are not kept";
  }
  loaded.maps = std::make_shared<const PrefilteredEnvironment>(
      prefilterEnvironment(decodeEnvironmentImage(path, bytes), settings));
  if (entry) {
    try {
      std::error_code ec;
      fs::create_directories(entry->parent_path(), ec);
      if (ec) throw InputError(cat(entry->parent_path().string(), ": cannot create it: ", ec.message()));
      writeFileAtomically(*entry, encodeEnvironmentCache(key, *loaded.maps));
    } catch (const std::exception& e) {
      loaded.warning = cat("environment cache not written (prefiltering again next time): ", e.what());
    }
  }
  loaded.seconds = elapsed();
  return loaded;
}

std::optional<EnvironmentSummary> applyEnvironment(Scene& scene, const EnvironmentRequest& request,
                                                   std::ostream& warnings) {
  if (request.file.empty()) return std::nullopt;
  if (!(request.intensity >= 0.0) || !std::isfinite(request.intensity))
    throw InputError(cat("--environment-intensity ", request.intensity, ": give a finite number ≥ 0"));
  const LoadedEnvironment loaded = loadEnvironment(request.file, PrefilterSettings{}, environmentCacheFolder());
  if (!loaded.warning.empty()) warnings << "lenslab: warning: " << loaded.warning << "\n";
  // The scaled radiance stays a float (scene/Scene.h's kMaxRadiance): refused here, in one line,
  // rather than written as an image of inf.
  float brightest = 0.0f;
  for (const glm::vec3& texel : loaded.maps->background.rgb)
    brightest = std::max({brightest, texel.r, texel.g, texel.b});
  if (static_cast<double>(brightest) * request.intensity > kMaxRadiance)
    throw InputError(cat("--environment-intensity ", request.intensity, ": times ", request.file,
                         "'s brightest texel, ", brightest, ", it exceeds a float's largest radiance (", kMaxRadiance,
                         "); give at most ", kMaxRadiance / brightest));
  scene.environment = std::make_shared<const EnvironmentLookup>(
      loaded.maps, EnvironmentPlacement{request.rotationDegrees, static_cast<float>(request.intensity)});
  EnvironmentSummary s;
  s.file = request.file;
  s.intensity = request.intensity;
  s.rotationDegrees = request.rotationDegrees;
  s.widthPx = loaded.maps->background.width;
  s.heightPx = loaded.maps->background.height;
  s.specularLevels = loaded.maps->specularLevels();
  s.fromCache = loaded.fromCache;
  s.seconds = loaded.seconds;
  return s;
}

}  // namespace lenslab
