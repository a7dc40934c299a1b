#pragma once
// The sweep's ray-cast reference and its cache. The reference is two independent halves of the
// samples (other seeds), averaged; their difference measures its own noise. Both halves are kept
// in the --out folder as reference-<key>-a.exr and -b.exr, and a later sweep with the same key
// reads them instead of ray casting again.
//
// The key is what the reference is computed from, as bytes: every input file (the scene's glTF
// or GLB and each buffer and image it names, Scene::files; the camera file, the environment
// image and the lens file, SweepOptions::inputFiles), the options that change the reference
// (SweepOptions::inputOptions: background, environment intensity and rotation, lens settings),
// the camera actually used, the image size, samples and seed. Nothing here reads a scene's
// fields: a new material field, light or texture setting reaches the key through its file.
#include "core/Image.h"
#include "report/Sweep.h"

#include <string>

namespace lenslab {

class RayCaster;

// The cache key, 16 hex digits. Throws InputError when an input file cannot be read (it was read
// a moment ago to load the scene, so only a file removed since then).
std::string referenceKey(const Scene& scene, const Camera& camera, ImageSize size, const SweepOptions& options);

struct ReferenceHalves {
  Image halves[2];
  double seconds = 0.0;  // ray casting; 0 when both came from the cache
  bool cached = false;   // both halves read from the cache
};

// The two halves: from the cache in options.outDir when both are there at this size, else ray
// cast (each written to the cache when there is an outDir). A scene made in code (no
// Scene::files) is never cached: its key would not see its contents.
ReferenceHalves referenceHalves(const RayCaster& caster, const Scene& scene, const Camera& camera, ImageSize size,
                                const SweepOptions& options);

}  // namespace lenslab
