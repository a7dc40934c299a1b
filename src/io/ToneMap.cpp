#include "io/ToneMap.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/ImageFile.h"

#include <array>
#include <utility>

namespace lenslab {

// The GLSL, as C++: glm's names are GLSL's.
namespace glsl {
using glm::clamp;
using glm::max;
using glm::min;
using glm::mix;
using glm::vec3;
#include "../../shaders/common/view_transform.glsl"
}  // namespace glsl

namespace {

constexpr std::array<std::pair<ViewTransform, std::string_view>, 2> kNames = {{
    {ViewTransform::None, "none"},
    {ViewTransform::PbrNeutral, "pbr-neutral"},
}};

static_assert(static_cast<int>(ViewTransform::None) == glsl::kViewTransformNone);
static_assert(static_cast<int>(ViewTransform::PbrNeutral) == glsl::kViewTransformPbrNeutral);

}  // namespace

std::string_view viewTransformName(ViewTransform transform) {
  for (const auto& [t, name] : kNames)
    if (t == transform) return name;
  return "none";
}

std::optional<ViewTransform> viewTransformNamed(std::string_view name) {
  for (const auto& [t, n] : kNames)
    if (n == name) return t;
  return std::nullopt;
}

std::string viewTransformNames() {
  std::string s;
  for (const auto& [t, name] : kNames) s += (s.empty() ? "" : ", ") + std::string(name);
  return s;
}

glm::vec3 pbrNeutral(glm::vec3 linear) { return glsl::pbrNeutral(linear); }

glm::vec3 displayLinear(glm::vec3 linear, const DisplayEncoding& e) {
  return glsl::viewTransformed(e.exposureScale * linear, static_cast<int>(e.transform));
}

glm::vec3 displayEncoded(glm::vec3 linear, const DisplayEncoding& e) {
  const glm::vec3 d = displayLinear(linear, e);
  return {srgbFromLinear(d.r), srgbFromLinear(d.g), srgbFromLinear(d.b)};
}

DisplaySettings resolveDisplay(const ExposureRequest& request, std::string_view viewTransform,
                               const SelectedCamera& camera) {
  const std::optional<ViewTransform> transform = viewTransformNamed(viewTransform);
  if (!transform)
    throw InputError(cat("--view-transform ", excerpt(viewTransform), ": give one of ", viewTransformNames()));
  DisplaySettings d;
  d.exposure = resolveExposure(request, camera);
  d.encoding.exposureScale = static_cast<float>(d.exposure.scale);
  d.encoding.transform = *transform;
  return d;
}

}  // namespace lenslab
