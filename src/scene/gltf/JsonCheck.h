#pragma once
// The JSON, before tinygltf sees it: parsed by nlohmann::json (with its nesting bounded), then
// checked for what tinygltf lets pass or words unclearly.
#include <nlohmann/json.hpp>

#include <string_view>

namespace lenslab::gltf {

// The JSON of a .gltf or of a GLB's JSON chunk; refuses an empty file, a byte-order mark, nesting
// deeper than kMaxJsonDepth and invalid JSON.
nlohmann::json parseJson(std::string_view text);

// The top level's shape, required extensions, buffers without data, URIs that are not files
// beside the scene, nodes with both a matrix and TRS. `binary`: the JSON came from a GLB.
void precheckJson(const nlohmann::json& root, bool binary);

// tinygltf-2.7: its URI decoder reads '+' as a space (form encoding), though in a URI path only
// %XX is an escape, so "a+b.bin" would be looked for as "a b.bin". Rewrites '+' in the buffers' and
// images' file URIs as "%2B", which tinygltf decodes back to '+'; returns whether it changed any.
// Can go when tinygltf decodes URI paths by RFC 3986.
bool escapePlusInFileUris(nlohmann::json& root);

}  // namespace lenslab::gltf
