#pragma once
// The interactive demo's window state: one Viewer per `lenslab view` run. Its frame loop and
// drawing are in Viewer.cpp, the Dear ImGui panel in ViewerPanel.cpp; ViewApp.cpp owns GLFW and
// ImGui's lifetimes and builds it. Internal to src/view.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"
#include "gl/DefaultFramebuffer.h"
#include "gl/ImageTexture.h"
#include "plan/FramePlan.h"
#include "render/GatherDof.h"
#include "render/ImageDrawer.h"
#include "render/LineDrawer.h"
#include "render/Renderer.h"
#include "scene/Scene.h"
#include "view/Navigation.h"
#include "view/ViewApp.h"

#define GLFW_INCLUDE_NONE  // no GL header from GLFW: glad's (through gl/) must be the only one
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <glm/glm.hpp>

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
         PlanOptions planOptions)
      : options_(options), window_(window), scene_(scene), size_(size), planOptions_(planOptions), cam_(std::move(camera)),
        lastGood_(cam_), baseSource_(cam_.camera.source), renderer_(scene), showBaseline_(options.showBaseline && !options.noUi),
        showOutside_(options.outsideView && !options.noUi) {
    float xs = 1.0f, ys = 1.0f;
    glfwGetWindowContentScale(window_, &xs, &ys);
    uiScale_ = std::max(1.0f, xs);
    ImGui::GetStyle().ScaleAllSizes(uiScale_);
    ImGui::GetIO().FontGlobalScale = uiScale_;
    std::snprintf(cameraPath_.data(), cameraPath_.size(), "%s", "camera-view.json");
    std::snprintf(imagePath_.data(), imagePath_.size(), "%s", "view.png");
    std::snprintf(windowPath_.data(), windowPath_.size(), "%s", "view-window.png");
  }

  int run();

 private:
  bool scripted() const { return options_.frames > 0; }
  void layout();
  void handleInput();
  void focusAt(glm::dvec2 pixel);
  void restart();
  void accumulate();
  void draw();
  void drawOutside(const gl::PixelRect& rect);
  Camera outsideCamera(double aspect) const;
  gl::PixelRect toPixels(const WindowRect& r) const;
  std::optional<glm::dvec2> imagePixelAt(ImVec2 mouse) const;
  void finishScripted();
  void reportError(const std::string& message);

  // Panel sections, one function each (ViewerPanel.cpp).
  void panel();
  void sectionProgress();
  void sectionLecture();
  void sectionMatrices();
  void sectionPhysical();
  void sectionSamples();
  void sectionLensEffects();
  void adoptPhysical(const PhysicalCamera& physical);  // keeps the lens effects and calibrated size
  void sectionCompare();
  void sectionFiles();
  void sectionHelp();
  void cameraEdited(const Camera& camera);  // a lecture-form edit: the physical form is dropped

  const ViewOptions& options_;
  GLFWwindow* window_;
  const Scene& scene_;
  ImageSize size_;
  PlanOptions planOptions_;
  EditableCamera cam_;
  EditableCamera lastGood_;  // what to go back to when an edit makes the camera invalid
  std::string baseSource_;   // where the camera came from, before any click
  FramePlan plan_;
  Renderer renderer_;
  ImageDrawer imageDrawer_;
  LineDrawer lineDrawer_;
  std::unique_ptr<GatherDof> gather_;  // made when the baseline is first shown
  bool dirty_ = true;                  // the accumulation must restart
  const gl::RenderTarget* resolved_ = nullptr;

  // Progress, for the panel and --stats.
  double msPerSample_ = 0.0;      // the last frame's, the next frame's estimate
  double accumulationMs_ = 0.0;   // scene passes of this accumulation, GPU finished
  Clock::time_point restartTime_ = Clock::now();
  double convergedAfterMs_ = -1.0;
  int frames_ = 0;
  double frameMsMax_ = 0.0;       // the slowest frame (input to panel drawn), for --stats
  double frameMsSum_ = 0.0;
  std::optional<double> focusDistance_;  // the last click's

  // The post-process baseline, for comparison.
  bool showBaseline_;
  int baselineTaps_ = 32;
  bool baselineValid_ = false;
  gl::ImageTexture baselineTexture_;

  // The outside view: an orbit camera around the lecture camera.
  bool showOutside_;
  double outsideAzimuth_ = 0.8;     // radians from behind the camera toward its right
  double outsideElevation_ = 0.5;   // radians above the horizon
  double outsideZoom_ = 0.8;
  bool enlargeAperture_ = true;     // draw the (mm-sized) aperture large enough to see
  bool outsideDirty_ = true;
  gl::ImageTexture outsideTexture_;
  Camera outsideCamera_;

  // Layout and input.
  float uiScale_ = 1.0f;
  int windowWidth_ = 0, windowHeight_ = 0, fbWidth_ = 0, fbHeight_ = 0;
  WindowRect imageRect_, outsideRect_;
  Region pressRegion_ = Region::None;
  bool dragged_ = false;

  bool saveWindowPending_ = false;
  std::string error_;   // shown in red in the panel (and on stderr)
  std::string status_;  // the last thing saved
  std::array<char, 512> cameraPath_{}, imagePath_{}, windowPath_{};
};

}  // namespace lenslab::view
