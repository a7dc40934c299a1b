#pragma once
// Whether the viewer's panel shows all of its text: each frame counts the items whose text runs
// past the panel's visible right edge (cut off), for the scripted --stats, so that a test can
// ask for none at a narrow and a wide window. Call check() after an item, or checkText() for text
// drawn inside a full-width frame (a header, a progress bar), whose item is never wider than
// the panel but whose text can be cut all the same. Needs the current ImGui window: the panel.
#include <imgui.h>

#include <string>

namespace lenslab::view {

class PanelFit {
 public:
  void beginFrame();
  // The last item, when it reaches past the panel's right edge. `what` names it in the report.
  void check(const char* what);
  // Text of width CalcTextSize(text) plus `framePx` (arrow, padding) inside the width left on
  // this line.
  void checkText(const char* text, float framePx);
  // The next widget's `count` numbers, each printed with `format` (printf, one double), inside its
  // fields: the next item's width shared as DragScalarN shares it.
  void checkFields(const char* what, const double* values, int fields, const char* format);

  // The layout that keeps the text whole: labels above their widgets when the panel is too narrow
  // for a widget and its label side by side. Set by the panel at the start of each frame.
  bool labelsAbove = false;
  void endFrame();  // keeps the frame's count when it is the largest so far

  int clippedMost() const { return most_; }                   // the most cut items in one frame
  const std::string& firstClipped() const { return first_; }  // the first cut item seen, for the report
  float widestOverflowPx() const { return overflowPx_; }      // how far the worst ran past the edge

 private:
  void count(const char* what, float overflowPx);

  int clipped_ = 0;
  int most_ = 0;
  std::string first_;
  float overflowPx_ = 0.0f;
};

}  // namespace lenslab::view
