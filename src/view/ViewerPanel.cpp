// lenslab view: the Dear ImGui panel, one function per section (progress, the viewing
// description and its matrices, comparison and outside view, saving, display, controls; the lens's
// sections are in ViewerPanelLens.cpp, the widgets in PanelWidgets.h). Edits go to the model
// (ViewerModel.h), which checks them and marks the accumulation for a restart.
#include "view/Viewer.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "view/PanelWidgets.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cmath>
#include <limits>

namespace lenslab::view {

void Viewer::sectionProgress() {
  const ImVec4 amber(1.0f, 0.8f, 0.3f, 1.0f);
  if (renderer_.adaptive()) {
    // Per-tile budgets: the estimate (against the image's own converged limit) and the target.
    const FrameEstimate e = renderer_.estimate();
    const double target = model_.plan().adaptive->targetPsnrDb;
    const std::string overlay = cat(std::round(e.psnrDb * 10.0) / 10.0, " dB of ", target, " dB (estimate)");
    fit_.checkText(overlay.c_str(), 2.0f * ImGui::GetStyle().FramePadding.x);
    ImGui::ProgressBar(static_cast<float>(std::clamp(e.psnrDb / target, 0.0, 1.0)), ImVec2(-FLT_MIN, 0),
                       overlay.c_str());
    wrapped(cat(std::round(e.meanSamples * 10.0) / 10.0, " samples per pixel (", e.minSamples, " to ", e.maxSamples,
                " per tile), ", e.tilesActive, " of ", e.tiles, " tiles going, round ", e.rounds));
    if (renderer_.done() && !e.targetMet) wrappedColoured(amber, "stopped at max samples short of the target");
  } else {
    const int done = renderer_.samplesDone(), planned = renderer_.samplesPlanned();
    const std::string overlay = cat(done, " / ", planned, " samples");
    fit_.checkText(overlay.c_str(), 2.0f * ImGui::GetStyle().FramePadding.x);
    ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(std::max(planned, 1)), ImVec2(-FLT_MIN, 0),
                       overlay.c_str());
  }
  const SampleBudget& budget = model_.budget();
  char text[160];
  std::snprintf(text, sizeof text, "%.2f ms per sample, %.0f ms accumulated", budget.msPerSample(),
                budget.accumulationMs());
  wrapped(text);
  if (budget.convergedAfterMs() >= 0.0)
    std::snprintf(text, sizeof text, "converged %.0f ms after the last change", budget.convergedAfterMs());
  else
    std::snprintf(text, sizeof text, "converging (%.1f fps)", static_cast<double>(ImGui::GetIO().Framerate));
  wrapped(text);
  if (showBaseline_) wrappedColoured(amber, cat("showing the post-process baseline (", baselineTaps_, " taps)"));
  const Camera& c = model_.camera().camera;
  wrapped(cat("image ", model_.size().widthPx, " x ", model_.size().heightPx, "; focus distance ",
              number(c.focusDistance())));
}

void Viewer::sectionLecture() {
  if (!header(fit_, "Viewing description (lecture)", openFlags(true))) return;
  Camera c = model_.camera().camera;
  ViewSpec& s = c.view;
  const float step = static_cast<float>(0.005 * std::max(1.0, s.prp.z));
  bool changed = false;
  int projection = s.projection == Projection::Perspective ? 0 : 1;
  if (labelled(fit_, "projection",
               [&](const char* id) { return ImGui::Combo(id, &projection, "perspective\0parallel\0"); })) {
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
  changed |= dragDouble(fit_, "aperture radius", c.lens.apertureRadius, step * 0.01f, 0.0, 1e6);
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
  if (s.projection == Projection::Perspective)
    matrixTable(fit_, "lecture perspective (1/f)", lecturePerspective(s.prp.z));
  matrixTable(fit_, "clipFromEye (reverse-Z)", clipFromEye(s));
  matrixTable(fit_, "clipFromWorld", clipFromWorld(s));
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
    wrapped(
        "The lecture's diagram. Yellow: PRP. White: window on the view plane (plane of focus). Grey: view volume. "
        "Cyan: aperture; orange: samples done. Red: rays through the window centre.");
    bool enlarge = model_.enlargeAperture();
    if (checkbox(fit_, "enlarge the aperture", &enlarge)) model_.setEnlargeAperture(enlarge);
    const Camera& c = model_.camera().camera;
    if (enlarge && !c.lens.isPinhole())
      wrapped(cat("aperture drawn x", std::round(model_.diagramApertureScale()), " (radius ",
                  number(c.lens.apertureRadius), ")"));
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
  if (pathAndButton("##window", windowPath_, "Save window"))
    saveWindowPending_ = true;  // read once this frame is drawn
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
        return ImGui::Combo(id, &transform, name, const_cast<std::vector<std::string>*>(&names),
                            static_cast<int>(names.size()));
      }))
    display_.encoding.transform = static_cast<ViewTransform>(transform);
  wrapped(cat("starting exposure: ", describe(display_.exposure),
              ". Save image writes a PNG as shown; an EXR holds the "
              "linear radiance."));
}

void Viewer::sectionHelp() {
  if (!header(fit_, "Controls", openFlags(false))) return;
  wrapped(
      "Click the image: focus there. Left drag: orbit about the focus point. Right drag: look around from the PRP. "
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
