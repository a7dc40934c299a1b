#include "app/AovOutputs.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/OutputPath.h"

#include <nlohmann/json.hpp>

#include <map>
#include <set>

namespace lenslab {

AovOutput parseAovRequest(const AovRequest& request, bool sequence) {
  AovOutput o;
  o.selection = parseAovs(request.names);
  if (o.selection.flow && !sequence)
    throw InputError(cat("--aov ", aovList(o.selection),
                         ": flow is each pixel's motion to the next frame of a sequence; `lenslab capture` writes it"));
  o.format = parseAovFormat(request.format);
  o.normals = parseNormalConvention(request.normals);
  if (!o.selection.any() && o.format != AovFormat::Exr)
    throw InputError(cat("--aov-format ", request.format, ": give --aov LIST too, the AOVs to write"));
  if (!o.selection.normal && o.normals != NormalConvention::Gl)
    throw InputError(cat("--normal-convention ", request.normals, ": give --aov normal too (it turns the normals)"));
  return o;
}

void checkAovOutput(const AovOutput& output, const std::filesystem::path& image, const std::string& outOption) {
  for (const std::filesystem::path& file : aovFilePaths(output, image))
    checkOutputPath(file, OutputKind::Any, outOption);
  if (output.selection.instance) checkOutputPath(instancesFileBeside(image), OutputKind::Json, outOption);
}

AovOutput checkedAovOutput(const AovRequest& request, const std::filesystem::path& image,
                           const std::string& outOption) {
  const AovOutput output = parseAovRequest(request);
  checkAovOutput(output, image, outOption);
  return output;
}

std::filesystem::path instancesFileBeside(const std::filesystem::path& image) {
  std::filesystem::path p = image;
  p.replace_extension();
  return p.string() + ".instances.json";
}

std::vector<ImageChannel> addAovOutputs(OutputSet& outputs, const std::filesystem::path& image, const AovImages& images,
                                        const AovOutput& output, const Scene& scene,
                                        const std::function<void(const std::string&)>& warn,
                                        const std::filesystem::path& instancesFile) {
  if (!output.selection.any()) return {};
  if (output.selection.instance)
    outputs.add(instancesFile.empty() ? instancesFileBeside(image) : instancesFile, instancesJson(scene));
  std::vector<std::string> warnings;
  std::vector<ImageChannel> channels = writeAovFiles(outputs, image, images, output, warnings);
  for (const std::string& w : warnings) warn(w);
  return channels;
}

std::string instancesJson(const Scene& scene) {
  // Every node that places a mesh, in node order: its primitives are instances of their own.
  std::map<int, std::vector<const Instance*>> byNode;
  for (const Instance& instance : scene.instances)
    if (instance.gltfNode >= 0) byNode[instance.gltfNode].push_back(&instance);
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [node, instances] : byNode) {
    nlohmann::json entry;
    entry["id"] = node + 1;
    entry["node"] = node;
    entry["node_name"] = instances.front()->gltfNodeName;
    const int firstMesh = instances.front()->mesh;
    std::string mesh = firstMesh >= 0 ? scene.meshes[static_cast<std::size_t>(firstMesh)].name : "";
    // The loader names a mesh's primitives "NAME#k" (scene/gltf/Primitives.cpp): the glTF mesh is NAME.
    if (const std::size_t hash = mesh.rfind('#'); instances.size() > 1 && hash != std::string::npos) mesh.erase(hash);
    entry["mesh"] = mesh;
    std::set<std::string> seen;
    nlohmann::json materials = nlohmann::json::array();
    for (const Instance* i : instances) {
      const int material = i->mesh >= 0 ? scene.meshes[static_cast<std::size_t>(i->mesh)].material : -1;
      const std::string name = material < 0 ? std::string("(glTF default material)")
                                            : scene.materials[static_cast<std::size_t>(material)].name;
      if (seen.insert(name).second) materials.push_back(name);
    }
    entry["materials"] = materials;
    list.push_back(entry);
  }
  nlohmann::json root;
  root["scene"] = scene.source;
  root["background"] = 0;
  root["instances"] = list;
  return root.dump(2) + "\n";
}

}  // namespace lenslab
