// lenslab view: the panel's sections on the lens (ViewerPanel.cpp has the rest): the physical
// lens, the aperture samples, and the lecture's lens effects.
#include "view/Viewer.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Text.h"
#include "view/PanelWidgets.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>

namespace lenslab::view {

void Viewer::sectionPhysical() {
  if (!header(fit_, "Physical lens", openFlags(true))) return;
  if (!model_.camera().physical) {
    wrapped("The camera is in the lecture form.");
    if (!model_.canDescribeAsLens()) {
      wrapped("(A physical lens needs a perspective projection with the PRP over the window centre.)");
      return;
    }
    if (button(fit_, "Describe it as a lens (35 mm)")) model_.describeAsLens();
    return;
  }
  PhysicalCamera p = *model_.camera().physical;
  bool changed = false;
  const float step = static_cast<float>(0.005 * std::max(1.0, glm::length(p.target - p.eye)));
  changed |= dragDouble3(fit_, "eye", p.eye, step);
  changed |= dragDouble3(fit_, "target", p.target, step);
  changed |= dragDouble3(fit_, "up", p.up, 0.005f);
  changed |= dragDouble(fit_, "focal length (mm)", p.focalLengthMm, 0.2f, 1.0, 2000.0);
  changed |= dragDoubles(fit_, "sensor (mm)", &p.sensorMm.x, 2, 0.1f);
  bool pinhole = std::isinf(p.fNumber);
  if (checkbox(fit_, "pinhole (no aperture)", &pinhole)) {
    p.fNumber = pinhole ? std::numeric_limits<double>::infinity() : 2.8;
    changed = true;
  }
  if (!pinhole) changed |= dragDouble(fit_, "f-number", p.fNumber, 0.02f, 0.5, 64.0, "f/%.2f");
  bool infinityFocus = std::isinf(p.focusDistance);
  if (checkbox(fit_, "focus at infinity", &infinityFocus)) {
    p.focusDistance = infinityFocus ? std::numeric_limits<double>::infinity() : glm::length(p.target - p.eye);
    changed = true;
  }
  if (!infinityFocus) changed |= dragDouble(fit_, "focus distance (m)", p.focusDistance, step, 1e-3, 1e9);
  if (changed) model_.editPhysical(p);
}

void Viewer::sectionSamples() {
  if (!header(fit_, "Aperture samples", openFlags(true))) return;
  PlanOptions o = model_.planOptions();
  const FramePlan& plan = model_.plan();
  bool changed = false;
  int pattern = static_cast<int>(o.pattern);
  static const std::vector<std::string> names = patternNameList();  // in AperturePattern's order
  const auto name = [](void* list, int i, const char** out) {
    *out = (*static_cast<const std::vector<std::string>*>(list))[static_cast<std::size_t>(i)].c_str();
    return true;
  };
  if (labelled(fit_, "pattern", [&](const char* id) {
        return ImGui::Combo(id, &pattern, name, const_cast<std::vector<std::string>*>(&names),
                            static_cast<int>(names.size()));
      })) {
    o.pattern = static_cast<AperturePattern>(pattern);
    changed = true;
  }
  bool automatic = o.apertureSamples == 0;
  if (checkbox(fit_, "auto sample count", &automatic)) {
    o.apertureSamples = automatic ? 0 : std::max(plan.apertureSamples, 1);
    changed = true;
  }
  int& count = automatic ? o.maxSamples : o.apertureSamples;
  changed |= labelled(fit_, automatic ? "max samples" : "samples", [&](const char* id) {
    return ImGui::SliderInt(id, &count, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  });
  bool target = o.targetPsnrDb.has_value();
  if (checkbox(fit_, "to a target PSNR", &target)) {
    o.targetPsnrDb = target ? std::optional<double>(40.0) : std::nullopt;
    if (target) {
      o.pattern = AperturePattern::Sobol;
      o.apertureSamples = 0;
    }
    changed = true;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("per-tile budgets: each tile gets samples until its estimate reaches the target");
  if (o.targetPsnrDb) {
    float db = static_cast<float>(*o.targetPsnrDb);
    if (labelled(fit_, "target (dB)",
                 [&](const char* id) { return ImGui::SliderFloat(id, &db, 20.0f, 60.0f, "%.1f"); })) {
      o.targetPsnrDb = db;
      changed = true;
    }
  }
  int seed = static_cast<int>(o.seed);
  if (labelled(fit_, "seed", [&](const char* id) { return ImGui::InputInt(id, &seed); })) {
    o.seed = static_cast<std::uint32_t>(std::max(seed, 0));
    changed = true;
  }
  if (changed) model_.setPlanOptions(o);
  wrapped(cat("N = ", plan.apertureSamples, ": ", plan.samplesWhy));
  char text[96];
  std::snprintf(text, sizeof text, "circle of confusion in view: %.2f to %.2f px", plan.cocMinPx, plan.cocMaxPx);
  wrapped(text);
}

// The lecture's last part: distortion, chromatic aberration, the curved focal plane. Each adds a
// pass or shader variant only when it is not zero; the plan's passes are listed to show it.
void Viewer::sectionLensEffects() {
  if (!header(fit_, "Lens effects", openFlags(true))) return;
  const Camera& c = model_.camera().camera;
  LensEffects e = c.lens.effects;
  bool changed = false;
  wrapped("Distortion: Brown-Conrady in OpenCV's order (normalised coordinates about the principal point)");
  changed |= dragDouble(fit_, "k1", e.distortion.k1, 0.002f, -2.0, 2.0);
  changed |= dragDouble(fit_, "k2", e.distortion.k2, 0.002f, -2.0, 2.0);
  changed |= dragDouble(fit_, "k3", e.distortion.k3, 0.002f, -2.0, 2.0);
  changed |= dragDouble(fit_, "p1", e.distortion.p1, 0.0002f, -0.2, 0.2);
  changed |= dragDouble(fit_, "p2", e.distortion.p2, 0.0002f, -0.2, 0.2);
  if (scripted()) ImGui::SetNextItemOpen(true, ImGuiCond_Once);  // the whole panel in a scripted run
  const bool lectureSeries = ImGui::TreeNode("the lecture's series");
  fit_.check("the lecture's series");
  if (lectureSeries) {
    wrapped("rho = rho'(1 + a rho' + b rho'^2 + c rho'^3)");
    changed |= dragDouble(fit_, "alpha", e.distortion.alpha, 0.002f, -2.0, 2.0);
    changed |= dragDouble(fit_, "beta", e.distortion.beta, 0.002f, -2.0, 2.0);
    changed |= dragDouble(fit_, "gamma", e.distortion.gamma, 0.002f, -2.0, 2.0);
    ImGui::TreePop();
  }
  wrapped(
      "Chromatic aberration: lateral = red/blue magnification relative to green; axial = each colour's plane of "
      "focus, as a change of 1/focus distance (1/world unit)");
  changed |= dragDouble(fit_, "lateral red", e.chromatic.lateralRed, 0.0002f, -0.1, 0.1);
  changed |= dragDouble(fit_, "lateral blue", e.chromatic.lateralBlue, 0.0002f, -0.1, 0.1);
  changed |= dragDouble(fit_, "axial red (1/m)", e.chromatic.inverseFocusShiftRed, 0.002f, -10.0, 10.0);
  changed |= dragDouble(fit_, "axial blue (1/m)", e.chromatic.inverseFocusShiftBlue, 0.002f, -10.0, 10.0);
  const double focus = c.inverseFocusDistance();
  const auto distance = [](double inverse) {
    return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity();
  };
  if (e.chromatic.hasAxial())
    wrapped(cat("red in focus at ", number(distance(focus + e.chromatic.inverseFocusShiftRed)), ", green ",
                number(distance(focus)), ", blue ", number(distance(focus + e.chromatic.inverseFocusShiftBlue))));
  wrapped("Field curvature: 1/focus distance grows by this (1/m) times r^2 toward the corners");
  changed |= dragDouble(fit_, "curvature", e.fieldCurvature.inverseFocusPerRadius2, 0.005f, -20.0, 20.0);
  if (!e.fieldCurvature.isZero()) {
    const double corner = normalisedWindow(c.view).cornerRadius();
    wrapped(cat("centre in focus at ", number(distance(focus)), ", corners at ",
                number(distance(focus + e.fieldCurvature.inverseFocusPerRadius2 * corner * corner))));
  }
  if (button(fit_, "no lens effects")) {
    e = LensEffects{};
    changed = true;
  }
  if (changed) model_.editLensEffects(e);  // checked here: an invalid lens is reported and not taken
  std::string passes;
  for (const PlannedPass& pass : model_.plan().passes) {
    passes += (passes.empty() ? "" : ", ") + pass.name;
    for (const std::string& variant : pass.variants) passes += "+" + variant;
  }
  wrapped("passes: " + passes);
  for (const std::string& warning : model_.plan().warnings) wrapped("note: " + warning);
}

}  // namespace lenslab::view
