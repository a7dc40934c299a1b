#include "app/LensRequest.h"

#include "camera/LensFitCamera.h"
#include "camera/ViewSpec.h"
#include "core/Error.h"
#include "core/Text.h"
#include "core/TextFile.h"
#include "lens/ParaxialLens.h"

#include <cmath>
#include <cstdio>

namespace lenslab {

CameraOptions framingForLens(CameraOptions options, const std::string& file, const Scene& scene, bool cameraFile) {
  if (file.empty() || cameraFile || options.namesBaseCamera() || !scene.cameras.empty() || options.focalLengthMm)
    return options;
  options.focalLengthMm = firstOrder(parseLensPrescription(readTextFile(file, "lens file"), file)).focalLengthMm;
  return options;
}

LensRequest lensRequestFor(const std::string& file, const SelectedCamera& selected, const Camera& camera) {
  const auto refuse = [&](const std::string& why) { throw InputError(cat("--lens ", file, ": ", why)); };
  if (camera.view.projection != Projection::Perspective) refuse("a real lens needs a perspective camera");
  if (!camera.lens.effects.isZero())
    refuse(
        "the camera's lens effects (distortion, chromatic, field_curvature, vignetting) stand for a lens; the "
        "prescription has its own: "
        "remove them from the camera");
  if (camera.lens.barrel.present())
    refuse("the camera's \"barrel\" stands for a lens's rims; the prescription has its own: remove it");
  if (!camera.lens.aperture.isRound()) refuse("the prescription's stop is round: remove --blades and --squeeze");
  const Window& w = camera.view.window;
  const double centreU = 0.5 * (w.umin + w.umax) - camera.view.prp.x,
               centreV = 0.5 * (w.vmin + w.vmax) - camera.view.prp.y;
  if (std::abs(centreU) > 1e-9 * w.width() || std::abs(centreV) > 1e-9 * w.height())
    refuse(
        "the camera's window is shifted off its axis (a shift lens); a prescription's sensor is centred on the axis");
  LensRequest r;
  r.lens = std::make_shared<LensPrescription>(parseLensPrescription(readTextFile(file, "lens file"), file));
  r.settings.sensorMm =
      selected.physical ? selected.physical->sensorMm : glm::dvec2(36.0, 36.0 * w.height() / w.width());
  if (selected.physical && std::isfinite(selected.physical->fNumber)) r.settings.fNumber = selected.physical->fNumber;
  r.settings.focusDistance = camera.focusDistance();
  const ViewBasis basis = viewBasis(camera.view);
  r.pose.eye = prpWorld(camera.view);
  r.pose.right = basis.u;
  r.pose.up = basis.v;
  r.pose.forward = -basis.n;
  r.pose.worldPerMm = kMetresPerMillimetre;
  return r;
}

LensCamera lensCameraFor(const LensRequest& r) { return LensCamera(r.lens, r.settings, r.pose); }

FittedLens fitFor(const LensRequest& r) {
  LensFitSettings s;
  s.sensorMm = r.settings.sensorMm;
  s.fNumber = r.settings.fNumber;
  s.focusDistanceMm = r.settings.focusDistance / r.pose.worldPerMm;
  return fitLens(*r.lens, s);
}

double fitErrorPx(const FittedLens& fit, const LensRequest& r, int widthPx) {
  return fit.usable ? fit.error.worstUm() * 1e-3 / (r.settings.sensorMm.x / widthPx) : INFINITY;
}

Camera fittedCameraFor(const LensRequest& r, const FittedLens& fit, const Camera& camera, const std::string& file) {
  return cameraForFittedLens(camera, fit, r.settings.sensorMm, r.pose.worldPerMm,
                             cat(camera.source, " through ", file, " (fitted)"));
}

FocusExplanation focusExplanation(const LensRequest& r, const FittedLens& fit) {
  FocusExplanation e;
  e.askedDistance = r.settings.focusDistance;
  const double asked = 1.0 / r.settings.focusDistance, fitted = fit.inverseFocusPerMm / r.pose.worldPerMm;
  if (std::abs(fitted - asked) <= 0.005 * std::max(asked, fitted)) return e;
  const auto distance = [](double inverse) {
    if (!(inverse > 0.0)) return std::string("infinity");
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", 1.0 / inverse);
    return std::string(text);
  };
  e.note =
      cat("asked focus ", distance(asked),
          ": the film is placed where the lens's first-order (paraxial) image of that plane lies; its traced "
          "rays at ",
          r.settings.fNumber ? cat("f/", *r.settings.fNumber) : std::string("the full opening"),
          " come to their best focus on the axis (of the focal surface fitted over the field) at ", distance(fitted),
          ": the lens's aberrations (spherical aberration, field curvature) move best focus from the paraxial "
          "one, and the fitted thin lens focuses where the real lens is sharpest");
  return e;
}

std::vector<std::pair<std::string, Camera>> fittedCameraAblations(const Camera& fitted) {
  std::vector<std::pair<std::string, Camera>> out;
  const auto without = [&](const std::string& name, bool present, auto leaveOut) {
    if (!present) return;
    Camera c = fitted;
    leaveOut(c);
    out.emplace_back(name, c);
  };
  const LensEffects& e = fitted.lens.effects;
  without("distortion", !e.distortion.isZero(), [](Camera& c) { c.lens.effects.distortion = {}; });
  without("colour", e.chromatic.hasLateral() || e.chromatic.hasAxial(),
          [](Camera& c) { c.lens.effects.chromatic = {}; });
  without("field-curvature", !e.fieldCurvature.isZero(), [](Camera& c) { c.lens.effects.fieldCurvature = {}; });
  without("barrel", fitted.lens.barrel.present(), [](Camera& c) { c.lens.barrel = {}; });
  without("vignetting", !e.vignetting.isZero(), [](Camera& c) { c.lens.effects.vignetting = {}; });
  return out;
}

}  // namespace lenslab
