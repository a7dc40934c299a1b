#pragma once
// Command-line options shared by the benchmarks (lenslab_ratios, lenslab_bench): which scene,
// camera, image size and view count to measure, and the backend.
//   --scene FILE.gltf     default assets/rows/rows.gltf
//   --camera FILE.json    default assets/rows/camera-dof.json
//   --size WxH            default 1280x720
//   --views N             aperture views of a frame, default 64
//   --backend=egl         a GPU through EGL instead of llvmpipe through OSMesa
// (tools/make-big-scene.py writes a scene of over a million triangles with a camera beside it.)
#include "core/Image.h"
#include "gl/GlContext.h"
#include "scene/Scene.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace lenslab::bench {

struct Options {
  std::string scenePath;
  std::string cameraPath;
  int widthPx = 1280;
  int heightPx = 720;
  int views = 64;
  Backend backend = Backend::OSMesa;
};

// LENSLAB_ASSET_DIR overrides the source tree's assets/ (for a binary copied elsewhere).
inline std::string assetDir() {
  const char* env = std::getenv("LENSLAB_ASSET_DIR");
  return env && *env ? env : LENSLAB_BENCH_ASSET_DIR;
}

// Takes the options above out of argv (the rest is left for Google Benchmark's own flags).
// Throws with one line naming the option and what it takes.
inline Options parseOptions(int& argc, char** argv) {
  Options o;
  o.scenePath = assetDir() + "/rows/rows.gltf";
  o.cameraPath = assetDir() + "/rows/camera-dof.json";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--backend=egl") {
      o.backend = Backend::Egl;
    } else if (arg == "--scene") {
      o.scenePath = value();
    } else if (arg == "--camera") {
      o.cameraPath = value();
    } else if (arg == "--size") {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%dx%d", &o.widthPx, &o.heightPx) != 2 || o.widthPx < 1 || o.heightPx < 1 ||
          o.widthPx > 16384 || o.heightPx > 16384)
        throw std::runtime_error("--size " + v + ": expected WxH, each 1 to 16384 (e.g. 1920x1080)");
    } else if (arg == "--views") {
      const std::string v = value();
      o.views = std::atoi(v.c_str());
      if (o.views < 2 || o.views > 4096) throw std::runtime_error("--views " + v + ": expected 2 to 4096");
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return o;
}

// Triangles one scene pass draws: every instance's mesh.
inline double trianglesOf(const Scene& scene) {
  double triangles = 0.0;
  for (const Instance& instance : scene.instances)
    triangles += static_cast<double>(scene.meshes[static_cast<std::size_t>(instance.mesh)].indices.size() / 3);
  return triangles;
}

}  // namespace lenslab::bench
