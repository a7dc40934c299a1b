// libFuzzer target: the glTF loader, as `lenslab render SCENE` and `lenslab info SCENE` meet a file.
// The input is written to a file in this process's own scratch folder and loaded with loadGltf
// (the loader only takes a path; going through the file also covers reading it). The bytes decide
// the container, as in the loader: a GLB when they start with the magic "glTF" (named fuzz.glb),
// else glTF JSON (named fuzz.gltf; relative URIs resolve in the empty scratch folder, data: URIs
// are read). A scene that loads is then given a camera as `render` would (chooseCamera: its first
// glTF camera, else an automatic framing of its bounding sphere).
//
// The loader's contract: any input loads or is refused with an InputError. Any other exception,
// a crash, an abort, a hang (-timeout), a sanitizer report or a large allocation (-rss_limit_mb,
// -malloc_limit_mb) is a finding. Built with LENSLAB_FUZZ (the fuzz preset); run by tools/fuzz.sh.
#include "core/Error.h"
#include "plan/CameraSelection.h"
#include "scene/GltfLoader.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;

fs::path scratch;  // this process's folder: the input file is written here

void removeScratch() {
  std::error_code ec;
  fs::remove_all(scratch, ec);
}

void writeFile(const fs::path& file, const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::perror(file.c_str());
    std::abort();  // the harness failed, not the loader: stop rather than fuzz nothing
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::string pattern = (fs::temp_directory_path() / "lenslab-gltf-fuzz-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::perror("mkdtemp");
    std::abort();
  }
  scratch = pattern;
  std::atexit(removeScratch);
  return 0;
}

// LENSLAB_FUZZ_VERBOSE=1 prints each refusal (to see why a seed or a finding is refused).
const bool verbose = std::getenv("LENSLAB_FUZZ_VERBOSE") != nullptr;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && std::string_view(reinterpret_cast<const char*>(data), 4) == "glTF";
  const fs::path file = scratch / (glb ? "fuzz.glb" : "fuzz.gltf");
  writeFile(file, data, size);
  try {
    const lenslab::Scene scene = lenslab::loadGltf(file);
    (void)lenslab::chooseCamera(scene, std::nullopt, {}, 1.5);
    if (verbose)
      std::fprintf(stderr, "loaded: %zu triangles, %zu images, %zu cameras\n", scene.triangleCount(),
                   scene.images.size(), scene.cameras.size());
  } catch (const lenslab::InputError& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    // refused with one line: what the loader must do with bad input
  }
  std::error_code ec;
  fs::remove(file, ec);
  return 0;
}
