#pragma once
// Environment files: an equirectangular image of linear radiance (scene/Environment.h's
// convention), Radiance .hdr or OpenEXR .exr, read through OpenImageIO; and the prefiltered maps
// made from it, computed once and kept in a cache.
//
// The cache: one file per (file contents, prefilter settings, format version) under
// $XDG_CACHE_HOME/lenslab (else ~/.cache/lenslab), named by a hash of those three, holding the key
// itself and a checksum, written atomically (io/AtomicFile.h). An entry whose key or checksum does
// not match (stale or corrupt) is computed again and replaced; a folder that cannot be written
// costs a warning and the prefiltering next time, never the run.
#include "scene/Environment.h"
#include "scene/EnvironmentPrefilter.h"
#include "scene/Scene.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace lenslab {

// The largest environment: 16384 × 8192 texels (16K, the largest panoramas published).
constexpr int kMaxEnvironmentWidthPx = 16384;

// The image in `path` (.hdr or .exr, RGB or RGBA: alpha is dropped), read through the bounded
// reader (core/TextFile.h: a regular file of at most kMaxEnvironmentFileBytes). Throws InputError,
// one line naming the file, for another extension, a folder or device, a file too large, another
// channel count, a width not twice the height or over kMaxEnvironmentWidthPx, a header claiming
// more texels than the file's bytes can hold or than memory can, or a pixel that is not finite or
// negative.
EnvironmentImage readEnvironmentImage(const std::filesystem::path& path);
// The same from the file's bytes, already read (`path` names it in messages).
EnvironmentImage decodeEnvironmentImage(const std::filesystem::path& path, const std::string& bytes);

// $XDG_CACHE_HOME/lenslab when XDG_CACHE_HOME is an absolute path, else $HOME/.cache/lenslab;
// nullopt when neither can be found.
std::optional<std::filesystem::path> environmentCacheFolder();

struct LoadedEnvironment {
  std::shared_ptr<const PrefilteredEnvironment> maps;
  bool fromCache = false;
  double seconds = 0.0;  // reading, and prefiltering when it was not cached
  std::string warning;   // why the cache could not be read or written; empty when it could
};

// The prefiltered maps of the environment in `path`, from the cache in `cacheFolder` (nullopt:
// no cache) or computed and stored there.
LoadedEnvironment loadEnvironment(const std::filesystem::path& path, const PrefilterSettings& settings,
                                  const std::optional<std::filesystem::path>& cacheFolder);

// What a command asks for (--environment, --environment-intensity, --environment-rotation).
struct EnvironmentRequest {
  std::string file;              // empty: no environment
  double intensity = 1.0;        // ≥ 0
  double rotationDegrees = 0.0;  // about world +Y
};

// What --stats reports of the environment a run used.
struct EnvironmentSummary {
  std::string file;
  double intensity = 1.0;
  double rotationDegrees = 0.0;
  int widthPx = 0;
  int heightPx = 0;
  int specularLevels = 0;
  bool fromCache = false;
  double seconds = 0.0;  // reading it, and prefiltering when not cached
};

// Loads the requested environment (the cache in environmentCacheFolder()) into scene.environment;
// nothing without a file. The cache's warning, if any, goes to `warnings` as one line.
std::optional<EnvironmentSummary> applyEnvironment(Scene& scene, const EnvironmentRequest& request,
                                                   std::ostream& warnings);

// The bytes of a cache entry and back (for tests): `key` names what it was made from; read
// returns nullopt when the bytes are not a whole entry of that key.
std::string encodeEnvironmentCache(const std::string& key, const PrefilteredEnvironment& maps);
std::optional<PrefilteredEnvironment> decodeEnvironmentCache(const std::string& key, const std::string& bytes);
// The key of a file's contents with these settings (and the format's version).
std::string environmentCacheKey(const std::string& fileBytes, const PrefilterSettings& settings);

}  // namespace lenslab
