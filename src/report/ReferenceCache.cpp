#include "report/ReferenceCache.h"

#include "core/Clock.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "raycast/RayCaster.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <iomanip>
#include <sstream>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bits: a cache key, not a security measure. Every piece is added with its length
// first, so that two lists of pieces hash alike only when the pieces are the same.
struct Hash {
  std::uint64_t value = 1469598103934665603ull;
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value = (value ^ p[i]) * 1099511628211ull;
  }
  void piece(std::string_view text) {
    const std::uint64_t size = text.size();
    bytes(&size, sizeof size);
    bytes(text.data(), text.size());
  }
  // A number as the shortest text that reads back as it (every bit counts, unlike cat's 6 digits).
  template <class T>
  void number(T v) {
    char text[32];
    piece(std::string_view(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, v).ptr - text)));
  }
};

// The bytes of an input file, read as the loaders read it. (A scene's buffers and images of a few
// hundred MB take a second or so of byte-wise hashing: small beside the reference.)
void addFile(Hash& h, const fs::path& file) {
  h.piece(readInputFile(file, "sweep reference input", kMaxGltfFileBytes));
}

}  // namespace

std::string referenceKey(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& o) {
  Hash h;
  // The ray caster's own version: bump it when what it computes from the same inputs changes.
  // v5: keyed on the input files' bytes.
  h.piece("lenslab reference v5");
  h.number(scene.files.size() + o.inputFiles.size());
  for (const fs::path& file : scene.files) addFile(h, file);
  for (const fs::path& file : o.inputFiles) addFile(h, file);
  h.number(o.inputOptions.size());
  for (const std::string& option : o.inputOptions) h.piece(option);
  // The camera used, after every option and the depth range fitted: its file form, and the two
  // numbers the file form rounds or leaves implicit.
  h.piece(toCameraJson(camera));
  h.number(camera.lens.apertureRadius);
  h.number(camera.inverseFocusDistance());
  for (const long long v : {static_cast<long long>(size.widthPx), static_cast<long long>(size.heightPx),
                            static_cast<long long>(o.referenceSpp), static_cast<long long>(o.seed)})
    h.number(v);
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << h.value;
  return s.str();
}

ReferenceHalves referenceHalves(const RayCaster& caster, const Scene& scene, const Camera& camera, ImageSize size,
                                const SweepOptions& o) {
  ReferenceHalves out;
  const bool cache = !o.outDir.empty() && !scene.files.empty();
  const std::string key = cache ? referenceKey(scene, camera, size, o) : std::string();
  int fromCache = 0;
  for (int k = 0; k < 2; ++k) {
    const fs::path cached = cache ? o.outDir / cat("reference-", key, k == 0 ? "-a" : "-b", ".exr") : fs::path();
    if (!cached.empty() && fs::exists(cached)) {
      out.halves[k] = readImage(cached);
      if (out.halves[k].width == size.widthPx && out.halves[k].height == size.heightPx) {
        ++fromCache;
        continue;
      }
    }
    if (o.log)
      o.log(cat("reference: ray casting ", size.widthPx, "x", size.heightPx, " at ", o.referenceSpp / 2, " spp (half ",
                k + 1, " of 2", cached.empty() ? std::string() : cat(", cached as ", cached.filename().string()), ")"));
    const auto t = std::chrono::steady_clock::now();
    const RaycastOptions half{std::max(1, o.referenceSpp / 2), o.seed ^ (k == 0 ? 0x9e3779b9u : 0x7f4a7c15u)};
    const auto rowsDone = [&](int rows, int height) {
      if (o.progress) o.progress("reference rows", std::int64_t{k} * height + rows, 2 * std::int64_t{height});
    };
    out.halves[k] =
        o.exactLens ? caster.render(*o.exactLens, half, rowsDone) : caster.render(camera, size, half, rowsDone);
    out.seconds += secondsSince(t);
    if (!cached.empty()) writeImage(*o.outputs, cached, out.halves[k]);
  }
  out.cached = fromCache == 2;
  return out;
}

}  // namespace lenslab
