#pragma once
// A small glTF written by a test: one buffer (in a data: URI), meshes, nodes, cameras and
// animation channels added one call at a time (tests/scene/animation_test.cpp,
// tests/plan/camera_options_test.cpp).
#include <OpenImageIO/strutil.h>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace lenslab::test {

// A glTF with one buffer (in a data: URI), a one-triangle mesh (0,0,0), (1,0,0), (0,1,0), and
// helpers for nodes and animation channels.
class AnimatedGltf {
  using json = nlohmann::json;
  static constexpr int kFloat = 5126, kUShort = 5123;

 public:
  json gltf = {{"asset", {{"version", "2.0"}}}, {"scenes", json::array({{{"nodes", json::array()}}})}};

  int floats(const std::vector<float>& values, const char* type, std::size_t count) {
    return accessor(values.data(), values.size() * sizeof(float), kFloat, type, count);
  }

  int triangle() {
    if (triangleMesh_ >= 0) return triangleMesh_;
    const int positions = floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    gltf["accessors"][static_cast<std::size_t>(positions)]["min"] = {0, 0, 0};
    gltf["accessors"][static_cast<std::size_t>(positions)]["max"] = {1, 1, 0};
    const std::vector<std::uint16_t> i = {0, 1, 2};
    const int indices = accessor(i.data(), i.size() * sizeof(std::uint16_t), kUShort, "SCALAR", 3);
    return triangleMesh_ =
               push("meshes", {{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}});
  }

  // A node (its JSON given), a root of the drawn scene unless it has a parent.
  int node(json n, int parent = -1) {
    const int index = push("nodes", n);
    if (parent >= 0)
      gltf["nodes"][static_cast<std::size_t>(parent)]["children"].push_back(index);
    else
      gltf["scenes"][0]["nodes"].push_back(index);
    return index;
  }

  // A channel with its own sampler in animation `animation` (made when needed).
  void channel(int target, const char* path, const char* interpolation, const std::vector<float>& timesSeconds,
               const std::vector<float>& values, std::size_t animation = 0) {
    const std::size_t components = std::string(path) == "rotation" ? 4 : 3;
    const int input = floats(timesSeconds, "SCALAR", timesSeconds.size());
    const int output = floats(values, components == 4 ? "VEC4" : "VEC3", values.size() / components);
    while (gltf["animations"].size() <= animation)
      gltf["animations"].push_back({{"samplers", json::array()}, {"channels", json::array()}});
    json& a = gltf["animations"][animation];
    a["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
    a["channels"].push_back({{"sampler", a["samplers"].size() - 1}, {"target", {{"node", target}, {"path", path}}}});
  }

  std::filesystem::path write(const std::filesystem::path& file) const {
    json g = gltf;
    g["buffers"] = {{{"byteLength", bin_.size()},
                     {"uri", "data:application/octet-stream;base64," + OIIO::Strutil::base64_encode(bin_)}}};
    std::ofstream(file, std::ios::binary) << g.dump();
    return file;
  }

 private:
  int accessor(const void* data, std::size_t bytes, int componentType, const char* type, std::size_t count) {
    while (bin_.size() % 4) bin_.push_back('\0');
    const int view = push("bufferViews", {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}});
    bin_.append(static_cast<const char*>(data), bytes);
    return push("accessors",
                {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
  }

  int push(const char* collection, const json& item) {
    gltf[collection].push_back(item);
    return static_cast<int>(gltf[collection].size()) - 1;
  }

  std::string bin_;
  int triangleMesh_ = -1;
};

}  // namespace lenslab::test
