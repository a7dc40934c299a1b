#include "plan/UserOptions.h"

#include "camera/LensMap.h"
#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"
#include "lens/AperturePattern.h"

#include <array>
#include <charconv>
#include <exception>
#include <limits>
#include <string>

namespace lenslab {

PlanOptions toPlanOptions(const LensOptions& o) {
  PlanOptions p;
  const std::string name = !o.pattern.empty() ? o.pattern : "sobol";
  const auto pattern = patternFromName(name);
  if (!pattern) throw InputError(cat("--pattern ", o.pattern, ": use one of ", patternNames()));
  p.pattern = *pattern;
  if (o.targetPsnrDb) {
    if (!(*o.targetPsnrDb >= 10.0 && *o.targetPsnrDb <= 100.0))
      throw InputError(cat("--target-psnr ", *o.targetPsnrDb, ": give a PSNR from 10 to 100 dB"));
    if (p.pattern != AperturePattern::Sobol)
      throw InputError(
          cat("--pattern ", o.pattern,
              ": --target-psnr stops tiles early, which needs the progressive order "
              "(every prefix well spread) and its two independent streams: use --pattern sobol or leave it out"));
    if (o.apertureSamples != "auto")
      throw InputError(cat("--aperture-samples ", o.apertureSamples,
                           ": --target-psnr chooses each tile's count; give "
                           "one or the other (--max-samples caps the tiles)"));
    p.targetPsnrDb = o.targetPsnrDb;
  }
  // The command line has checked it (auto, or a whole number from 1 to 65536); the panel and
  // tests set it directly.
  if (o.apertureSamples != "auto") {
    int n = 0;
    const char* end = o.apertureSamples.data() + o.apertureSamples.size();
    const auto [stop, error] = std::from_chars(o.apertureSamples.data(), end, n);
    if (error != std::errc() || stop != end || n < 1 || n > 65536)
      throw InputError(cat("--aperture-samples ", o.apertureSamples, ": give a whole number from 1 to 65536, or auto"));
    p.apertureSamples = n;
    // The lecture's pattern is its 17 points: another count would be ignored in silence.
    if (p.pattern == AperturePattern::Lecture17 && n != 17)
      throw InputError(cat("--aperture-samples ", n,
                           ": --pattern lecture17 is the lecture's 17 points, always 17 views; give 17 or leave "
                           "--aperture-samples out (or another --pattern for ",
                           n, " views)"));
  }
  if (o.cellFilter == "on" || o.cellFilter == "off")
    p.cellFilter = o.cellFilter == "on";
  else if (!o.cellFilter.empty())
    throw InputError(cat("--cell-filter ", o.cellFilter, ": give on or off"));
  p.maxSamples = o.maxSamples;
  p.seed = o.seed;
  return p;
}

ApertureShape withApertureOptions(ApertureShape a, const LensOptions& o) {
  if (o.blades) a.blades = *o.blades;
  if (o.squeeze) a.anamorphicSqueeze = *o.squeeze;
  if (const std::optional<ApertureProblem> problem = apertureShapeProblem(a)) {
    const bool blades = problem->field == "blades";
    if (blades && o.blades) throw InputError(cat("--blades ", problem->message));
    if (problem->field == "anamorphic_squeeze" && o.squeeze) throw InputError(cat("--squeeze ", problem->message));
  }
  return a;
}

std::string describeLensEffectOptions(const LensOptions& o) {
  const auto list = [](const std::vector<double>& values) {
    std::string text;
    for (const double v : values) text += cat(text.empty() ? "" : ",", numberText(v));
    return text;
  };
  std::string text;
  if (!o.distortion.empty()) text += cat("--distortion ", list(o.distortion));
  if (!o.fisheye.empty()) text += cat(text.empty() ? "" : " ", "--fisheye ", list(o.fisheye));
  if (!o.lateralColor.empty()) text += cat(text.empty() ? "" : " ", "--lateral-color ", list(o.lateralColor));
  if (o.axialAbbe) text += cat(text.empty() ? "" : " ", "--axial-color ", numberText(*o.axialAbbe));
  return text;
}

LensEffects withLensEffectOptions(LensEffects e, const LensOptions& o, std::optional<double> focalLength,
                                  const std::string& camera) {
  if (o.distortion.size() > kOpenCvDistortionTerms)
    throw InputError(
        cat("--distortion: ", o.distortion.size(), " numbers; give 1 to ", kOpenCvDistortionTerms,
            ", OpenCV's k1,k2,p1,p2,k3,k4,k5,k6,s1,s2,s3,s4 (a tilted sensor's tauX, tauY is not modelled)"));
  if (o.lateralColor.size() > 2)
    throw InputError(cat("--lateral-color: ", o.lateralColor.size(), " numbers; give RED or RED,BLUE"));
  if (o.fisheye.size() > 4)
    throw InputError(cat("--fisheye: ", o.fisheye.size(),
                         " numbers; give 1 to 4, the fisheye model's k1,k2,k3,k4 (OpenCV's cv::fisheye D)"));
  if (!o.distortion.empty()) e.distortion = distortionFromDistCoeffs(o.distortion);
  if (!o.fisheye.empty()) {
    e.distortion = Distortion{};
    e.distortion.fisheye = true;
    const std::array<double Distortion::*, 4> terms = {&Distortion::k1, &Distortion::k2, &Distortion::k3,
                                                       &Distortion::k4};
    for (std::size_t i = 0; i < o.fisheye.size(); ++i) e.distortion.*terms[i] = o.fisheye[i];
  }
  if (!o.lateralColor.empty()) {
    // One number: red's image larger by it and blue's smaller by as much (a simple lens's sign).
    e.chromatic.lateralRed = o.lateralColor[0];
    e.chromatic.lateralBlue = o.lateralColor.size() > 1 ? o.lateralColor[1] : -o.lateralColor[0];
  }
  if (o.axialAbbe) {
    if (!focalLength)
      throw InputError(cat("--axial-color ", *o.axialAbbe, ": an Abbe number needs the lens's focal length, which ",
                           camera,
                           " does not give (it is not in the physical form); use a camera in the physical form, or set "
                           "\"chromatic\": {\"focus_distance_red\", \"focus_distance_blue\"} in a camera file"));
    const std::array<double, 2> shifts = inverseFocusShiftsFromAbbe(*o.axialAbbe, *focalLength);
    e.chromatic.inverseFocusShiftRed = shifts[0];
    e.chromatic.inverseFocusShiftBlue = shifts[1];
  }
  return e;
}

namespace {

// --blades / --squeeze and the lens-effect options (--distortion, --lateral-color, ...) over the camera's.
SelectedCamera withApertureAndEffectOptions(SelectedCamera c, const LensOptions& o) {
  c.camera.lens.aperture = withApertureOptions(c.camera.lens.aperture, o);
  if (o.changesLensEffects()) {
    const std::optional<double> focalLength =
        c.physical ? std::optional<double>(c.physical->focalLengthMm * kMetresPerMillimetre) : std::nullopt;
    c.camera.lens.effects = withLensEffectOptions(c.camera.lens.effects, o, focalLength, c.camera.source);
    // Every later message about the lens (a fold, the raster's linearisation) names the options.
    c.camera.source += cat(" with ", describeLensEffectOptions(o));
    validateLensEffects(c.camera, c.camera.source, focalLength);
  }
  return c;
}

}  // namespace

SelectedCamera applyLensOptions(const SelectedCamera& camera, const LensOptions& o) {
  if (o.focusDistance.empty()) return withApertureAndEffectOptions(camera, o);
  const double d = o.focusDistance == "infinity"
                       ? std::numeric_limits<double>::infinity()
                       : readNumber("--focus-distance", o.focusDistance, {.unit = "world units"});
  SelectedCamera c = refocused(camera, d, "--focus-distance");
  c.camera.source += cat(", refocused to ", o.focusDistance);
  return withApertureAndEffectOptions(c, o);
}

void applyBackground(Scene& scene, const std::optional<glm::vec3>& background) {
  if (background) scene.lighting.background = *background;
}

}  // namespace lenslab
