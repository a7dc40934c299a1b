// lenslab view: the frame loop, input, accumulation and drawing of one window.
//
// Each frame does a bounded amount of accumulation (about frameBudgetMs of scene passes, at least
// one, from the last measured cost per sample), shows the mean so far, then the panel. Any change
// of the camera or the lens restarts the accumulation.
#include "view/Viewer.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "camera/FocusOnPixel.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "io/Progress.h"
#include "render/RasterDepth.h"
#include "view/LectureDiagram.h"

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
  if (area.width / std::max(area.height, 1.0) > aspect) r.width = area.height * aspect;
  else r.height = area.width / aspect;
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

// The diagram's lines as the line drawer takes them.
std::vector<LineSegment> segments(const std::vector<DiagramLine>& lines) {
  std::vector<LineSegment> out;
  out.reserve(lines.size());
  for (const DiagramLine& l : lines) out.push_back({l.from, l.to, l.color});
  return out;
}

}  // namespace

void Viewer::reportError(const std::string& message) {
  error_ = message;
  std::cerr << "lenslab: error: " << message << "\n";
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
  const double panelWidth = options_.noUi ? 0.0 : std::min(430.0 * uiScale_, 0.5 * windowWidth_);
  WindowRect area{0.0, 0.0, windowWidth_ - panelWidth, static_cast<double>(windowHeight_)};
  const double aspect = static_cast<double>(size_.widthPx) / size_.heightPx;
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
  return glm::dvec2((mouse.x - imageRect_.x) / imageRect_.width * size_.widthPx,
                    (mouse.y - imageRect_.y) / imageRect_.height * size_.heightPx);
}

void Viewer::focusAt(glm::dvec2 pixel) {
  // The camera's source names only the latest click, not every click since the start.
  Camera current = cam_.camera;
  current.source = baseSource_;
  const Camera focused = focusOnPixel(current, size_, pixel, rasterDepth(renderer_));
  // refocused() moves the view plane to the new plane of focus: PRP.n is the focus distance.
  const double distance = focused.view.prp.z;
  cam_.camera = focused;
  if (cam_.physical) cam_.physical->focusDistance = distance;
  focusDistance_ = distance;
  std::cout << "lenslab: focus distance " << cat(distance) << " (pixel " << cat(pixel.x) << "," << cat(pixel.y) << ")" << std::endl;
  dirty_ = true;
}

void Viewer::handleInput() {
  ImGuiIO& io = ImGui::GetIO();
  if (glfwGetKey(window_, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window_, GLFW_TRUE);
  const ImVec2 mouse = io.MousePos;
  if (!io.WantCaptureMouse) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
      pressRegion_ = imageRect_.contains(mouse) ? Region::Image : outsideRect_.contains(mouse) ? Region::Outside : Region::None;
      dragged_ = false;
    }
    constexpr double kRadiansPerPoint = 0.005;
    const double dx = io.MouseDelta.x * kRadiansPerPoint, dy = io.MouseDelta.y * kRadiansPerPoint;
    const bool leftDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Left, 3.0f);
    const bool rightDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 1.0f);
    if (pressRegion_ == Region::Image) {
      if (leftDrag && (dx != 0.0 || dy != 0.0)) {
        cam_ = orbited(cam_, -dx, -dy);
        dragged_ = dirty_ = true;
      }
      if (rightDrag && (dx != 0.0 || dy != 0.0)) {
        cam_ = lookedAround(cam_, -dx, -dy);
        dragged_ = dirty_ = true;
      }
      if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !dragged_) {
        if (const auto pixel = imagePixelAt(mouse)) {
          try {
            focusAt(*pixel);
          } catch (const InputError& e) {
            // focusOnPixel speaks of the command-line option; here it was a click.
            std::string message = e.what();
            if (message.rfind("--focus-at ", 0) == 0) message = "click at image pixel " + message.substr(11);
            reportError(message);
          }
        }
      }
    } else if (pressRegion_ == Region::Outside && leftDrag) {
      outsideAzimuth_ -= dx;
      outsideElevation_ = std::clamp(outsideElevation_ + dy, -1.5, 1.5);
      outsideDirty_ = true;
    }
    if (io.MouseWheel != 0.0f) {
      if (imageRect_.contains(mouse)) {
        cam_ = flown(cam_, {0.0, 0.0, 0.1 * io.MouseWheel * cam_.camera.view.prp.z});
        dirty_ = true;
      } else if (outsideRect_.contains(mouse)) {
        outsideZoom_ = std::clamp(outsideZoom_ * std::pow(0.9, io.MouseWheel), 0.05, 50.0);
        outsideDirty_ = true;
      }
    }
  }
  if (!io.WantCaptureKeyboard) {
    // Fly: W/S forward and back, A/D sideways, Q/E down and up; Shift is faster.
    auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0 : 0.0; };
    const glm::dvec3 m(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                       held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (m != glm::dvec3(0.0)) {
      const double speed = 0.5 * cam_.camera.view.prp.z * (held(GLFW_KEY_LEFT_SHIFT) > 0.0 ? 4.0 : 1.0);
      cam_ = flown(cam_, m * speed * static_cast<double>(io.DeltaTime));
      dirty_ = true;
    }
  }
}

void Viewer::restart() {
  try {
    validate(cam_.camera.view, "the panel's camera");
    validateLensEffects(cam_.camera, "the panel's camera");
    if (!(cam_.camera.apertureRadius >= 0.0) || !std::isfinite(cam_.camera.apertureRadius))
      throw InputError("the panel's camera: aperture radius must be 0 (a pinhole) or positive");
    plan_ = makeFramePlan(scene_, cam_.camera, size_, planOptions_);
    lastGood_ = cam_;
    error_.clear();
  } catch (const InputError& e) {
    reportError(e.what());
    cam_ = lastGood_;
    plan_ = makeFramePlan(scene_, cam_.camera, size_, planOptions_);
  }
  renderer_.begin(cam_.camera, plan_, size_);
  resolved_ = nullptr;
  accumulationMs_ = 0.0;
  convergedAfterMs_ = -1.0;
  restartTime_ = Clock::now();
  baselineValid_ = false;
  outsideDirty_ = true;
  dirty_ = false;
}

void Viewer::accumulate() {
  const int remaining = renderer_.samplesPlanned() - renderer_.samplesDone();
  if (remaining <= 0) return;
  // Bounded work: as many samples as the last measured cost allows in the budget, at least one.
  const int count = msPerSample_ > 0.0
      ? std::clamp(static_cast<int>(options_.frameBudgetMs / msPerSample_), 1, remaining)
      : 1;
  const auto t = Clock::now();
  const int added = renderer_.addSamples(count);
  finishGpuWork();  // honest timing: the scene passes are done
  const double ms = msSince(t);
  msPerSample_ = ms / std::max(added, 1);
  accumulationMs_ += ms;
  resolved_ = &renderer_.resolveOnGpu();
  if (renderer_.samplesDone() == renderer_.samplesPlanned()) convergedAfterMs_ = msSince(restartTime_);
}

Camera Viewer::outsideCamera(double aspect) const {
  const Camera& c = cam_.camera;
  const glm::dvec3 prp = prpWorld(c.view);
  const glm::dvec3 focus = focusPivotWorld(c);
  const glm::dvec3 pivot = 0.5 * (prp + focus);
  const double extent = std::max({c.view.prp.z, c.view.window.width(), c.view.window.height()});
  const double distance = 2.2 * extent * outsideZoom_;
  // Azimuth from behind the camera (its +n, flattened onto the ground) toward its right.
  const ViewBasis b = viewBasis(c.view);
  glm::dvec3 back(b.n.x, 0.0, b.n.z);
  back = glm::length(back) > 1e-6 ? glm::normalize(back) : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 right = glm::cross(glm::dvec3(0.0, 1.0, 0.0), back);
  const glm::dvec3 dir = std::cos(outsideElevation_) * (std::cos(outsideAzimuth_) * back + std::sin(outsideAzimuth_) * right) +
                         std::sin(outsideElevation_) * glm::dvec3(0.0, 1.0, 0.0);
  PhysicalCamera p;
  p.eye = pivot + distance * dir;
  p.target = pivot;
  p.up = std::abs(dir.y) > 0.99 ? -back : glm::dvec3(0.0, 1.0, 0.0);
  p.focalLengthMm = 20.0;
  p.sensorMm = {24.0 * aspect, 24.0};
  // A pinhole: infinity focus puts no bound on how close it may come (no focus inside f).
  p.focusDistance = std::numeric_limits<double>::infinity();
  p.nearDistance = 1e-3 * distance;
  return toCamera(p, "outside view");
}

void Viewer::drawOutside(const gl::PixelRect& rect) {
  if (rect.empty()) return;
  outsideCamera_ = outsideCamera(static_cast<double>(rect.width) / rect.height);
  const bool resized = outsideTexture_.width() != rect.width || outsideTexture_.height() != rect.height;
  if (outsideDirty_ || resized) {
    // The scene from outside changes only with the cameras: drawn once, kept in a texture.
    const gl::RenderTarget& view = renderer_.renderPinhole(outsideCamera_, ImageSize{rect.width, rect.height});
    if (resized) outsideTexture_ = gl::ImageTexture(rect.width, rect.height);
    outsideTexture_.copyColor(view);
    outsideDirty_ = false;
  }
  gl::bindDefaultFramebuffer(fbWidth_, fbHeight_);
  imageDrawer_.draw(outsideTexture_, rect, 0.45f);
  DiagramStyle style;
  style.apertureScale = enlargeAperture_ ? readableApertureScale(cam_.camera) : 1.0;
  const std::vector<DiagramLine> lines = lectureDiagram(cam_.camera, renderer_.plannedSamples(), renderer_.samplesDone(), style);
  lineDrawer_.draw(segments(lines), clipFromWorld(outsideCamera_.view), rect);
}

void Viewer::draw() {
  // The baseline is computed once per change (one pinhole pass and one gather pass).
  if (showBaseline_ && !baselineValid_) {
    if (!gather_) gather_ = std::make_unique<GatherDof>();
    const Image image = gather_->apply(cam_.camera, renderer_.renderPinhole(cam_.camera, size_), baselineTaps_);
    if (!baselineTexture_) baselineTexture_ = gl::ImageTexture(image.width, image.height);
    baselineTexture_.upload(image);
    baselineValid_ = true;
  }
  gl::clearDefaultFramebuffer(fbWidth_, fbHeight_, {0.08f, 0.08f, 0.09f, 1.0f});
  const gl::PixelRect imageRect = toPixels(imageRect_);
  if (showBaseline_ && baselineValid_) imageDrawer_.draw(baselineTexture_, imageRect);
  else if (resolved_) imageDrawer_.draw(*resolved_, imageRect);
  if (showOutside_) drawOutside(toPixels(outsideRect_));
  gl::bindDefaultFramebuffer(fbWidth_, fbHeight_);  // for the panel
}

void Viewer::finishScripted() {
  if (!options_.screenshot.empty()) {
    // --no-ui: the image itself, as `render` writes it; with the UI: the whole window.
    writeImage(options_.screenshot, options_.noUi ? renderer_.resolve() : readWindow(fbWidth_, fbHeight_));
  }
  if (!options_.saveCamera.empty()) writeTextFileAtomically(options_.saveCamera, toCameraJson(cam_.camera));
  if (!options_.statsFile.empty()) {
    nlohmann::json j;
    j["command"] = "view";
    j["frames"] = frames_;
    j["width"] = size_.widthPx;
    j["height"] = size_.heightPx;
    j["framebuffer"] = {fbWidth_, fbHeight_};
    j["renderer"] = currentRenderer();
    j["samples_done"] = renderer_.samplesDone();
    j["samples_planned"] = renderer_.samplesPlanned();
    j["samples_why"] = plan_.samplesWhy;
    j["ms_per_sample"] = accumulationMs_ / std::max(renderer_.samplesDone(), 1);
    j["accumulation_ms"] = accumulationMs_;
    j["frame_ms_mean"] = frameMsSum_ / std::max(frames_, 1);
    j["frame_ms_max"] = frameMsMax_;  // the first frames include shader compilation
    j["focus_distance"] = focusDistance_ ? nlohmann::json(*focusDistance_) : nlohmann::json(nullptr);
    j["camera"] = cam_.camera.source;
    writeTextFileAtomically(options_.statsFile, j.dump(2) + "\n");
  }
}

int Viewer::run() {
  glfwSwapInterval(scripted() ? 0 : 1);  // vsync when a person watches; as fast as possible in tests
  // Sticky keys: a press and release between two frames still reads as pressed once (Escape).
  glfwSetInputMode(window_, GLFW_STICKY_KEYS, GLFW_TRUE);
  layout();
  restart();
  // Scripted clicks act as a click on the first frame would.
  if (options_.lens.focusAt) focusAt(*options_.lens.focusAt);
  if (options_.click) focusAt(*options_.click);
  while (!glfwWindowShouldClose(window_)) {
    const bool converged = renderer_.samplesDone() >= renderer_.samplesPlanned();
    if (!scripted() && converged && !dirty_) glfwWaitEventsTimeout(0.05);  // idle: no busy loop
    else glfwPollEvents();
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
      if (dirty_) restart();
      accumulate();
      if (!options_.noUi) panel();  // after accumulating, so it shows this frame's count; its edits restart the next
      draw();
    } catch (const std::exception& e) {
      if (scripted()) throw;
      reportError(e.what());  // shown in the panel; the window stays up
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
        reportError(e.what());
      }
    }
    if (scripted()) finishGpuWork();  // scripted frames are timed with the GPU done
    const double frameMs = msSince(frameStart);
    frameMsMax_ = std::max(frameMsMax_, frameMs);
    frameMsSum_ += frameMs;
    ++frames_;
    if (scripted() && frames_ >= options_.frames && renderer_.samplesDone() >= renderer_.samplesPlanned()) {
      finishScripted();
      return 0;
    }
    glfwSwapBuffers(window_);
  }
  return 0;
}

}  // namespace lenslab::view
