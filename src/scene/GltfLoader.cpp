// loadGltf, in the order its parts run; each part lives in src/scene/gltf/, in a file named after
// what it holds:
//   Container       the file's bytes; a GLB split into its JSON and BIN chunks
//   JsonCheck       the JSON parsed and checked before tinygltf sees it
//   TinygltfModel   tinygltf's Model (images kept encoded); checked views into its buffers
//   Accessors       accessor data, every byte checked, sparse applied, min/max enforced
//   ModelChecks     every reference and value checked; the node hierarchy a forest
//   Primitives      glTF primitives → triangle meshes
//   Images          image headers checked; used images decoded to RGBA8
//   SceneBuilder    the default scene walked into a Scene
//   Problems        Problem, refuse and notes;  Limits  what lenslab refuses to read
//   ComponentTypes  accessor types and component types
// Workarounds for Debian's tinygltf 2.7 carry a comment tag; when upgrading tinygltf, list them
// with  grep -rn 'tinygltf-2.7[:]' src/scene
#include "scene/GltfLoader.h"

#include "core/Error.h"
#include "core/Text.h"
#include "scene/gltf/Accessors.h"
#include "scene/gltf/Container.h"
#include "scene/gltf/JsonCheck.h"
#include "scene/gltf/ModelChecks.h"
#include "scene/gltf/Problems.h"
#include "scene/gltf/SceneBuilder.h"
#include "scene/gltf/TinygltfModel.h"

#include <new>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

Scene load(const fs::path& file) {
  using namespace gltf;
  const std::string bytes = readFile(file);
  const bool binary = startsWithGlbMagic(bytes);
  if (!binary && file.extension() == ".glb")
    refuse(bytes.empty() ? "the file is empty" : "not a binary glTF", ": a .glb starts with the magic \"glTF\"");
  std::string glb;
  std::string_view jsonText = bytes;
  if (binary) {
    const GlbChunks chunks = splitGlb(bytes);
    jsonText = chunks.json;
    glb = glbForTinygltf(chunks, bytes.size());
  }
  precheckJson(parseJson(jsonText), binary);
  const tinygltf::Model model = parseModel(glb.empty() ? std::string_view(bytes) : std::string_view(glb), binary, file.parent_path());
  const AccessorReader reader(model);
  const std::vector<int> parents = checkModel(model, reader);
  Scene scene;
  scene.source = file.string();
  buildScene(model, reader, parents, scene);
  scene.bounds = computeBounds(scene);
  return scene;
}

}  // namespace

Scene loadGltf(const fs::path& file) {
  try {
    return load(file);
  } catch (const gltf::Problem& problem) {
    throw InputError(cat(file.string(), ": ", gltf::oneLine(problem.what())));
  } catch (const std::bad_alloc&) {
    throw InputError(cat(file.string(), ": not enough memory to load it"));
  }
}

}  // namespace lenslab
