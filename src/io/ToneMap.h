#pragma once
// From a render's linear radiance to the values of an 8-bit image: an exposure (a scale) and a
// view transform, then the sRGB encoding. The EXR holds the radiance itself and none of this;
// PNG files and the viewer's window go through it (docs/exposure.md).
//
// The view transforms are one definition, shaders/common/view_transform.glsl, compiled here as C++
// and included by the viewer's display shader.
#include "camera/Exposure.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace lenslab {

// The values are the GLSL file's kViewTransform* numbers (the display shader's uniform).
enum class ViewTransform : int {
  None = 0,        // clip each channel at 1
  PbrNeutral = 1,  // Khronos PBR Neutral
};

// "none" or "pbr-neutral".
std::string_view viewTransformName(ViewTransform transform);
// The transform named `name`, or nullopt.
std::optional<ViewTransform> viewTransformNamed(std::string_view name);
// "none, pbr-neutral", for help and messages.
std::string viewTransformNames();

// Khronos PBR Neutral of linear RGB (view_transform.glsl's pbrNeutral).
glm::vec3 pbrNeutral(glm::vec3 linear);

// How an image's linear values become display values. The default changes nothing but the clip
// at 1: PNG files are then what they always were.
struct DisplayEncoding {
  float exposureScale = 1.0f;  // multiplies the linear radiance first (camera/Exposure.h)
  ViewTransform transform = ViewTransform::None;

  bool isIdentity() const { return exposureScale == 1.0f && transform == ViewTransform::None; }
};

// Display-referred linear RGB in [0, 1]: the view transform of exposureScale × linear.
glm::vec3 displayLinear(glm::vec3 linear, const DisplayEncoding& encoding);
// As displayLinear, then sRGB-encoded (what an 8-bit PNG holds, over 255).
glm::vec3 displayEncoded(glm::vec3 linear, const DisplayEncoding& encoding);

// A run's exposure (resolveExposure: the command line over the camera's physical settings) and
// view transform, and the encoding they make.
struct DisplaySettings {
  Exposure exposure;
  DisplayEncoding encoding;
};
// Throws InputError naming the option or field (resolveExposure's), or --view-transform for an
// unknown name.
DisplaySettings resolveDisplay(const ExposureRequest& request, std::string_view viewTransform,
                               const SelectedCamera& camera);

}  // namespace lenslab
