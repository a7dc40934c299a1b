#include "core/DataPaths.h"

#include "core/Error.h"

#include <cstdlib>
#include <system_error>

// Compiled in for this file only (CMakeLists.txt): the source tree, the build tree (symbolic links
// resolved), and the data folder relative to the installed executable's folder (e.g. "../share/lenslab").
#if !defined(LENSLAB_SOURCE_DIR) || !defined(LENSLAB_BUILD_DIR) || !defined(LENSLAB_DATA_FROM_BIN)
#error "CMakeLists.txt defines LENSLAB_SOURCE_DIR, LENSLAB_BUILD_DIR and LENSLAB_DATA_FROM_BIN for DataPaths.cpp"
#endif

namespace lenslab {
namespace fs = std::filesystem;

namespace {

std::optional<fs::path> fromEnvironment(const char* name) {
  if (const char* value = std::getenv(name); value && *value) return fs::path(value);
  return std::nullopt;
}

// Whether `path` is `folder` or lies below it (both absolute and normalised).
bool isInside(const fs::path& path, const fs::path& folder) {
  const fs::path p = path.lexically_normal(), f = folder.lexically_normal();
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
    if (fi->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *fi) return false;
  }
  return true;
}

// Whether the executable at `exe` (executablePath()'s) lies inside the build tree. Compared as text
// (CMake gives the build tree with its symbolic links resolved, as the kernel gives the
// executable): an installed lenslab does not so much as look at the build tree.
bool insideBuildTree(const fs::path& exe) { return !exe.empty() && isInside(exe, LENSLAB_BUILD_DIR); }

fs::path& embeddingLibrary() {
  static fs::path library;
  return library;
}

// The file that stands for "the executable" in the rules of DataPaths.h, and the data folder
// relative to its folder.
fs::path codePath() { return embeddingLibrary().empty() ? executablePath() : embeddingLibrary(); }
fs::path dataFromCode() {
  return embeddingLibrary().empty() ? fs::path(LENSLAB_DATA_FROM_BIN) : fs::path("share/lenslab");
}

}  // namespace

void setEmbeddingLibrary(const fs::path& library) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(library, error);
  embeddingLibrary() = error ? library : resolved;
}

fs::path executablePath() {
  // Read once: the executable does not change while it runs, and shaderDirectory() asks on every
  // shader load. (The environment variables are read each time: a test may set them.)
  static const fs::path exe = [] {
    std::error_code error;
    fs::path path = fs::read_symlink("/proc/self/exe", error);
    return error ? fs::path() : path;
  }();
  return exe;
}

bool runningFromBuildTree() { return insideBuildTree(codePath()); }

std::optional<fs::path> shaderDirectory() {
  if (auto env = fromEnvironment("LENSLAB_SHADER_DIR")) return env;
  if (runningFromBuildTree()) return fs::path(LENSLAB_SOURCE_DIR) / "shaders";
  return std::nullopt;
}

fs::path assetDirectory() {
  if (auto env = fromEnvironment("LENSLAB_ASSET_DIR")) return *env;
  const fs::path exe = codePath();
  fs::path installed;
  if (!exe.empty()) {
    installed = (exe.parent_path() / dataFromCode() / "assets").lexically_normal();
    std::error_code error;
    if (fs::is_directory(installed, error)) return installed;
  }
  if (insideBuildTree(exe)) return fs::path(LENSLAB_SOURCE_DIR) / "assets";
  throw InputError(
      "bundled scenes: no assets folder at " +
      (installed.empty() ? std::string("<executable>/" LENSLAB_DATA_FROM_BIN "/assets") : installed.string()) +
      "; set LENSLAB_ASSET_DIR to lenslab's assets/ folder, or name a scene file");
}

}  // namespace lenslab
