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
//   Animations      animation channels read into Scene::animation (src/scene/SceneAnimation poses it)
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

// Vertices beyond ±kMaxWorldCoordinate after their node transforms: one line naming the mesh.
void refuseFarPositions(const Scene& scene) {
  const auto within = [](const glm::dvec3& p) {
    return glm::all(glm::lessThanEqual(glm::abs(p), glm::dvec3(kMaxWorldCoordinate)));
  };
  if (scene.bounds.empty() || (within(scene.bounds.min) && within(scene.bounds.max))) return;
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    for (const Vertex& v : mesh.vertices) {
      const glm::dvec3 p(instance.worldFromModel * glm::dvec4(glm::dvec3(v.position), 1.0));
      if (!within(p))
        gltf::refuse("mesh ", instance.mesh, mesh.name.empty() ? "" : cat(" (", mesh.name, ")"), " has a vertex at (",
                     p.x, ", ", p.y, ", ", p.z, ") in world space, beyond +-", kMaxWorldCoordinate,
                     " where lenslab keeps its precision; move the scene nearer the origin or scale it down");
    }
  }
}

Scene load(const fs::path& file) {
  using namespace gltf;
  const std::string bytes = readFile(file);
  const bool binary = startsWithGlbMagic(bytes);
  if (!binary && file.extension() == ".glb")
    refuse(bytes.empty() ? "the file is empty" : "not a binary glTF", ": a .glb starts with the magic \"glTF\"");
  std::string glb;
  std::string_view jsonText = bytes;
  GlbChunks chunks;
  if (binary) {
    chunks = splitGlb(bytes);
    jsonText = chunks.json;
    glb = glbForTinygltf(chunks, bytes.size());
  }
  nlohmann::json root = parseJson(jsonText);
  precheckJson(root, binary);
  std::string escapedJson;  // tinygltf-2.7: see escapePlusInFileUris
  if (escapePlusInFileUris(root)) {
    escapedJson = root.dump();
    escapedJson.append((4 - escapedJson.size() % 4) % 4, ' ');  // a GLB chunk is 4-byte aligned
    if (binary) {
      chunks.json = escapedJson;
      glb = glbForTinygltf(chunks, 0);  // 0: always rebuilt
    }
  }
  const std::string_view input = !glb.empty()           ? std::string_view(glb)
                                 : !escapedJson.empty() ? std::string_view(escapedJson)
                                                        : std::string_view(bytes);
  Scene scene;
  scene.files.push_back(file);
  const tinygltf::Model model = parseModel(input, binary, file.parent_path(), scene.files);
  const AccessorReader reader(model);
  const std::vector<int> parents = checkModel(model, reader);
  scene.source = file.string();
  buildScene(model, reader, parents, scene);
  scene.bounds = computeBounds(scene);
  refuseFarPositions(scene);
  return scene;
}

}  // namespace

Scene loadGltf(const fs::path& file) {
  try {
    return load(file);
  } catch (const gltf::Problem& problem) {
    throw InputError(cat(file.string(), ": ", oneLine(problem.what())));
  } catch (const std::bad_alloc&) {
    throw InputError(cat(file.string(), ": not enough memory to load it"));
  }
}

}  // namespace lenslab
