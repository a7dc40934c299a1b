// lenslab view: the Dear ImGui panel, one function per section (progress, the viewing
// description and its matrices, the physical lens, aperture samples, lens effects, comparison and
// outside view, saving, controls). Edits go to the model (ViewerModel.h), which checks them and
// marks the accumulation for a restart.
#include "view/Viewer.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace lenslab::view {
namespace {

bool dragDouble3(const char* label, glm::dvec3& v, float speed) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, &v.x, 3, speed, nullptr, nullptr, "%.4g");
}
bool dragDouble(const char* label, double& v, float speed, double lo, double hi, const char* format = "%.4g") {
  return ImGui::DragScalar(label, ImGuiDataType_Double, &v, speed, &lo, &hi, format, ImGuiSliderFlags_AlwaysClamp);
}
void matrixTable(const char* name, const glm::dmat4& m) {
  ImGui::TextUnformatted(name);
  for (int row = 0; row < 4; ++row)  // GLM is column-major: m[column][row]
    ImGui::Text("  %9.4f %9.4f %9.4f %9.4f", m[0][row], m[1][row], m[2][row], m[3][row]);
}

}  // namespace

void Viewer::sectionProgress() {
  if (renderer_.adaptive()) {
    // Per-tile budgets: the estimate (against the image's own converged limit) and the target.
    const FrameEstimate e = renderer_.estimate();
    const double target = model_.plan().adaptive->targetPsnrDb;
    ImGui::ProgressBar(static_cast<float>(std::clamp(e.psnrDb / target, 0.0, 1.0)), ImVec2(-FLT_MIN, 0),
                       cat(std::round(e.psnrDb * 10.0) / 10.0, " dB of ", target, " dB (estimate)").c_str());
    ImGui::Text("%.1f samples per pixel (%d to %d per tile), %d of %d tiles going, round %d", e.meanSamples, e.minSamples,
                e.maxSamples, e.tilesActive, e.tiles, e.rounds);
    if (renderer_.done() && !e.targetMet)
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "stopped at max samples short of the target");
  } else {
    const int done = renderer_.samplesDone(), planned = renderer_.samplesPlanned();
    ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(std::max(planned, 1)), ImVec2(-FLT_MIN, 0),
                       cat(done, " / ", planned, " samples").c_str());
  }
  const SampleBudget& budget = model_.budget();
  ImGui::Text("%.2f ms per sample, %.0f ms accumulated", budget.msPerSample(), budget.accumulationMs());
  if (budget.convergedAfterMs() >= 0.0) ImGui::Text("converged %.0f ms after the last change", budget.convergedAfterMs());
  else ImGui::Text("converging (%.1f fps)", static_cast<double>(ImGui::GetIO().Framerate));
  if (showBaseline_) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "showing the post-process baseline (%d taps)", baselineTaps_);
  const Camera& c = model_.camera().camera;
  ImGui::Text("image %d x %d; focus distance %.4g", model_.size().widthPx, model_.size().heightPx,
              c.focusDistance());
}

void Viewer::sectionLecture() {
  if (!ImGui::CollapsingHeader("Viewing description (lecture)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  Camera c = model_.camera().camera;
  ViewSpec& s = c.view;
  const float step = static_cast<float>(0.005 * std::max(1.0, s.prp.z));
  bool changed = false;
  int projection = s.projection == Projection::Perspective ? 0 : 1;
  if (ImGui::Combo("projection", &projection, "perspective\0parallel\0")) {
    s.projection = projection == 0 ? Projection::Perspective : Projection::Parallel;
    if (s.projection == Projection::Parallel && std::isinf(s.farDistance)) s.farDistance = 1000.0 * s.prp.z;
    if (s.projection == Projection::Parallel && c.focusAtInfinity()) c.inverseFocusOffPlane.reset();
    changed = true;
  }
  changed |= dragDouble3("VRP (world)", s.vrp, step);
  changed |= dragDouble3("VPN (world)", s.vpn, 0.005f);
  changed |= dragDouble3("VUP (world)", s.vup, 0.005f);
  changed |= dragDouble3("PRP (u, v, n)", s.prp, step);
  changed |= ImGui::DragScalarN("window", ImGuiDataType_Double, &s.window.umin, 4, step, nullptr, nullptr, "%.4g");
  changed |= dragDouble("near", s.nearDistance, step * 0.1f, 0.0, 1e9);
  bool farInfinite = std::isinf(s.farDistance);
  if (ImGui::Checkbox("far at infinity", &farInfinite)) {
    s.farDistance = farInfinite ? std::numeric_limits<double>::infinity() : 1000.0 * s.prp.z;
    changed = true;
  }
  if (!farInfinite) changed |= dragDouble("far", s.farDistance, step * 10.0f, 0.0, 1e12);
  changed |= dragDouble("aperture radius", c.apertureRadius, step * 0.01f, 0.0, 1e6);
  if (changed) model_.editLecture(c);  // checked at the restart: an invalid camera is rolled back
  // Focus distance: moves the view plane (the plane of focus), keeping the field of view.
  double focus = std::min(model_.camera().camera.focusDistance(), 1e9);
  if (dragDouble("focus distance", focus, step, 1e-4, 1e9)) model_.refocus(focus);
}

void Viewer::sectionMatrices() {
  if (!ImGui::CollapsingHeader("Matrices (clipFromWorld = clipFromEye * eyeFromView * viewFromWorld)")) return;
  const ViewSpec& s = model_.camera().camera.view;
  const ViewBasis b = viewBasis(s);
  ImGui::Text("u = (%.3f %.3f %.3f)", b.u.x, b.u.y, b.u.z);
  ImGui::Text("v = (%.3f %.3f %.3f)", b.v.x, b.v.y, b.v.z);
  ImGui::Text("n = (%.3f %.3f %.3f)", b.n.x, b.n.y, b.n.z);
  matrixTable("viewFromWorld", viewFromWorld(s));
  matrixTable("eyeFromView", eyeFromView(s));
  if (s.projection == Projection::Perspective) matrixTable("lecture perspective (1/f)", lecturePerspective(s.prp.z));
  matrixTable("clipFromEye (reverse-Z)", clipFromEye(s));
  matrixTable("clipFromWorld", clipFromWorld(s));
}

void Viewer::sectionPhysical() {
  if (!ImGui::CollapsingHeader("Physical lens", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (!model_.camera().physical) {
    ImGui::TextWrapped("The camera is in the lecture form.");
    if (!model_.canDescribeAsLens()) {
      ImGui::TextWrapped("(A physical lens needs a perspective projection with the PRP over the window centre.)");
      return;
    }
    if (ImGui::Button("Describe it as a lens (35 mm)")) model_.describeAsLens();
    return;
  }
  PhysicalCamera p = *model_.camera().physical;
  bool changed = false;
  const float step = static_cast<float>(0.005 * std::max(1.0, glm::length(p.target - p.eye)));
  changed |= dragDouble3("eye", p.eye, step);
  changed |= dragDouble3("target", p.target, step);
  changed |= dragDouble3("up", p.up, 0.005f);
  changed |= dragDouble("focal length (mm)", p.focalLengthMm, 0.2f, 1.0, 2000.0);
  changed |= ImGui::DragScalarN("sensor (mm)", ImGuiDataType_Double, &p.sensorMm.x, 2, 0.1f, nullptr, nullptr, "%.4g");
  bool pinhole = std::isinf(p.fNumber);
  if (ImGui::Checkbox("pinhole (no aperture)", &pinhole)) {
    p.fNumber = pinhole ? std::numeric_limits<double>::infinity() : 2.8;
    changed = true;
  }
  if (!pinhole) changed |= dragDouble("f-number", p.fNumber, 0.02f, 0.5, 64.0, "f/%.2f");
  bool infinityFocus = std::isinf(p.focusDistance);
  if (ImGui::Checkbox("focus at infinity", &infinityFocus)) {
    p.focusDistance = infinityFocus ? std::numeric_limits<double>::infinity() : glm::length(p.target - p.eye);
    changed = true;
  }
  if (!infinityFocus) changed |= dragDouble("focus distance (m)", p.focusDistance, step, 1e-3, 1e9);
  if (changed) model_.editPhysical(p);
}

void Viewer::sectionSamples() {
  if (!ImGui::CollapsingHeader("Aperture samples", ImGuiTreeNodeFlags_DefaultOpen)) return;
  PlanOptions o = model_.planOptions();
  const FramePlan& plan = model_.plan();
  bool changed = false;
  int pattern = static_cast<int>(o.pattern);
  static const std::vector<std::string> names = patternNameList();  // in AperturePattern's order
  const auto name = [](void* list, int i, const char** out) {
    *out = (*static_cast<const std::vector<std::string>*>(list))[static_cast<std::size_t>(i)].c_str();
    return true;
  };
  if (ImGui::Combo("pattern", &pattern, name, const_cast<std::vector<std::string>*>(&names), static_cast<int>(names.size()))) {
    o.pattern = static_cast<AperturePattern>(pattern);
    changed = true;
  }
  bool automatic = o.apertureSamples == 0;
  if (ImGui::Checkbox("auto sample count", &automatic)) {
    o.apertureSamples = automatic ? 0 : std::max(plan.apertureSamples, 1);
    changed = true;
  }
  if (automatic) {
    changed |= ImGui::SliderInt("max samples", &o.maxSamples, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  } else {
    changed |= ImGui::SliderInt("samples", &o.apertureSamples, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  }
  bool target = o.targetPsnrDb.has_value();
  if (ImGui::Checkbox("to a target PSNR (per-tile budgets)", &target)) {
    o.targetPsnrDb = target ? std::optional<double>(40.0) : std::nullopt;
    if (target) {
      o.pattern = AperturePattern::Sobol;
      o.apertureSamples = 0;
    }
    changed = true;
  }
  if (o.targetPsnrDb) {
    float db = static_cast<float>(*o.targetPsnrDb);
    if (ImGui::SliderFloat("target (dB)", &db, 20.0f, 60.0f, "%.1f")) {
      o.targetPsnrDb = db;
      changed = true;
    }
  }
  int seed = static_cast<int>(o.seed);
  if (ImGui::InputInt("seed", &seed)) {
    o.seed = static_cast<std::uint32_t>(std::max(seed, 0));
    changed = true;
  }
  if (changed) model_.setPlanOptions(o);
  ImGui::TextWrapped("N = %d: %s", plan.apertureSamples, plan.samplesWhy.c_str());
  ImGui::Text("circle of confusion in view: %.2f to %.2f px", plan.cocMinPx, plan.cocMaxPx);
}

// The lecture's last part: distortion, chromatic aberration, the curved focal plane. Each adds a
// pass or shader variant only when it is not zero; the plan's passes are listed to show it.
void Viewer::sectionLensEffects() {
  if (!ImGui::CollapsingHeader("Lens effects", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Camera& c = model_.camera().camera;
  LensEffects e = c.effects;
  bool changed = false;
  ImGui::TextWrapped("Distortion: Brown-Conrady in OpenCV's order (normalised coordinates about the principal point)");
  changed |= dragDouble("k1", e.distortion.k1, 0.002f, -2.0, 2.0);
  changed |= dragDouble("k2", e.distortion.k2, 0.002f, -2.0, 2.0);
  changed |= dragDouble("k3", e.distortion.k3, 0.002f, -2.0, 2.0);
  changed |= dragDouble("p1", e.distortion.p1, 0.0002f, -0.2, 0.2);
  changed |= dragDouble("p2", e.distortion.p2, 0.0002f, -0.2, 0.2);
  if (ImGui::TreeNode("the lecture's series: rho = rho'(1 + a rho' + b rho'^2 + c rho'^3)")) {
    changed |= dragDouble("alpha", e.distortion.alpha, 0.002f, -2.0, 2.0);
    changed |= dragDouble("beta", e.distortion.beta, 0.002f, -2.0, 2.0);
    changed |= dragDouble("gamma", e.distortion.gamma, 0.002f, -2.0, 2.0);
    ImGui::TreePop();
  }
  ImGui::TextWrapped("Chromatic aberration: lateral = red/blue magnification relative to green; axial = "
                     "each colour's plane of focus, as a change of 1/focus distance (1/world unit)");
  changed |= dragDouble("lateral red", e.chromatic.lateralRed, 0.0002f, -0.1, 0.1);
  changed |= dragDouble("lateral blue", e.chromatic.lateralBlue, 0.0002f, -0.1, 0.1);
  changed |= dragDouble("axial red (1/m)", e.chromatic.inverseFocusShiftRed, 0.002f, -10.0, 10.0);
  changed |= dragDouble("axial blue (1/m)", e.chromatic.inverseFocusShiftBlue, 0.002f, -10.0, 10.0);
  const double focus = c.inverseFocusDistance();
  const auto distance = [](double inverse) { return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity(); };
  if (e.chromatic.hasAxial())
    ImGui::Text("red in focus at %.4g, green %.4g, blue %.4g", distance(focus + e.chromatic.inverseFocusShiftRed),
                distance(focus), distance(focus + e.chromatic.inverseFocusShiftBlue));
  ImGui::TextWrapped("Field curvature: 1/focus distance grows by this times r^2 toward the corners");
  changed |= dragDouble("curvature (1/m per r^2)", e.fieldCurvature.inverseFocusPerRadius2, 0.005f, -20.0, 20.0);
  if (!e.fieldCurvature.isZero()) {
    const double corner = normalisedWindow(c.view).cornerRadius();
    ImGui::Text("centre in focus at %.4g, corners at %.4g", distance(focus),
                distance(focus + e.fieldCurvature.inverseFocusPerRadius2 * corner * corner));
  }
  if (ImGui::Button("no lens effects")) {
    e = LensEffects{};
    changed = true;
  }
  if (changed) model_.editLensEffects(e);  // checked here: an invalid lens is reported and not taken
  std::string passes;
  for (const PlannedPass& pass : model_.plan().passes) {
    passes += (passes.empty() ? "" : ", ") + pass.name;
    for (const std::string& variant : pass.variants) passes += "+" + variant;
  }
  ImGui::TextWrapped("passes: %s", passes.c_str());
  for (const std::string& warning : model_.plan().warnings) ImGui::TextWrapped("note: %s", warning.c_str());
}

void Viewer::sectionCompare() {
  if (!ImGui::CollapsingHeader("Compare and outside view", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::Checkbox("show the post-process gather baseline", &showBaseline_)) baselineValid_ = false;
  if (showBaseline_ && ImGui::SliderInt("gather taps", &baselineTaps_, 8, 128)) baselineValid_ = false;
  if (ImGui::Checkbox("outside view (the lecture's diagram)", &showOutside_)) outsideDirty_ = true;
  if (showOutside_) {
    ImGui::TextWrapped("Yellow: PRP. White: window on the view plane (plane of focus). Grey: view volume. "
                       "Cyan: aperture; orange: samples done. Red: rays through the window centre.");
    bool enlarge = model_.enlargeAperture();
    if (ImGui::Checkbox("enlarge the aperture in the diagram", &enlarge)) model_.setEnlargeAperture(enlarge);
    const Camera& c = model_.camera().camera;
    if (enlarge && !c.isPinhole())
      ImGui::Text("aperture drawn x%.0f (radius %.4g)", model_.diagramApertureScale(), c.apertureRadius);
  }
}

void Viewer::sectionFiles() {
  if (!ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::InputText("##camera", cameraPath_.data(), cameraPath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save camera")) {
    try {
      writeTextFileAtomically(cameraPath_.data(), toCameraJson(model_.camera().camera));
      status_ = cat("wrote ", cameraPath_.data(), " (lenslab render --camera loads it)");
    } catch (const std::exception& e) {
      model_.reportError(e.what());
    }
  }
  ImGui::InputText("##image", imagePath_.data(), imagePath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save image")) {
    try {
      checkImageExtension(imagePath_.data());
      writeImage(imagePath_.data(), renderer_.resolve());
      status_ = cat("wrote ", imagePath_.data(), " (", renderer_.samplesDone(), " samples)");
    } catch (const std::exception& e) {
      model_.reportError(e.what());
    }
  }
  ImGui::InputText("##window", windowPath_.data(), windowPath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save window")) saveWindowPending_ = true;  // read once this frame is drawn
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
}

void Viewer::sectionHelp() {
  if (!ImGui::CollapsingHeader("Controls")) return;
  ImGui::TextWrapped("Click the image: focus there. Left drag: orbit about the focus point. Right drag: look "
                     "around from the PRP. Wheel: move forward. W/A/S/D/Q/E: fly (Shift: faster). "
                     "Outside view: left drag orbits, wheel zooms. Ctrl+click a field to type. Esc: quit.");
}

void Viewer::panel() {
  const float width = static_cast<float>(windowWidth_) - static_cast<float>(imageRect_.x + std::max(imageRect_.width, outsideRect_.width));
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(windowWidth_) - width, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(windowHeight_)));
  ImGui::Begin("lenslab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.0f);  // room for the labels on the right
  if (!model_.error().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", model_.error().c_str());
    ImGui::PopStyleColor();
  }
  ImGui::TextWrapped("%s", model_.camera().camera.source.c_str());
  sectionProgress();
  sectionLecture();
  sectionMatrices();
  sectionPhysical();
  sectionSamples();
  sectionLensEffects();
  sectionCompare();
  sectionFiles();
  sectionHelp();
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace lenslab::view
