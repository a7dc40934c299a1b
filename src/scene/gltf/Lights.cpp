#include "scene/gltf/Lights.h"

#include "core/NumberInput.h"
#include "scene/gltf/Problems.h"

#include <cmath>
#include <string>

namespace lenslab::gltf {

std::optional<PunctualLight> placedLight(const tinygltf::Model& model, const tinygltf::Node& node, int nodeIndex,
                                         const glm::dmat4& worldFromNode) {
  const auto found = node.extensions.find("KHR_lights_punctual");
  if (found == node.extensions.end()) return std::nullopt;
  const tinygltf::Value& reference = found->second.Get("light");
  if (!reference.IsNumber() || reference.GetNumberAsDouble() != std::floor(reference.GetNumberAsDouble()))
    refuse("node ", nodeIndex, " KHR_lights_punctual.light must be an integer index into the file's lights");
  const double indexValue = reference.GetNumberAsDouble();
  if (!(indexValue >= 0.0 && indexValue < static_cast<double>(model.lights.size())))
    refuse("node ", nodeIndex, " KHR_lights_punctual.light is ", indexValue, "; the file has ", model.lights.size(),
           " lights (valid: 0 to ", static_cast<long>(model.lights.size()) - 1, ")");
  const int index = static_cast<int>(indexValue);
  const tinygltf::Light& l = model.lights[toIndex(index)];
  const auto field = [&](const char* name) {
    return cat("light ", index, l.name.empty() ? "" : cat(" \"", excerpt(l.name), "\""), " ", name);
  };

  PunctualLight light;
  light.name = l.name;
  light.gltfNode = nodeIndex;
  if (l.type == "directional")
    light.type = LightType::Directional;
  else if (l.type == "point")
    light.type = LightType::Point;
  else if (l.type == "spot")
    light.type = LightType::Spot;
  else
    refuse(field("type"), " is \"", excerpt(l.type), "\"; give directional, point or spot");
  if (!l.color.empty()) {
    if (l.color.size() != 3)
      refuse(field("color"), " has ", l.color.size(), " numbers; give 3 (linear RGB, each in [0, 1])");
    for (int c = 0; c < 3; ++c)
      if (!(l.color[toIndex(c)] >= 0.0 && l.color[toIndex(c)] <= 1.0))
        refuse(field("color"), "[", c, "] is ", l.color[toIndex(c)], "; give a number in [0, 1]");
    light.color =
        glm::vec3(static_cast<float>(l.color[0]), static_cast<float>(l.color[1]), static_cast<float>(l.color[2]));
  }
  if (const std::optional<std::string> problem = numberProblem(l.intensity, NumberRange{0.0, kMaxRadiance, ""}))
    refuse(field("intensity"), ": ", *problem, " (a float's largest; lux for directional, candela for point and spot)");
  light.intensity = static_cast<float>(l.intensity);
  if (!(l.range >= 0.0) || !std::isfinite(l.range))
    refuse(field("range"), " is ", l.range, "; give a finite distance > 0, or leave it out for no range");
  if (light.type != LightType::Directional) light.range = l.range;
  if (light.type == LightType::Spot) {
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    constexpr double kHalfPi = 1.5707963267948966;
    if (!(outer > 0.0 && outer <= kHalfPi))
      refuse(field("spot.outerConeAngle"), " is ", outer, "; give an angle in (0, pi/2] radians");
    if (!(inner >= 0.0 && inner < outer))
      refuse(field("spot.innerConeAngle"), " is ", inner, "; give an angle in [0, outerConeAngle = ", outer,
             ") radians");
    light.innerConeAngleRadians = static_cast<float>(inner);
    light.outerConeAngleRadians = static_cast<float>(outer);
  }
  light.worldPosition = glm::dvec3(worldFromNode[3]);
  const glm::dvec3 shines(worldFromNode * glm::dvec4(0.0, 0.0, -1.0, 0.0));
  const double length = glm::length(shines);
  if (light.type != LightType::Point && (!(length > 0.0) || !std::isfinite(length)))
    refuse("node ", nodeIndex, " (", field("type"), " ", l.type,
           "): its world transform scales −Z to nothing, so the light has no direction; give the node and its parents "
           "a non-zero scale");
  if (length > 0.0 && std::isfinite(length)) light.worldDirection = shines / length;
  return light;
}

}  // namespace lenslab::gltf
