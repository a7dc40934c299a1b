#include "view/PanelWidgets.h"

#include <cstdio>

namespace lenslab::view {

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
bool dragDoubles(PanelFit& fit, const char* label, double* v, int n, float speed, const char* format) {
  return labelled(fit, label, [&](const char* id) {
    fit.checkFields(label, v, n, format);
    return ImGui::DragScalarN(id, ImGuiDataType_Double, v, n, speed, nullptr, nullptr, format);
  });
}
bool dragDouble3(PanelFit& fit, const char* label, glm::dvec3& v, float speed) {
  return dragDoubles(fit, label, &v.x, 3, speed);
}
bool dragDouble(PanelFit& fit, const char* label, double& v, float speed, double lo, double hi, const char* format) {
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
bool header(PanelFit& fit, const char* title, ImGuiTreeNodeFlags flags) {
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

}  // namespace lenslab::view
