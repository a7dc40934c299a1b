#include "view/PanelFit.h"

#include <algorithm>
#include <cstdio>

namespace lenslab::view {
namespace {

// The panel's visible right edge in screen coordinates: its content region, scroll bar excluded.
float rightEdge() { return ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x; }

// Half a pixel of slack: ImGui rounds item positions, and an item that ends on the edge is whole.
constexpr float kSlackPx = 0.5f;

}  // namespace

void PanelFit::beginFrame() { clipped_ = 0; }

void PanelFit::count(const char* what, float overflowPx) {
  ++clipped_;
  if (first_.empty()) first_ = what;
  overflowPx_ = std::max(overflowPx_, overflowPx);
}

void PanelFit::check(const char* what) {
  const float over = ImGui::GetItemRectMax().x - rightEdge();
  if (over > kSlackPx) count(what, over);
}

void PanelFit::checkText(const char* text, float framePx) {
  const float over = ImGui::CalcTextSize(text).x + framePx - ImGui::GetContentRegionAvail().x;
  if (over > kSlackPx) count(text, over);
}

void PanelFit::checkFields(const char* what, const double* values, int fields, const char* format) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float field =
      (ImGui::CalcItemWidth() - static_cast<float>(fields - 1) * style.ItemInnerSpacing.x) / static_cast<float>(fields);
  float worst = 0.0f;
  for (int i = 0; i < fields; ++i) {
    char text[64];
    std::snprintf(text, sizeof text, format, values[i]);
    worst = std::max(worst, ImGui::CalcTextSize(text).x + 2.0f * style.FramePadding.x - field);
  }
  if (worst > kSlackPx) count(what, worst);
}

void PanelFit::endFrame() { most_ = std::max(most_, clipped_); }

}  // namespace lenslab::view
