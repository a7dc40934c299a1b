#pragma once
// The interactive demo's window: one Viewer per `lenslab view` run, the shell around ViewerModel
// (the state and its rules, ViewerModel.h). The shell reads GLFW input, draws the Dear ImGui panel,
// runs the Renderer and shows its images; its frame loop and drawing are in Viewer.cpp, the panel
// in ViewerPanel.cpp. ViewApp.cpp owns GLFW and ImGui's lifetimes and builds it. Internal to
// src/view.
#include "gl/DefaultFramebuffer.h"
#include "gl/ImageTexture.h"
#include "io/Progress.h"
#include "render/GatherDof.h"
#include "render/ImageDrawer.h"
#include "render/LineDrawer.h"
#include "render/Renderer.h"
#include "view/PanelFit.h"
#include "view/ViewApp.h"
#include "view/ViewerModel.h"

#define GLFW_INCLUDE_NONE  // no GL header from GLFW: glad's (through gl/) must be the only one
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace lenslab::view {

using Clock = std::chrono::steady_clock;

// A rectangle in window coordinates (ImGui's and GLFW's cursor's), origin at the top left.
struct WindowRect {
  double x = 0, y = 0, width = 0, height = 0;
  bool contains(ImVec2 p) const { return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height; }
};

enum class Region { None, Image, Outside };

class Viewer {
 public:
  Viewer(const ViewOptions& options, GLFWwindow* window, const Scene& scene, EditableCamera camera, ImageSize size,
         PlanOptions planOptions, DisplaySettings display = {});

  int run();

 private:
  bool scripted() const { return options_.frames > 0; }
  void layout();
  void handleInput();
  void focusAt(glm::dvec2 pixel, const std::string& asked);
  void restart();
  void accumulate();
  void draw();
  void drawOutside(const gl::PixelRect& rect);
  gl::PixelRect toPixels(const WindowRect& r) const;
  std::optional<glm::dvec2> imagePixelAt(ImVec2 mouse) const;
  void finishScripted();

  // Panel sections, one function each (ViewerPanel.cpp). A scripted run opens every section, so
  // that its screenshot and the fit check (fit_) cover the whole panel.
  ImGuiTreeNodeFlags openFlags(bool openByDefault) const {
    return openByDefault || scripted() ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None;
  }
  void panel();
  void sectionProgress();
  void sectionLecture();
  void sectionMatrices();
  void sectionPhysical();
  void sectionSamples();
  void sectionLensEffects();
  void sectionDisplay();
  void sectionCompare();
  void sectionFiles();
  void sectionHelp();

  const ViewOptions& options_;
  GLFWwindow* window_;
  ViewerModel model_;
  Renderer renderer_;
  ImageDrawer imageDrawer_;
  DisplaySettings display_;  // exposure and view transform of the image shown and of Save image's PNG
  LineDrawer lineDrawer_;
  std::unique_ptr<GatherDof> gather_;  // made when the baseline is first shown
  const gl::RenderTarget* resolved_ = nullptr;

  // Frame times, for --stats.
  int frames_ = 0;
  double frameMsMax_ = 0.0;  // the slowest frame (input to panel drawn)
  double frameMsSum_ = 0.0;

  // The post-process baseline, for comparison.
  bool showBaseline_;
  int baselineTaps_ = 32;
  bool baselineValid_ = false;
  gl::ImageTexture baselineTexture_;

  // The outside view: the scene from the model's orbit camera, drawn once per change and kept.
  bool showOutside_;
  bool outsideDirty_ = true;
  gl::ImageTexture outsideTexture_;

  // Layout and input.
  float uiScale_ = 1.0f;
  int windowWidth_ = 0, windowHeight_ = 0, fbWidth_ = 0, fbHeight_ = 0;
  WindowRect imageRect_, outsideRect_;
  double panelWidth_ = 0.0;  // the panel's share of the window's right side (layout())
  Region pressRegion_ = Region::None;
  bool dragged_ = false;

  PanelFit fit_;                                // text cut off on the panel's right, counted each frame (--stats)
  std::unique_ptr<ProgressReporter> progress_;  // scripted runs: samples done, in a log

  bool saveWindowPending_ = false;
  std::string status_;  // the last thing saved
  std::array<char, 512> cameraPath_{}, imagePath_{}, windowPath_{};
};

}  // namespace lenslab::view
