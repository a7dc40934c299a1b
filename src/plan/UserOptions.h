#pragma once
// What a user asks of a frame in words (the command line's strings; the view's panel edits the
// same), turned into the plan's options and the camera: aperture pattern, sample count, seed,
// focus, background. No command-line library here: src/app registers these as options.
#include "camera/Camera.h"
#include "camera/PhysicalCamera.h"
#include "plan/FramePlan.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace lenslab {

struct LensOptions {
  std::string pattern;                 // empty: sobol (docs/sampling.md)
  std::optional<double> targetPsnrDb;  // per-tile budgets to this estimated PSNR
  std::string apertureSamples = "auto";
  int maxSamples = 256;
  std::uint32_t seed = 1;
  std::string focusDistance;          // a number or "infinity"; empty = the camera's
  std::optional<glm::dvec2> focusAt;  // pixel (x, y), from "X,Y"
  std::optional<int> blades;          // the aperture's blades (0: round), over the camera's
  std::optional<double> squeeze;      // the aperture's anamorphic squeeze, over the camera's
  std::string cellFilter;             // "on", "off", or empty: the plan's choice (off)
};

// Throws InputError for a bad pattern or sample count.
PlanOptions toPlanOptions(const LensOptions& options);

// The focus distance applied to the camera, along the same validation path as a camera file's
// focus_distance (see refocused(SelectedCamera)); then --blades and --squeeze over the camera's
// aperture shape (lens/ApertureShape.h), refused in one line naming the option when out of range.
SelectedCamera applyLensOptions(const SelectedCamera& camera, const LensOptions& options);
// --blades and --squeeze alone over `aperture` (capture: each frame's camera), refused alike.
ApertureShape withApertureOptions(ApertureShape aperture, const LensOptions& options);

// The background colour (linear RGB) where no surface is seen, replacing the scene's.
void applyBackground(Scene& scene, const std::optional<glm::vec3>& background);

}  // namespace lenslab
