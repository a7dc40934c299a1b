#pragma once
// The widgets of the viewer's panel (view/ViewerPanel*.cpp): each checks itself against the
// panel's width as it is drawn (PanelFit.h), so that a narrow window never cuts text off on the
// right. Shared by the panel's files, one per group of sections.
#include "view/PanelFit.h"

#include <glm/glm.hpp>
#include <imgui.h>

#include <cfloat>
#include <string>

namespace lenslab::view {

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
bool checkbox(PanelFit& fit, const char* label, bool* value);
bool button(PanelFit& fit, const char* label);
// Numbers in fields, each checked to show whole in its field.
bool dragDoubles(PanelFit& fit, const char* label, double* v, int n, float speed, const char* format = "%.4g");
bool dragDouble3(PanelFit& fit, const char* label, glm::dvec3& v, float speed);
bool dragDouble(PanelFit& fit, const char* label, double& v, float speed, double lo, double hi,
                const char* format = "%.4g");
// Prose and figures, wrapped at the panel's edge: nothing to cut.
void wrapped(const std::string& text);
void wrappedColoured(const ImVec4& colour, const std::string& text);
// A line that must not wrap (a row of numbers), checked against the width left.
void line(PanelFit& fit, const std::string& text);
// A section header: its title is drawn inside a full-width frame after the arrow.
bool header(PanelFit& fit, const char* title, ImGuiTreeNodeFlags flags = 0);
// A number as the panel shows it: four significant digits.
std::string number(double v);
// A 4x4 matrix in four columns that share the width, each number checked against its cell.
void matrixTable(PanelFit& fit, const char* name, const glm::dmat4& m);

}  // namespace lenslab::view
