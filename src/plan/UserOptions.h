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
#include <vector>

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
  // The lens effects over the camera's (lens/LensEffects.h), each replacing that effect:
  std::vector<double> distortion;    // --distortion: OpenCV's distCoeffs (1 to 12 numbers, missing ones 0)
  std::vector<double> fisheye;       // --fisheye: OpenCV's fisheye model's k1..k4 (1 to 4 numbers)
  std::vector<double> lateralColor;  // --lateral-color RED[,BLUE]: magnification of red and blue over green
  std::optional<double> axialAbbe;   // --axial-color ABBE: the glass's Abbe number

  bool changesLensEffects() const {
    return !distortion.empty() || !fisheye.empty() || !lateralColor.empty() || axialAbbe.has_value();
  }
};

// Throws InputError for a bad pattern or sample count.
PlanOptions toPlanOptions(const LensOptions& options);

// The focus distance applied to the camera, along the same validation path as a camera file's
// focus_distance (see refocused(SelectedCamera)); then --blades and --squeeze over the camera's
// aperture shape (lens/ApertureShape.h), refused in one line naming the option when out of range.
SelectedCamera applyLensOptions(const SelectedCamera& camera, const LensOptions& options);
// --blades and --squeeze alone over `aperture` (capture: each frame's camera), refused alike.
ApertureShape withApertureOptions(ApertureShape aperture, const LensOptions& options);
// --distortion (or --fisheye), --lateral-color and --axial-color over `effects`, each replacing its
// effect (the lecture's distortion series too: --distortion is OpenCV's whole model, --fisheye its
// fisheye model). --axial-color's Abbe
// number needs the lens's focal length (world units), which a camera in the physical form has;
// without it the option is refused in one line naming `camera` and the camera file's keys that
// set the axial colour instead. What the effects do to the image (a fold, a finite coefficient)
// is checked where every camera's effects are (camera/LensMap.h).
LensEffects withLensEffectOptions(LensEffects effects, const LensOptions& options, std::optional<double> focalLength,
                                  const std::string& camera);
// The lens-effect options given, as typed ("--distortion -0.2,0.05 --axial-color 40"), for messages.
std::string describeLensEffectOptions(const LensOptions& options);

// The background colour (linear RGB) where no surface is seen, replacing the scene's.
void applyBackground(Scene& scene, const std::optional<glm::vec3>& background);

}  // namespace lenslab
