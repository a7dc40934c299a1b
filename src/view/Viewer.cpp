// lenslab view: the frame loop, input, accumulation and drawing of one window.
//
// Each frame does a bounded amount of accumulation (as many samples as the model's budget allows,
// at least one), shows the mean so far, then the panel. Any change of the camera or the lens
// restarts the accumulation.
#include "view/Viewer.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "camera/Projection.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "render/RasterDepth.h"
#include "render/VisibleBlurPass.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace lenslab::view {
namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The largest rectangle of aspect `aspect` (width / height) centred in `area`.
WindowRect fitted(const WindowRect& area, double aspect) {
  WindowRect r = area;
  if (area.width / std::max(area.height, 1.0) > aspect)
    r.width = area.height * aspect;
  else
    r.height = area.width / aspect;
  r.x = area.x + 0.5 * (area.width - r.width);
  r.y = area.y + 0.5 * (area.height - r.height);
  return r;
}

// Reads the window's back buffer (what is about to be shown), as a linear image: the framebuffer
// holds display (sRGB) values.
Image readWindow(int widthPx, int heightPx) {
  Image image = gl::readDefaultFramebuffer(widthPx, heightPx);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    for (std::size_t k = 0; k < 3; ++k) image.rgba[i + k] = linearFromSrgb(image.rgba[i + k]);
  return image;
}

void printFocus(double distance, glm::dvec2 pixel) {
  std::cout << "lenslab: focus distance " << cat(distance) << " (pixel " << cat(pixel.x) << "," << cat(pixel.y) << ")"
            << std::endl;
}

// The diagram's lines as the line drawer takes them.
std::vector<LineSegment> segments(const std::vector<DiagramLine>& lines) {
  std::vector<LineSegment> out;
  out.reserve(lines.size());
  for (const DiagramLine& l : lines) out.push_back({l.from, l.to, l.color});
  return out;
}

}  // namespace

Viewer::Viewer(const ViewOptions& options, GLFWwindow* window, const Scene& scene, EditableCamera camera,
               ImageSize size, PlanOptions planOptions, DisplaySettings display)
    : options_(options),
      window_(window),
      model_(scene, std::move(camera), size, planOptions, options.frameBudgetMs, std::cerr),
      renderer_(scene),
      display_(std::move(display)),
      showBaseline_(options.showBaseline && !options.noUi),
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

gl::PixelRect Viewer::toPixels(const WindowRect& r) const {
  const double sx = fbWidth_ / std::max(1.0, static_cast<double>(windowWidth_));
  const double sy = fbHeight_ / std::max(1.0, static_cast<double>(windowHeight_));
  const int x0 = static_cast<int>(std::lround(r.x * sx)), x1 = static_cast<int>(std::lround((r.x + r.width) * sx));
  const int y0 = static_cast<int>(std::lround(r.y * sy)), y1 = static_cast<int>(std::lround((r.y + r.height) * sy));
  return {x0, fbHeight_ - y1, x1 - x0, y1 - y0};
}

void Viewer::layout() {
  glfwGetWindowSize(window_, &windowWidth_, &windowHeight_);
  glfwGetFramebufferSize(window_, &fbWidth_, &fbHeight_);
  panelWidth_ = options_.noUi ? 0.0 : std::min(430.0 * uiScale_, 0.5 * windowWidth_);
  WindowRect area{0.0, 0.0, windowWidth_ - panelWidth_, static_cast<double>(windowHeight_)};
  const double aspect = static_cast<double>(model_.size().widthPx) / model_.size().heightPx;
  if (showOutside_) {
    WindowRect top = area, bottom = area;
    top.height = bottom.height = 0.5 * area.height;
    bottom.y = top.height;
    imageRect_ = fitted(top, aspect);
    outsideRect_ = bottom;
  } else {
    imageRect_ = fitted(area, aspect);
    outsideRect_ = {};
  }
}

std::optional<glm::dvec2> Viewer::imagePixelAt(ImVec2 mouse) const {
  if (!imageRect_.contains(mouse)) return std::nullopt;
  return glm::dvec2((mouse.x - imageRect_.x) / imageRect_.width * model_.size().widthPx,
                    (mouse.y - imageRect_.y) / imageRect_.height * model_.size().heightPx);
}

// A scripted focus (--focus-at, --click): an error ends the run.
void Viewer::focusAt(glm::dvec2 pixel, const std::string& asked) {
  printFocus(model_.focusAt(pixel, rasterDepth(renderer_), asked), pixel);
}

void Viewer::handleInput() {
  ImGuiIO& io = ImGui::GetIO();
  if (glfwGetKey(window_, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window_, GLFW_TRUE);
  const ImVec2 mouse = io.MousePos;
  if (!io.WantCaptureMouse) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
      pressRegion_ = imageRect_.contains(mouse)     ? Region::Image
                     : outsideRect_.contains(mouse) ? Region::Outside
                                                    : Region::None;
      dragged_ = false;
    }
    constexpr double kRadiansPerPoint = 0.005;
    const double dx = io.MouseDelta.x * kRadiansPerPoint, dy = io.MouseDelta.y * kRadiansPerPoint;
    const bool leftDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Left, 3.0f);
    const bool rightDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 1.0f);
    if (pressRegion_ == Region::Image) {
      if (leftDrag && (dx != 0.0 || dy != 0.0)) {
        model_.orbit(-dx, -dy);
        dragged_ = true;
      }
      if (rightDrag && (dx != 0.0 || dy != 0.0)) {
        model_.lookAround(-dx, -dy);
        dragged_ = true;
      }
      if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !dragged_) {
        if (const auto pixel = imagePixelAt(mouse)) {
          if (const auto distance = model_.clickAt(*pixel, rasterDepth(renderer_))) printFocus(*distance, *pixel);
        }
      }
    } else if (pressRegion_ == Region::Outside && leftDrag) {
      model_.outside().orbit(-dx, dy);
      outsideDirty_ = true;
    }
    if (io.MouseWheel != 0.0f) {
      if (imageRect_.contains(mouse)) {
        model_.moveForward(io.MouseWheel);
      } else if (outsideRect_.contains(mouse)) {
        model_.outside().zoomBy(io.MouseWheel);
        outsideDirty_ = true;
      }
    }
  }
  if (!io.WantCaptureKeyboard) {
    // Fly: W/S forward and back, A/D sideways, Q/E down and up; Shift is faster.
    auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0 : 0.0; };
    const glm::dvec3 m(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                       held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (m != glm::dvec3(0.0)) model_.fly(m, static_cast<double>(io.DeltaTime), held(GLFW_KEY_LEFT_SHIFT) > 0.0);
  }
}

void Viewer::restart() {
  model_.restart();  // checks the camera (back to the last valid one), plans, restarts the budget
  if (model_.wantsVisibleBlur()) model_.replanWith(measureVisibleBlur(renderer_, model_.renderCamera(), model_.size()));
  renderer_.begin(model_.renderCamera(), model_.plan(), model_.size());
  resolved_ = nullptr;
  baselineValid_ = false;
  outsideDirty_ = true;
}

void Viewer::accumulate() {
  if (renderer_.adaptive()) {
    // Per-tile budgets: one round a frame (the tiles still short of the target), then the estimate.
    if (renderer_.done()) return;
    const auto t = Clock::now();
    const int before = renderer_.samplesDone();
    const bool more = renderer_.step();
    finishGpuWork();
    model_.budget().measured(renderer_.samplesDone() - before, msSince(t), !more);
    resolved_ = &renderer_.resolveOnGpu();
    return;
  }
  const int count = model_.budget().samplesForFrame(renderer_.samplesPlanned() - renderer_.samplesDone());
  if (count == 0) return;
  const auto t = Clock::now();
  const int added = renderer_.addSamples(count);
  finishGpuWork();  // honest timing: the scene passes are done
  model_.budget().measured(added, msSince(t), renderer_.samplesDone() == renderer_.samplesPlanned());
  resolved_ = &renderer_.resolveOnGpu();
}

void Viewer::drawOutside(const gl::PixelRect& rect) {
  if (rect.empty()) return;
  const Camera outside = model_.outsideCamera(static_cast<double>(rect.width) / rect.height);
  const bool resized = outsideTexture_.width() != rect.width || outsideTexture_.height() != rect.height;
  if (outsideDirty_ || resized) {
    // The scene from outside changes only with the cameras: drawn once, kept in a texture.
    const gl::RenderTarget& view = renderer_.renderPinhole(outside, ImageSize{rect.width, rect.height});
    if (resized) outsideTexture_ = gl::ImageTexture(rect.width, rect.height);
    outsideTexture_.copyColor(view);
    outsideDirty_ = false;
  }
  gl::bindDefaultFramebuffer(fbWidth_, fbHeight_);
  imageDrawer_.draw(outsideTexture_, rect, 0.45f);
  lineDrawer_.draw(segments(model_.diagram(renderer_.plannedSamples(), renderer_.samplesDone())),
                   clipFromWorld(outside.view), rect);
}

void Viewer::draw() {
  // The baseline is computed once per change (one pinhole pass and one gather pass).
  if (showBaseline_ && !baselineValid_) {
    if (!gather_) gather_ = std::make_unique<GatherDof>();
    const Camera camera = model_.renderCamera();
    const Image image = gather_->apply(camera, renderer_.renderPinhole(camera, model_.size()), baselineTaps_);
    if (!baselineTexture_) baselineTexture_ = gl::ImageTexture(image.width, image.height);
    baselineTexture_.upload(image);
    baselineValid_ = true;
  }
  gl::clearDefaultFramebuffer(fbWidth_, fbHeight_, {0.08f, 0.08f, 0.09f, 1.0f});
  const gl::PixelRect imageRect = toPixels(imageRect_);
  if (showBaseline_ && baselineValid_)
    imageDrawer_.draw(baselineTexture_, imageRect, 1.0f, display_.encoding);
  else if (resolved_)
    imageDrawer_.draw(*resolved_, imageRect, 1.0f, display_.encoding);
  if (showOutside_) drawOutside(toPixels(outsideRect_));
  gl::bindDefaultFramebuffer(fbWidth_, fbHeight_);  // for the panel
}

void Viewer::finishScripted() {
  // The scripted run's files appear together or not at all (io/AtomicFile.h).
  OutputSet outputs;
  if (!options_.screenshot.empty()) {
    // --no-ui: the image itself, as `render` writes it; with the UI: the whole window.
    if (options_.noUi) {
      Image image = renderer_.resolve();
      applyDisplayForFile(options_.screenshot, image, display_.encoding);
      writeImage(outputs, options_.screenshot, image);
    } else {
      writeImage(outputs, options_.screenshot, readWindow(fbWidth_, fbHeight_));
    }
  }
  if (!options_.saveCamera.empty()) outputs.add(options_.saveCamera, toCameraJson(model_.camera().camera));
  if (!options_.statsFile.empty()) {
    nlohmann::json j;
    j["command"] = "view";
    j["frames"] = frames_;
    j["width"] = model_.size().widthPx;
    j["height"] = model_.size().heightPx;
    j["framebuffer"] = {fbWidth_, fbHeight_};
    j["renderer"] = currentRenderer();
    j["samples_done"] = renderer_.samplesDone();
    j["samples_planned"] =
        renderer_.adaptive() ? model_.plan().apertureSamples : renderer_.samplesPlanned();  // per-tile: the cap
    j["samples_why"] = model_.plan().samplesWhy;
    if (renderer_.adaptive()) {
      const FrameEstimate e = renderer_.estimate();
      j["estimate"] = {{"psnr", e.psnrDb}, {"rmse", e.rmse}, {"target_met", e.targetMet}};
      j["samples"] = {{"min", e.minSamples}, {"mean", e.meanSamples}, {"max", e.maxSamples}, {"rounds", e.rounds}};
    }
    const double accumulationMs = model_.budget().accumulationMs();
    j["ms_per_sample"] = accumulationMs / std::max(renderer_.samplesDone(), 1);
    j["accumulation_ms"] = accumulationMs;
    j["frame_ms_mean"] = frameMsSum_ / std::max(frames_, 1);
    j["frame_ms_max"] = frameMsMax_;  // the first frames include shader compilation
    if (!options_.noUi) {
      // Panel text cut off on the right: the most items in any frame (0 when everything fits).
      j["panel_clipped_items"] = fit_.clippedMost();
      if (fit_.clippedMost() > 0) {
        j["panel_first_clipped"] = fit_.firstClipped();
        j["panel_overflow_px"] = fit_.widestOverflowPx();
      }
      j["window"] = {windowWidth_, windowHeight_};
    }
    const std::optional<double> focus = model_.lastFocusDistance();
    j["focus_distance"] = focus ? nlohmann::json(*focus) : nlohmann::json(nullptr);
    j["camera"] = model_.camera().camera.source;
    j["display"] = {{"exposure_stops", std::log2(display_.encoding.exposureScale)},
                    {"exposure_scale", display_.encoding.exposureScale},
                    {"view_transform", viewTransformName(display_.encoding.transform)}};
    outputs.add(options_.statsFile, j.dump(2) + "\n");
  }
  outputs.commit();
}

int Viewer::run() {
  glfwSwapInterval(scripted() ? 0 : 1);  // vsync when a person watches; as fast as possible in tests
  // Sticky keys: a press and release between two frames still reads as pressed once (Escape).
  glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
  layout();
  restart();
  // Scripted clicks act as a click on the first frame would.
  if (options_.lens.focusAt) focusAt(*options_.lens.focusAt, "--focus-at");
  if (options_.click) focusAt(*options_.click, "--click");
  while (!glfwWindowShouldClose(window_)) {
    const bool converged = renderer_.done();
    if (!scripted() && converged && !model_.needsRestart())
      glfwWaitEventsTimeout(0.05);  // idle: no busy loop
    else
      glfwPollEvents();
    layout();
    if (!scripted() && (glfwGetWindowAttrib(window_, GLFW_ICONIFIED) || fbWidth_ == 0 || fbHeight_ == 0)) {
      glfwWaitEvents();  // minimised: no work until something happens
      continue;
    }
    const auto frameStart = Clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    try {
      handleInput();
      if (model_.needsRestart()) restart();
      accumulate();
      if (!options_.noUi) panel();  // after accumulating, so it shows this frame's count; its edits restart the next
      draw();
    } catch (const std::exception& e) {
      if (scripted()) throw;
      model_.reportError(e.what());  // shown in the panel; the window stays up
    }
    ImGui::Render();
    if (!options_.noUi) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (saveWindowPending_) {
      saveWindowPending_ = false;
      try {
        checkImageExtension(windowPath_.data());
        writeImage(windowPath_.data(), readWindow(fbWidth_, fbHeight_));
        status_ = cat("wrote ", windowPath_.data());
      } catch (const std::exception& e) {
        model_.reportError(e.what());
      }
    }
    if (scripted()) finishGpuWork();  // scripted frames are timed with the GPU done
    const double frameMs = msSince(frameStart);
    frameMsMax_ = std::max(frameMsMax_, frameMs);
    frameMsSum_ += frameMs;
    ++frames_;
    if (scripted()) {
      // A long scripted run (thousands of samples on a CPU renderer) says how far it is in a log.
      if (!progress_) progress_ = std::make_unique<ProgressReporter>("view", "samples", false);
      if (renderer_.adaptive()) progress_->setUnit(kTilesAtTargetUnit);
      const Renderer::Progress p = renderer_.progress();
      progress_->update(p.done, p.total);
    }
    if (scripted() && frames_ >= options_.frames && renderer_.done()) {
      finishScripted();
      progress_->finish();
      return 0;
    }
    glfwSwapBuffers(window_);
  }
  return 0;
}

}  // namespace lenslab::view
