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
#include <cstdio>
#include <cmath>
#include <limits>

namespace lenslab::view {
namespace {

// Each item is checked against the panel's width as it is drawn (PanelFit.h): a narrow window must
// not cut text off on the right.
// A widget with its label on the right, or above it when the panel is too narrow for both on one
// line (fit.labelsAbove). `widget(label)` draws it under the label (an ImGui id) it is given.
template <class Widget>
bool labelled(PanelFit& fit, const char* label, Widget widget) {
  if (!fit.labelsAbove) {
    const bool changed = widget(label);
    fit.check(label);
    return changed;
  }
  ImGui::TextUnformatted(label);
  fit.check(label);
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::PushID(label);  // the widget's id: the label's, without its text
  const bool changed = widget("##v");
  ImGui::PopID();
  fit.check(label);
  return changed;
}
// A checkbox or a button: its label is its text and its id.
bool checkbox(PanelFit& fit, const char* label, bool* value) {
  const bool changed = ImGui::Checkbox(label, value);
  fit.check(label);
  return changed;
}
bool button(PanelFit& fit, const char* label) {
  const bool pressed = ImGui::Button(label);
  fit.check(label);
  return pressed;
}
// Numbers in fields, each checked to show whole in its field.
bool dragDoubles(PanelFit& fit, const char* label, double* v, int n, float speed, const char* format = "%.4g") {
  return labelled(fit, label, [&](const char* id) {
    fit.checkFields(label, v, n, format);
    return ImGui::DragScalarN(id, ImGuiDataType_Double, v, n, speed, nullptr, nullptr, format);
  });
}
bool dragDouble3(PanelFit& fit, const char* label, glm::dvec3& v, float speed) { return dragDoubles(fit, label, &v.x, 3, speed); }
bool dragDouble(PanelFit& fit, const char* label, double& v, float speed, double lo, double hi, const char* format = "%.4g") {
  return labelled(fit, label, [&](const char* id) {
    fit.checkFields(label, &v, 1, format);
    return ImGui::DragScalar(id, ImGuiDataType_Double, &v, speed, &lo, &hi, format, ImGuiSliderFlags_AlwaysClamp);
  });
}
// Prose and figures, wrapped at the panel's edge: nothing to cut.
void wrapped(const std::string& text) { ImGui::TextWrapped("%s", text.c_str()); }
void wrappedColoured(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped(text);
  ImGui::PopStyleColor();
}
// A line that must not wrap (a row of numbers), checked against the width left.
void line(PanelFit& fit, const std::string& text) {
  fit.checkText(text.c_str(), 0.0f);
  ImGui::TextUnformatted(text.c_str());
}
// A section header: its title is drawn inside a full-width frame after the arrow.
bool header(PanelFit& fit, const char* title, ImGuiTreeNodeFlags flags = 0) {
  fit.checkText(title, ImGui::GetTreeNodeToLabelSpacing() + ImGui::GetStyle().FramePadding.x);
  return ImGui::CollapsingHeader(title, flags);
}
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}
// A 4x4 matrix in four columns that share the width, each number checked against its cell.
void matrixTable(PanelFit& fit, const char* name, const glm::dmat4& m) {
  ImGui::TextUnformatted(name);
  fit.check(name);
  if (!ImGui::BeginTable(name, 4, ImGuiTableFlags_SizingStretchSame)) return;
  for (int row = 0; row < 4; ++row) {  // GLM is column-major: m[column][row]
    ImGui::TableNextRow();
    for (int column = 0; column < 4; ++column) {
      ImGui::TableNextColumn();
      line(fit, number(m[column][row]));
    }
  }
  ImGui::EndTable();
}

}  // namespace

void Viewer::sectionProgress() {
  const ImVec4 amber(1.0f, 0.8f, 0.3f, 1.0f);
  if (renderer_.adaptive()) {
    // Per-tile budgets: the estimate (against the image's own converged limit) and the target.
    const FrameEstimate e = renderer_.estimate();
    const double target = model_.plan().adaptive->targetPsnrDb;
    const std::string overlay = cat(std::round(e.psnrDb * 10.0) / 10.0, " dB of ", target, " dB (estimate)");
    fit_.checkText(overlay.c_str(), 2.0f * ImGui::GetStyle().FramePadding.x);
    ImGui::ProgressBar(static_cast<float>(std::clamp(e.psnrDb / target, 0.0, 1.0)), ImVec2(-FLT_MIN, 0), overlay.c_str());
    wrapped(cat(std::round(e.meanSamples * 10.0) / 10.0, " samples per pixel (", e.minSamples, " to ", e.maxSamples,
                " per tile), ", e.tilesActive, " of ", e.tiles, " tiles going, round ", e.rounds));
    if (renderer_.done() && !e.targetMet) wrappedColoured(amber, "stopped at max samples short of the target");
  } else {
    const int done = renderer_.samplesDone(), planned = renderer_.samplesPlanned();
    const std::string overlay = cat(done, " / ", planned, " samples");
    fit_.checkText(overlay.c_str(), 2.0f * ImGui::GetStyle().FramePadding.x);
    ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(std::max(planned, 1)), ImVec2(-FLT_MIN, 0), overlay.c_str());
  }
  const SampleBudget& budget = model_.budget();
  char text[160];
  std::snprintf(text, sizeof text, "%.2f ms per sample, %.0f ms accumulated", budget.msPerSample(), budget.accumulationMs());
  wrapped(text);
  if (budget.convergedAfterMs() >= 0.0) std::snprintf(text, sizeof text, "converged %.0f ms after the last change", budget.convergedAfterMs());
  else std::snprintf(text, sizeof text, "converging (%.1f fps)", static_cast<double>(ImGui::GetIO().Framerate));
  wrapped(text);
  if (showBaseline_) wrappedColoured(amber, cat("showing the post-process baseline (", baselineTaps_, " taps)"));
  const Camera& c = model_.camera().camera;
  wrapped(cat("image ", model_.size().widthPx, " x ", model_.size().heightPx, "; focus distance ", number(c.focusDistance())));
}

void Viewer::sectionLecture() {
  if (!header(fit_, "Viewing description (lecture)", openFlags(true))) return;
  Camera c = model_.camera().camera;
  ViewSpec& s = c.view;
  const float step = static_cast<float>(0.005 * std::max(1.0, s.prp.z));
  bool changed = false;
  int projection = s.projection == Projection::Perspective ? 0 : 1;
  if (labelled(fit_, "projection", [&](const char* id) { return ImGui::Combo(id, &projection, "perspective\0parallel\0"); })) {
    s.projection = projection == 0 ? Projection::Perspective : Projection::Parallel;
    if (s.projection == Projection::Parallel && std::isinf(s.farDistance)) s.farDistance = 1000.0 * s.prp.z;
    if (s.projection == Projection::Parallel && c.focusAtInfinity()) c.inverseFocusOffPlane.reset();
    changed = true;
  }
  changed |= dragDouble3(fit_, "VRP (world)", s.vrp, step);
  changed |= dragDouble3(fit_, "VPN (world)", s.vpn, 0.005f);
  changed |= dragDouble3(fit_, "VUP (world)", s.vup, 0.005f);
  changed |= dragDouble3(fit_, "PRP (u, v, n)", s.prp, step);
  changed |= dragDoubles(fit_, "window", &s.window.umin, 4, step);
  changed |= dragDouble(fit_, "near", s.nearDistance, step * 0.1f, 0.0, 1e9);
  bool farInfinite = std::isinf(s.farDistance);
  if (checkbox(fit_, "far at infinity", &farInfinite)) {
    s.farDistance = farInfinite ? std::numeric_limits<double>::infinity() : 1000.0 * s.prp.z;
    changed = true;
  }
  if (!farInfinite) changed |= dragDouble(fit_, "far", s.farDistance, step * 10.0f, 0.0, 1e12);
  changed |= dragDouble(fit_, "aperture radius", c.apertureRadius, step * 0.01f, 0.0, 1e6);
  if (changed) model_.editLecture(c);  // checked at the restart: an invalid camera is rolled back
  // Focus distance: moves the view plane (the plane of focus), keeping the field of view.
  double focus = std::min(model_.camera().camera.focusDistance(), 1e9);
  if (dragDouble(fit_, "focus distance", focus, step, 1e-4, 1e9)) model_.refocus(focus);
}

void Viewer::sectionMatrices() {
  if (!header(fit_, "Matrices", openFlags(false))) return;
  wrapped("clipFromWorld = clipFromEye * eyeFromView * viewFromWorld");
  const ViewSpec& s = model_.camera().camera.view;
  const ViewBasis b = viewBasis(s);
  char text[96];
  for (const auto& [name, axis] : {std::pair{"u", b.u}, std::pair{"v", b.v}, std::pair{"n", b.n}}) {
    std::snprintf(text, sizeof text, "%s = (%.3f %.3f %.3f)", name, axis.x, axis.y, axis.z);
    line(fit_, text);
  }
  matrixTable(fit_, "viewFromWorld", viewFromWorld(s));
  matrixTable(fit_, "eyeFromView", eyeFromView(s));
  if (s.projection == Projection::Perspective) matrixTable(fit_, "lecture perspective (1/f)", lecturePerspective(s.prp.z));
  matrixTable(fit_, "clipFromEye (reverse-Z)", clipFromEye(s));
  matrixTable(fit_, "clipFromWorld", clipFromWorld(s));
}

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
        return ImGui::Combo(id, &pattern, name, const_cast<std::vector<std::string>*>(&names), static_cast<int>(names.size()));
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
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("per-tile budgets: each tile gets samples until its estimate reaches the target");
  if (o.targetPsnrDb) {
    float db = static_cast<float>(*o.targetPsnrDb);
    if (labelled(fit_, "target (dB)", [&](const char* id) { return ImGui::SliderFloat(id, &db, 20.0f, 60.0f, "%.1f"); })) {
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
  LensEffects e = c.effects;
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
  wrapped("Chromatic aberration: lateral = red/blue magnification relative to green; axial = each colour's plane of "
          "focus, as a change of 1/focus distance (1/world unit)");
  changed |= dragDouble(fit_, "lateral red", e.chromatic.lateralRed, 0.0002f, -0.1, 0.1);
  changed |= dragDouble(fit_, "lateral blue", e.chromatic.lateralBlue, 0.0002f, -0.1, 0.1);
  changed |= dragDouble(fit_, "axial red (1/m)", e.chromatic.inverseFocusShiftRed, 0.002f, -10.0, 10.0);
  changed |= dragDouble(fit_, "axial blue (1/m)", e.chromatic.inverseFocusShiftBlue, 0.002f, -10.0, 10.0);
  const double focus = c.inverseFocusDistance();
  const auto distance = [](double inverse) { return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity(); };
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

void Viewer::sectionCompare() {
  if (!header(fit_, "Compare and outside view", openFlags(true))) return;
  if (checkbox(fit_, "post-process gather baseline", &showBaseline_)) baselineValid_ = false;
  if (showBaseline_) {
    if (labelled(fit_, "gather taps", [&](const char* id) { return ImGui::SliderInt(id, &baselineTaps_, 8, 128); }))
      baselineValid_ = false;
  }
  if (checkbox(fit_, "outside view (the diagram)", &showOutside_)) outsideDirty_ = true;
  if (showOutside_) {
    wrapped("The lecture's diagram. Yellow: PRP. White: window on the view plane (plane of focus). Grey: view volume. "
            "Cyan: aperture; orange: samples done. Red: rays through the window centre.");
    bool enlarge = model_.enlargeAperture();
    if (checkbox(fit_, "enlarge the aperture", &enlarge)) model_.setEnlargeAperture(enlarge);
    const Camera& c = model_.camera().camera;
    if (enlarge && !c.isPinhole())
      wrapped(cat("aperture drawn x", std::round(model_.diagramApertureScale()), " (radius ", number(c.apertureRadius), ")"));
  }
}

void Viewer::sectionFiles() {
  if (!header(fit_, "Save", openFlags(true))) return;
  // Each path field leaves room on its line for its button.
  const auto pathAndButton = [this](const char* id, std::array<char, 512>& path, const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttonWidth = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
    ImGui::SetNextItemWidth(std::max(1.0f, ImGui::GetContentRegionAvail().x - buttonWidth - style.ItemSpacing.x));
    ImGui::InputText(id, path.data(), path.size());
    ImGui::SameLine();
    return button(fit_, label);
  };
  if (pathAndButton("##camera", cameraPath_, "Save camera")) {
    try {
      writeTextFileAtomically(cameraPath_.data(), toCameraJson(model_.camera().camera));
      status_ = cat("wrote ", cameraPath_.data(), " (lenslab render --camera loads it)");
    } catch (const std::exception& e) {
      model_.reportError(e.what());
    }
  }
  if (pathAndButton("##image", imagePath_, "Save image")) {
    try {
      checkImageExtension(imagePath_.data());
      Image image = renderer_.resolve();
      applyDisplayForFile(imagePath_.data(), image, display_.encoding);  // a PNG as shown; an EXR linear
      writeImage(imagePath_.data(), image);
      status_ = cat("wrote ", imagePath_.data(), " (", renderer_.samplesDone(), " samples)");
    } catch (const std::exception& e) {
      model_.reportError(e.what());
    }
  }
  if (pathAndButton("##window", windowPath_, "Save window")) saveWindowPending_ = true;  // read once this frame is drawn
  if (!status_.empty()) wrapped(status_);
}

void Viewer::sectionDisplay() {
  if (!header(fit_, "Display", openFlags(true))) return;
  // Stops about the starting exposure (a physical one can be far from 0 EV); the slider edits the
  // scale that PNG files and the window share, and nothing is rendered again.
  static const std::vector<std::string> names = {"none", "pbr-neutral"};  // ViewTransform's order
  float stops = std::log2(display_.encoding.exposureScale);
  const float start = static_cast<float>(display_.exposure.stops);
  if (labelled(fit_, "exposure (EV)", [&](const char* id) {
        return ImGui::SliderFloat(id, &stops, start - 10.0f, start + 10.0f, "%+.2f", ImGuiSliderFlags_AlwaysClamp);
      }))
    display_.encoding.exposureScale = std::exp2(stops);
  int transform = static_cast<int>(display_.encoding.transform);
  const auto name = [](void* list, int i, const char** out) {
    *out = (*static_cast<const std::vector<std::string>*>(list))[static_cast<std::size_t>(i)].c_str();
    return true;
  };
  if (labelled(fit_, "view transform", [&](const char* id) {
        return ImGui::Combo(id, &transform, name, const_cast<std::vector<std::string>*>(&names), static_cast<int>(names.size()));
      }))
    display_.encoding.transform = static_cast<ViewTransform>(transform);
  wrapped(cat("starting exposure: ", describe(display_.exposure), ". Save image writes a PNG as shown; an EXR holds the "
              "linear radiance."));
}

void Viewer::sectionHelp() {
  if (!header(fit_, "Controls", openFlags(false))) return;
  wrapped("Click the image: focus there. Left drag: orbit about the focus point. Right drag: look around from the PRP. "
          "Wheel: move forward. W/A/S/D/Q/E: fly (Shift: faster). Outside view: left drag orbits, wheel zooms. "
          "Ctrl+click a field to type. Esc: quit.");
}

void Viewer::panel() {
  // The panel takes the right side layout() left it, whatever the image's letterboxing.
  const float width = static_cast<float>(panelWidth_);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(windowWidth_) - width, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(windowHeight_)));
  ImGui::Begin("lenslab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  fit_.beginFrame();
  // Widgets share the width with their labels on the right, which get the room the longest needs;
  // where that would leave a widget too little for its numbers (a narrow window), each label goes
  // above its widget, which then takes the whole width.
  const float labels = ImGui::CalcTextSize("focus distance (m)").x + ImGui::GetStyle().ItemInnerSpacing.x;
  fit_.labelsAbove = ImGui::GetContentRegionAvail().x - labels < 16.0f * ImGui::GetFontSize();
  ImGui::PushItemWidth(fit_.labelsAbove ? -FLT_MIN : -labels);
  if (!model_.error().empty()) wrappedColoured(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), model_.error());
  wrapped(model_.camera().camera.source);
  sectionProgress();
  sectionLecture();
  sectionMatrices();
  sectionPhysical();
  sectionSamples();
  sectionLensEffects();
  sectionDisplay();
  sectionCompare();
  sectionFiles();
  sectionHelp();
  ImGui::PopItemWidth();
  fit_.endFrame();
  ImGui::End();
}

}  // namespace lenslab::view
