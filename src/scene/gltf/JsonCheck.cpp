#include "scene/gltf/JsonCheck.h"

#include "core/NumberInput.h"
#include "scene/gltf/Limits.h"
#include "scene/gltf/Problems.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <string>

namespace lenslab::gltf {

namespace {

// The deepest nesting of arrays and objects (strings skipped), refused beyond kMaxJsonDepth.
// tinygltf-2.7: JSON nesting bounded before anything parses it, because tinygltf 2.7 recurses once
// per level of "extras"/"extensions" and overflows the stack; can go when tinygltf is upgraded to
// one that bounds its recursion (precheckJson's e.dump() recurses too: bound that first).
void checkNestingDepth(std::string_view text) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) refuse("the JSON nests deeper than ", kMaxJsonDepth, " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// "http://...", "file:..." (RFC 3986: a letter, then letters, digits, '+', '-', '.', then ':');
// data: URIs are the one scheme glTF readers must take. (No std::regex: libstdc++'s recurses per
// character and overflows the stack on a long data: URI.)
bool hasUriScheme(const std::string& uri) {
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0])) || uri.starts_with("data:")) return false;
  for (const char c : uri) {
    if (c == ':') return true;
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
  }
  return false;
}

// root[key] when it is an array, else an empty array (no copy: buffers may hold megabytes).
const nlohmann::json& arrayAt(const nlohmann::json& root, const char* key) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto found = root.find(key);
  return found != root.end() && found->is_array() ? *found : empty;
}

// A string member, or "" when absent or not a string.
std::string stringAt(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return {};
  const auto found = object.find(key);
  return found != object.end() && found->is_string() ? found->get<std::string>() : std::string();
}

}  // namespace

nlohmann::json parseJson(std::string_view text) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    refuse("the file is empty (glTF JSON starts with '{')");
  if (text.substr(0, 3) == "\xEF\xBB\xBF")
    refuse("the JSON starts with a UTF-8 byte-order mark, which glTF forbids (it must begin with '{')");
  checkNestingDepth(text);
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    if (const auto end = what.find("] "); what.starts_with("[json.exception") && end != std::string::npos)
      what.erase(0, end + 2);
    refuse("invalid JSON: ", what);
  }
}

// What tinygltf lets pass or words unclearly: the top level's shape, required extensions (named
// before tinygltf trips over the data they encode), buffers without data, URIs that are not
// files beside the scene.
void precheckJson(const nlohmann::json& root, bool binary) {
  if (!root.is_object()) refuse("the top level of the JSON must be an object, not ", root.type_name());
  for (const char* key :
       {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials", "meshes", "nodes",
        "samplers", "scenes", "skins", "textures", "extensionsUsed", "extensionsRequired"})
    if (root.contains(key) && !root[key].is_array())
      refuse("\"", key, "\" must be an array, not ", root[key].type_name());
  if (root.contains("asset") && !root["asset"].is_object()) refuse("\"asset\" must be an object");
  for (const auto& e : arrayAt(root, "extensionsRequired"))
    if (!e.is_string() || std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), e.get<std::string>()) ==
                              kSupportedExtensions.end())
      refuse("extensionsRequired lists ", e.is_string() ? e.get<std::string>() : e.dump(),
             ", which lenslab does not support (supported: ", joined(kSupportedExtensions), ")");
  const nlohmann::json& buffers = arrayAt(root, "buffers");
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    if (buffers[i].is_object() && !buffers[i].contains("uri") && !(binary && i == 0))
      refuse("buffer ", i, " has no uri; only the first buffer of a .glb (its BIN chunk) may leave it out");
    if (const std::string uri = stringAt(buffers[i], "uri"); hasUriScheme(uri))
      refuse("buffer ", i, ": uri ", uri,
             " is not a relative path; lenslab reads files beside the scene and data: URIs");
  }
  const nlohmann::json& images = arrayAt(root, "images");
  for (std::size_t i = 0; i < images.size(); ++i)
    if (const std::string uri = stringAt(images[i], "uri"); hasUriScheme(uri))
      refuse("image ", i, ": uri ", uri,
             " is not a relative path; lenslab reads files beside the scene and data: URIs");
  // tinygltf 2.7 keeps only the matrix of a node that also has translation, rotation or scale.
  // tinygltf-2.7: matrix + TRS refused here from the JSON, since tinygltf 2.7 drops the TRS and the
  // Model cannot tell; can move to ModelChecks (nodes) when tinygltf is upgraded to one that keeps both.
  const nlohmann::json& nodes = arrayAt(root, "nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].is_object() && nodes[i].contains("matrix") &&
        (nodes[i].contains("translation") || nodes[i].contains("rotation") || nodes[i].contains("scale")))
      refuse("node ", i, " has both a matrix and translation/rotation/scale; glTF allows one or the other");
  // glTF: aspectRatio and zfar, when present, are > 0. tinygltf 2.7 reads a missing one as 0, so the
  // Model cannot tell "aspectRatio": 0 from none; refused here from the JSON.
  // tinygltf-2.7: can move to ModelChecks (cameras) when tinygltf marks absent values.
  const nlohmann::json& cameras = arrayAt(root, "cameras");
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (!cameras[i].is_object() || !cameras[i].contains("perspective") || !cameras[i]["perspective"].is_object())
      continue;
    const nlohmann::json& p = cameras[i]["perspective"];
    for (const char* key : {"aspectRatio", "zfar"})
      if (p.contains(key) && !(p[key].is_number() && p[key].get<double>() > 0.0 && std::isfinite(p[key].get<double>())))
        refuse("camera ", i,
               cameras[i].contains("name") && cameras[i]["name"].is_string()
                   ? cat(" \"", excerpt(cameras[i]["name"].get<std::string>()), "\"")
                   : std::string(),
               ": ", key, " is ", excerpt(p[key].dump()),
               "; when present it must be a positive finite number (leave it out ",
               std::string_view(key) == "zfar" ? "for an infinite far plane)" : "to use the image's aspect ratio)");
  }
}

bool escapePlusInFileUris(nlohmann::json& root) {
  bool changed = false;
  for (const char* list : {"buffers", "images"}) {
    if (!root.is_object() || !root.contains(list) || !root[list].is_array()) continue;
    for (nlohmann::json& item : root[list]) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      std::string uri = item["uri"].get<std::string>();
      if (uri.starts_with("data:") || uri.find('+') == std::string::npos) continue;
      std::string escaped;
      for (const char c : uri) escaped += c == '+' ? std::string("%2B") : std::string(1, c);
      item["uri"] = escaped;
      changed = true;
    }
  }
  return changed;
}

}  // namespace lenslab::gltf
