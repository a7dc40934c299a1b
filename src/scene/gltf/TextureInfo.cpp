#include "scene/gltf/TextureInfo.h"

#include "scene/TextureTransform.h"
#include "scene/gltf/Problems.h"

#include <cmath>

namespace lenslab::gltf {
namespace {

const tinygltf::Value* transformOf(const tinygltf::ExtensionMap& extensions) {
  const auto found = extensions.find("KHR_texture_transform");
  return found == extensions.end() ? nullptr : &found->second;
}

// A finite number, or `fallback` where the field is absent.
float number(const tinygltf::Value& object, const char* field, float fallback, const std::string& where) {
  if (!object.Has(field)) return fallback;
  const tinygltf::Value& v = object.Get(field);
  const double d = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
  if (!std::isfinite(d)) refuse(where, " KHR_texture_transform.", field, " must be a finite number");
  return static_cast<float>(d);
}

glm::vec2 pair(const tinygltf::Value& object, const char* field, glm::vec2 fallback, const std::string& where) {
  if (!object.Has(field)) return fallback;
  const tinygltf::Value& v = object.Get(field);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
    refuse(where, " KHR_texture_transform.", field, " must be an array of 2 numbers");
  const glm::dvec2 d(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
  if (!std::isfinite(d.x) || !std::isfinite(d.y))
    refuse(where, " KHR_texture_transform.", field, " must hold finite numbers");
  return glm::vec2(d);
}

}  // namespace

int effectiveTexCoord(int texCoord, const tinygltf::ExtensionMap& extensions) {
  const tinygltf::Value* t = transformOf(extensions);
  if (!t || !t->Has("texCoord") || !t->Get("texCoord").IsNumber()) return texCoord;
  const double d = t->Get("texCoord").GetNumberAsDouble();
  return d >= 0.0 && d <= 1e6 && d == std::floor(d) ? static_cast<int>(d) : -1;
}

TextureRef textureRef(int texture, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& where) {
  TextureRef ref;
  ref.texture = texture;
  ref.texCoord = texCoord;
  if (const tinygltf::Value* t = transformOf(extensions)) {
    if (!t->IsObject()) refuse(where, " KHR_texture_transform must be an object");
    if (t->Has("texCoord")) {
      ref.texCoord = effectiveTexCoord(texCoord, extensions);
      if (ref.texCoord < 0 || !t->Get("texCoord").IsNumber())
        refuse(where, " KHR_texture_transform.texCoord must be an integer >= 0");
    }
    ref.uvFromTexCoord = uvFromTexCoord(pair(*t, "offset", glm::vec2(0.0f), where), number(*t, "rotation", 0.0f, where),
                                        pair(*t, "scale", glm::vec2(1.0f), where));
  }
  return ref;
}

}  // namespace lenslab::gltf
