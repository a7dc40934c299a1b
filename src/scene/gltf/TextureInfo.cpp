#include "scene/gltf/TextureInfo.h"

#include "core/NumberInput.h"
#include "scene/TextureTransform.h"
#include "scene/gltf/Problems.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace lenslab::gltf {
namespace {

const tinygltf::Value* transformOf(const tinygltf::ExtensionMap& extensions) {
  const auto found = extensions.find("KHR_texture_transform");
  return found == extensions.end() ? nullptr : &found->second;
}

// The extension bounds none of its numbers. Offsets and scales are kept where a float texture
// coordinate times them stays a float (|value| ≤ 1e30: 10^30 repeats of the texture, far past
// where a float uv holds any position within one); a rotation may be any finite angle, reduced
// to one turn in double before it becomes a float.
constexpr NumberRange kTransformRange{-1e30, 1e30, "texture units"};
constexpr NumberRange kRotationRange{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                                     "radians"};

double checked(double value, const char* field, const NumberRange& range, const std::string& where) {
  if (const std::optional<std::string> problem = numberProblem(value, range))
    refuse(where, " KHR_texture_transform.", field, ": ", *problem);
  return value;
}

// A finite angle, or `fallback` where the field is absent, within one turn.
float rotation(const tinygltf::Value& object, const std::string& where) {
  if (!object.Has("rotation")) return 0.0f;
  const tinygltf::Value& v = object.Get("rotation");
  if (!v.IsNumber()) refuse(where, " KHR_texture_transform.rotation must be a number (radians)");
  const double d = checked(v.GetNumberAsDouble(), "rotation", kRotationRange, where);
  return static_cast<float>(std::remainder(d, 2.0 * std::numbers::pi));
}

glm::dvec2 pair(const tinygltf::Value& object, const char* field, glm::dvec2 fallback, const std::string& where) {
  if (!object.Has(field)) return fallback;
  const tinygltf::Value& v = object.Get(field);
  if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
    refuse(where, " KHR_texture_transform.", field, " must be an array of 2 numbers");
  return {checked(v.Get(0).GetNumberAsDouble(), field, kTransformRange, where),
          checked(v.Get(1).GetNumberAsDouble(), field, kTransformRange, where)};
}

// An offset along one axis, moved by whole periods of that axis's wrap.
double withinPeriod(double offset, Wrap wrap) {
  if (wrap == Wrap::ClampToEdge) return offset;
  const double period = wrap == Wrap::MirroredRepeat ? 2.0 : 1.0;
  return offset - period * std::floor(offset / period);
}

}  // namespace

int effectiveTexCoord(int texCoord, const tinygltf::ExtensionMap& extensions) {
  const tinygltf::Value* t = transformOf(extensions);
  if (!t || !t->Has("texCoord") || !t->Get("texCoord").IsNumber()) return texCoord;
  const double d = t->Get("texCoord").GetNumberAsDouble();
  return d >= 0.0 && d <= 1e6 && d == std::floor(d) ? static_cast<int>(d) : -1;
}

TextureRef textureRef(int texture, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& where,
                      const Sampler& sampler) {
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
    const glm::dvec2 offset = pair(*t, "offset", glm::dvec2(0.0), where);
    ref.uvFromTexCoord =
        uvFromTexCoord(glm::vec2(withinPeriod(offset.x, sampler.wrapS), withinPeriod(offset.y, sampler.wrapT)),
                       rotation(*t, where), glm::vec2(pair(*t, "scale", glm::dvec2(1.0), where)));
  }
  return ref;
}

}  // namespace lenslab::gltf
