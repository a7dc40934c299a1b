// lenslab view: the window, its frame loop, the panel and the outside view.
//
// Each frame does a bounded amount of accumulation (about frameBudgetMs of scene passes, at least
// one, from the last measured cost per sample), shows the mean so far, then the panel. Any change
// of the camera or the lens restarts the accumulation. glad is loaded for the GLFW context (the
// renderer's GL calls go through it); Dear ImGui's OpenGL3 backend brings its own loader.
#include <glad/gl.h>  // before any other GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "view/ViewApp.h"

#include "app/CameraSelection.h"
#include "camera/ImageSize.h"
#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "io/AtomicFile.h"
#include "io/CameraJson.h"
#include "io/ImageFile.h"
#include "plan/FramePlan.h"
#include "render/GatherDof.h"
#include "render/Renderer.h"
#include "scene/GltfLoader.h"
#include "view/GlDraw.h"
#include "view/LectureDiagram.h"
#include "view/Navigation.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace lenslab::view {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// ---- GLFW and ImGui lifetimes, torn down in reverse order ----

std::string& lastGlfwError() {
  static std::string error;
  return error;
}
void onGlfwError(int code, const char* text) { lastGlfwError() = cat("GLFW error ", code, ": ", text); }

struct GlfwLibrary {
  GlfwLibrary() {
    glfwSetErrorCallback(onGlfwError);  // first, so that a failing glfwInit says why
    if (glfwInit() != GLFW_TRUE)
      throw std::runtime_error(cat("cannot start GLFW (", lastGlfwError(), "); is DISPLAY set? Under CI: Xvfb :99 & DISPLAY=:99"));
  }
  ~GlfwLibrary() { glfwTerminate(); }
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

struct WindowOwner {
  GLFWwindow* window = nullptr;
  WindowOwner(int width, int height) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);  // the ceiling here (../shared/TOOLCHAIN.md)
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: size in screen coordinates
    window = glfwCreateWindow(width, height, "lenslab view", nullptr, nullptr);
    if (!window) throw std::runtime_error(cat("cannot open a window with an OpenGL 4.5 core context (", lastGlfwError(), ")"));
  }
  ~WindowOwner() { glfwDestroyWindow(window); }
  WindowOwner(const WindowOwner&) = delete;
  WindowOwner& operator=(const WindowOwner&) = delete;
};

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// A rectangle in window coordinates (ImGui's and GLFW's cursor's), origin at the top left.
struct WindowRect {
  double x = 0, y = 0, width = 0, height = 0;
  bool contains(ImVec2 p) const { return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height; }
};

// The largest rectangle of aspect `aspect` (width / height) centred in `area`.
WindowRect fitted(const WindowRect& area, double aspect) {
  WindowRect r = area;
  if (area.width / std::max(area.height, 1.0) > aspect) r.width = area.height * aspect;
  else r.height = area.width / aspect;
  r.x = area.x + 0.5 * (area.width - r.width);
  r.y = area.y + 0.5 * (area.height - r.height);
  return r;
}

enum class Region { None, Image, Outside };

const char* const kPatterns[] = {"lecture17", "concentric", "r2", "random"};

// Reads the window's back buffer (what is about to be shown), as a linear image.
Image readWindow(int widthPx, int heightPx) {
  std::vector<unsigned char> rgba(static_cast<std::size_t>(widthPx) * static_cast<std::size_t>(heightPx) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, widthPx, heightPx, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image image(widthPx, heightPx);
  for (int y = 0; y < heightPx; ++y) {
    for (int x = 0; x < widthPx; ++x) {
      // GL rows start at the bottom; the framebuffer holds display (sRGB) values.
      const unsigned char* p = &rgba[(static_cast<std::size_t>(heightPx - 1 - y) * static_cast<std::size_t>(widthPx) + static_cast<std::size_t>(x)) * 4];
      image.set(x, y, {linearFromSrgb(p[0] / 255.0f), linearFromSrgb(p[1] / 255.0f), linearFromSrgb(p[2] / 255.0f), 1.0f});
    }
  }
  return image;
}

// A float texture of the given size, for images that are drawn more than once.
gl::Texture floatTexture(int widthPx, int heightPx) {
  gl::Texture t = gl::Texture::create();
  glTextureStorage2D(t.id(), 1, GL_RGBA32F, widthPx, heightPx);
  return t;
}

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
  void drawOutside(const PixelRect& rect);
  Camera outsideCamera(double aspect) const;
  PixelRect toPixels(const WindowRect& r) const;
  std::optional<glm::dvec2> imagePixelAt(ImVec2 mouse) const;
  void finishScripted();
  void reportError(const std::string& message);

  // Panel sections, one function each, so that later lens effects (issue #5: distortion,
  // chromatic aberration, field curvature) add a section of their own.
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
  gl::Texture baselineTexture_;

  // The outside view: an orbit camera around the lecture camera.
  bool showOutside_;
  double outsideAzimuth_ = 0.8;     // radians from behind the camera toward its right
  double outsideElevation_ = 0.5;   // radians above the horizon
  double outsideZoom_ = 0.8;
  bool enlargeAperture_ = true;     // draw the (mm-sized) aperture large enough to see
  bool outsideDirty_ = true;
  gl::Texture outsideTexture_;
  PixelRect outsideTextureSize_;
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

void Viewer::reportError(const std::string& message) {
  error_ = message;
  std::cerr << "lenslab: error: " << message << "\n";
}

PixelRect Viewer::toPixels(const WindowRect& r) const {
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
  glFinish();  // honest timing: the scene passes are done
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

void Viewer::drawOutside(const PixelRect& rect) {
  if (rect.empty()) return;
  outsideCamera_ = outsideCamera(static_cast<double>(rect.width) / rect.height);
  if (outsideDirty_ || outsideTextureSize_.width != rect.width || outsideTextureSize_.height != rect.height) {
    // The scene from outside changes only with the cameras: drawn once, kept in a texture.
    const ImageSize size{rect.width, rect.height};
    const gl::RenderTarget& view = renderer_.renderPinhole(outsideCamera_, size);
    if (outsideTextureSize_.width != rect.width || outsideTextureSize_.height != rect.height) {
      outsideTexture_ = floatTexture(rect.width, rect.height);
      outsideTextureSize_ = {0, 0, rect.width, rect.height};
    }
    glCopyImageSubData(view.colorTexture(), GL_TEXTURE_2D, 0, 0, 0, 0, outsideTexture_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       rect.width, rect.height, 1);
    outsideDirty_ = false;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  imageDrawer_.draw(outsideTexture_.id(), rect, 0.45f);
  DiagramStyle style;
  style.apertureScale = enlargeAperture_ ? readableApertureScale(cam_.camera) : 1.0;
  const std::vector<DiagramLine> lines = lectureDiagram(cam_.camera, renderer_.plannedSamples(), renderer_.samplesDone(), style);
  lineDrawer_.draw(lines, clipFromWorld(outsideCamera_.view), rect);
}

void Viewer::draw() {
  // The baseline is computed once per change (one pinhole pass and one gather pass).
  if (showBaseline_ && !baselineValid_) {
    if (!gather_) gather_ = std::make_unique<GatherDof>();
    const Image image = gather_->apply(cam_.camera, renderer_.renderPinhole(cam_.camera, size_), baselineTaps_);
    if (!baselineTexture_) baselineTexture_ = floatTexture(size_.widthPx, size_.heightPx);
    for (int y = 0; y < image.height; ++y)  // Image rows run from the top, GL's from the bottom
      glTextureSubImage2D(baselineTexture_.id(), 0, 0, image.height - 1 - y, image.width, 1, GL_RGBA, GL_FLOAT,
                          &image.rgba[image.offset(0, y)]);
    baselineValid_ = true;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbWidth_, fbHeight_);
  glDisable(GL_SCISSOR_TEST);
  const float background[] = {0.08f, 0.08f, 0.09f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, background);
  const PixelRect imageRect = toPixels(imageRect_);
  if (showBaseline_ && baselineValid_) imageDrawer_.draw(baselineTexture_.id(), imageRect);
  else if (resolved_) imageDrawer_.draw(resolved_->colorTexture(), imageRect);
  if (showOutside_) drawOutside(toPixels(outsideRect_));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbWidth_, fbHeight_);
}

// ---- the panel ----

bool dragDouble3(const char* label, glm::dvec3& v, float speed) {
  return ImGui::DragScalarN(label, ImGuiDataType_Double, &v.x, 3, speed, nullptr, nullptr, "%.4g");
}
bool dragDouble(const char* label, double& v, float speed, double lo, double hi, const char* format = "%.4g") {
  return ImGui::DragScalar(label, ImGuiDataType_Double, &v, speed, &lo, &hi, format, ImGuiSliderFlags_AlwaysClamp);
}
void matrixTable(const char* name, const glm::dmat4& m) {
  ImGui::TextUnformatted(name);
  for (int row = 0; row < 4; ++row)  // GLM is column-major: m[column][row]
    ImGui::Text("  %9.4f %9.4f %9.4f %9.4f", m[0][row], m[1][row], m[2][row], m[3][row]);
}

void Viewer::adoptPhysical(const PhysicalCamera& physical) {
  const Camera before = cam_.camera;
  cam_ = fromPhysical(physical, before.source);
  cam_.camera.effects = before.effects;
  cam_.camera.calibratedSize = before.calibratedSize;
}

void Viewer::cameraEdited(const Camera& camera) {
  cam_.camera = camera;
  cam_.physical.reset();
  dirty_ = true;
}

void Viewer::sectionProgress() {
  const int done = renderer_.samplesDone(), planned = renderer_.samplesPlanned();
  ImGui::ProgressBar(static_cast<float>(done) / static_cast<float>(std::max(planned, 1)), ImVec2(-FLT_MIN, 0),
                     cat(done, " / ", planned, " samples").c_str());
  ImGui::Text("%.2f ms per sample, %.0f ms accumulated", msPerSample_, accumulationMs_);
  if (convergedAfterMs_ >= 0.0) ImGui::Text("converged %.0f ms after the last change", convergedAfterMs_);
  else ImGui::Text("converging (%.1f fps)", static_cast<double>(ImGui::GetIO().Framerate));
  if (showBaseline_) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "showing the post-process baseline (%d taps)", baselineTaps_);
  ImGui::Text("image %d x %d; focus distance %.4g", size_.widthPx, size_.heightPx,
              cam_.camera.focusAtInfinity ? std::numeric_limits<double>::infinity() : cam_.camera.view.prp.z);
}

void Viewer::sectionLecture() {
  if (!ImGui::CollapsingHeader("Viewing description (lecture)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  Camera c = cam_.camera;
  ViewSpec& s = c.view;
  const float step = static_cast<float>(0.005 * std::max(1.0, s.prp.z));
  bool changed = false;
  int projection = s.projection == Projection::Perspective ? 0 : 1;
  if (ImGui::Combo("projection", &projection, "perspective\0parallel\0")) {
    s.projection = projection == 0 ? Projection::Perspective : Projection::Parallel;
    if (s.projection == Projection::Parallel && std::isinf(s.farDistance)) s.farDistance = 1000.0 * s.prp.z;
    if (s.projection == Projection::Parallel) c.focusAtInfinity = false;
    changed = true;
  }
  changed |= dragDouble3("VRP (world)", s.vrp, step);
  changed |= dragDouble3("VPN (world)", s.vpn, 0.005f);
  changed |= dragDouble3("VUP (world)", s.vup, 0.005f);
  changed |= dragDouble3("PRP (u, v, n)", s.prp, step);
  changed |= ImGui::DragScalarN("window", ImGuiDataType_Double, &s.window.umin, 4, step, nullptr, nullptr, "%.4g");
  changed |= dragDouble("near", s.nearDistance, step * 0.1f, 0.0, 1e9);
  bool farInfinite = std::isinf(s.farDistance);
  if (ImGui::Checkbox("far at infinity", &farInfinite)) {
    s.farDistance = farInfinite ? std::numeric_limits<double>::infinity() : 1000.0 * s.prp.z;
    changed = true;
  }
  if (!farInfinite) changed |= dragDouble("far", s.farDistance, step * 10.0f, 0.0, 1e12);
  changed |= dragDouble("aperture radius", c.apertureRadius, step * 0.01f, 0.0, 1e6);
  if (changed) cameraEdited(c);
  // Focus distance: moves the view plane (the plane of focus), keeping the field of view.
  double focus = cam_.camera.view.prp.z;
  if (dragDouble("focus distance", focus, step, 1e-4, 1e9)) {
    try {
      cam_.camera = refocused(cam_.camera, focus, "focus distance");
      if (cam_.physical) cam_.physical->focusDistance = focus;
      dirty_ = true;
    } catch (const InputError& e) {
      reportError(e.what());
    }
  }
}

void Viewer::sectionMatrices() {
  if (!ImGui::CollapsingHeader("Matrices (clipFromWorld = clipFromEye * eyeFromView * viewFromWorld)")) return;
  const ViewSpec& s = cam_.camera.view;
  const ViewBasis b = viewBasis(s);
  ImGui::Text("u = (%.3f %.3f %.3f)", b.u.x, b.u.y, b.u.z);
  ImGui::Text("v = (%.3f %.3f %.3f)", b.v.x, b.v.y, b.v.z);
  ImGui::Text("n = (%.3f %.3f %.3f)", b.n.x, b.n.y, b.n.z);
  matrixTable("viewFromWorld", viewFromWorld(s));
  matrixTable("eyeFromView", eyeFromView(s));
  if (s.projection == Projection::Perspective) matrixTable("lecture perspective (1/f)", lecturePerspective(s.prp.z));
  matrixTable("clipFromEye (reverse-Z)", clipFromEye(s));
  matrixTable("clipFromWorld", clipFromWorld(s));
}

void Viewer::sectionPhysical() {
  if (!ImGui::CollapsingHeader("Physical lens", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (!cam_.physical) {
    const ViewSpec& s = cam_.camera.view;
    const bool centred = s.projection == Projection::Perspective &&
                         glm::length(glm::dvec2(s.prp.x, s.prp.y) - s.window.center()) < 1e-9 * std::max(1.0, s.prp.z);
    ImGui::TextWrapped("The camera is in the lecture form.");
    if (!centred) {
      ImGui::TextWrapped("(A physical lens needs a perspective projection with the PRP over the window centre.)");
      return;
    }
    if (ImGui::Button("Describe it as a lens (35 mm)")) {
      try {
        const glm::dvec2 sensor(36.0, 36.0 * s.window.height() / s.window.width());
        PhysicalCamera p = toPhysical(s, sensor);
        if (cam_.camera.apertureRadius > 0.0)
          p.fNumber = p.focalLengthMm * kMetresPerMillimetre / (2.0 * cam_.camera.apertureRadius);
        if (cam_.camera.focusAtInfinity) p.focusDistance = std::numeric_limits<double>::infinity();
        adoptPhysical(p);
        dirty_ = true;
      } catch (const InputError& e) {
        reportError(e.what());
      }
    }
    return;
  }
  PhysicalCamera p = *cam_.physical;
  bool changed = false;
  const float step = static_cast<float>(0.005 * std::max(1.0, glm::length(p.target - p.eye)));
  changed |= dragDouble3("eye", p.eye, step);
  changed |= dragDouble3("target", p.target, step);
  changed |= dragDouble3("up", p.up, 0.005f);
  changed |= dragDouble("focal length (mm)", p.focalLengthMm, 0.2f, 1.0, 2000.0);
  changed |= ImGui::DragScalarN("sensor (mm)", ImGuiDataType_Double, &p.sensorMm.x, 2, 0.1f, nullptr, nullptr, "%.4g");
  bool pinhole = std::isinf(p.fNumber);
  if (ImGui::Checkbox("pinhole (no aperture)", &pinhole)) {
    p.fNumber = pinhole ? std::numeric_limits<double>::infinity() : 2.8;
    changed = true;
  }
  if (!pinhole) changed |= dragDouble("f-number", p.fNumber, 0.02f, 0.5, 64.0, "f/%.2f");
  bool infinityFocus = std::isinf(p.focusDistance);
  if (ImGui::Checkbox("focus at infinity", &infinityFocus)) {
    p.focusDistance = infinityFocus ? std::numeric_limits<double>::infinity() : glm::length(p.target - p.eye);
    changed = true;
  }
  if (!infinityFocus) changed |= dragDouble("focus distance (m)", p.focusDistance, step, 1e-3, 1e9);
  if (changed) {
    try {
      adoptPhysical(p);
      dirty_ = true;
    } catch (const InputError& e) {
      reportError(e.what());
    }
  }
}

void Viewer::sectionSamples() {
  if (!ImGui::CollapsingHeader("Aperture samples", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int pattern = static_cast<int>(planOptions_.pattern);
  if (ImGui::Combo("pattern", &pattern, kPatterns, 4)) {
    planOptions_.pattern = static_cast<AperturePattern>(pattern);
    dirty_ = true;
  }
  bool automatic = planOptions_.apertureSamples == 0;
  if (ImGui::Checkbox("auto sample count", &automatic)) {
    planOptions_.apertureSamples = automatic ? 0 : std::max(plan_.apertureSamples, 1);
    dirty_ = true;
  }
  if (automatic) {
    dirty_ |= ImGui::SliderInt("max samples", &planOptions_.maxSamples, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  } else {
    dirty_ |= ImGui::SliderInt("samples", &planOptions_.apertureSamples, 1, 4096, "%d", ImGuiSliderFlags_Logarithmic);
  }
  int seed = static_cast<int>(planOptions_.seed);
  if (ImGui::InputInt("seed", &seed)) {
    planOptions_.seed = static_cast<std::uint32_t>(std::max(seed, 0));
    dirty_ = true;
  }
  ImGui::TextWrapped("N = %d: %s", plan_.apertureSamples, plan_.samplesWhy.c_str());
  ImGui::Text("circle of confusion in view: %.2f to %.2f px", plan_.cocMinPx, plan_.cocMaxPx);
}

// The lecture's last part: distortion, chromatic aberration, the curved focal plane. Each adds a
// pass or shader variant only when it is not zero; the plan's passes are listed to show it.
void Viewer::sectionLensEffects() {
  if (!ImGui::CollapsingHeader("Lens effects", ImGuiTreeNodeFlags_DefaultOpen)) return;
  Camera c = cam_.camera;
  LensEffects& e = c.effects;
  bool changed = false;
  ImGui::TextWrapped("Distortion: Brown-Conrady in OpenCV's order (normalised coordinates about the principal point)");
  changed |= dragDouble("k1", e.distortion.k1, 0.002f, -2.0, 2.0);
  changed |= dragDouble("k2", e.distortion.k2, 0.002f, -2.0, 2.0);
  changed |= dragDouble("k3", e.distortion.k3, 0.002f, -2.0, 2.0);
  changed |= dragDouble("p1", e.distortion.p1, 0.0002f, -0.2, 0.2);
  changed |= dragDouble("p2", e.distortion.p2, 0.0002f, -0.2, 0.2);
  if (ImGui::TreeNode("the lecture's series: rho = rho'(1 + a rho' + b rho'^2 + c rho'^3)")) {
    changed |= dragDouble("alpha", e.distortion.alpha, 0.002f, -2.0, 2.0);
    changed |= dragDouble("beta", e.distortion.beta, 0.002f, -2.0, 2.0);
    changed |= dragDouble("gamma", e.distortion.gamma, 0.002f, -2.0, 2.0);
    ImGui::TreePop();
  }
  ImGui::TextWrapped("Chromatic aberration: lateral = red/blue magnification relative to green; axial = "
                     "each colour's plane of focus, as a change of 1/focus distance (1/world unit)");
  changed |= dragDouble("lateral red", e.chromatic.lateralRed, 0.0002f, -0.1, 0.1);
  changed |= dragDouble("lateral blue", e.chromatic.lateralBlue, 0.0002f, -0.1, 0.1);
  changed |= dragDouble("axial red (1/m)", e.chromatic.inverseFocusShiftRed, 0.002f, -10.0, 10.0);
  changed |= dragDouble("axial blue (1/m)", e.chromatic.inverseFocusShiftBlue, 0.002f, -10.0, 10.0);
  const double focus = cam_.camera.inverseFocusDistance();
  const auto distance = [](double inverse) { return inverse > 0.0 ? 1.0 / inverse : std::numeric_limits<double>::infinity(); };
  if (e.chromatic.hasAxial())
    ImGui::Text("red in focus at %.4g, green %.4g, blue %.4g", distance(focus + e.chromatic.inverseFocusShiftRed),
                distance(focus), distance(focus + e.chromatic.inverseFocusShiftBlue));
  ImGui::TextWrapped("Field curvature: 1/focus distance grows by this times r^2 toward the corners");
  changed |= dragDouble("curvature (1/m per r^2)", e.fieldCurvature.inverseFocusPerRadius2, 0.005f, -20.0, 20.0);
  if (!e.fieldCurvature.isZero()) {
    const double corner = normalisedWindow(c.view).cornerRadius();
    ImGui::Text("centre in focus at %.4g, corners at %.4g", distance(focus),
                distance(focus + e.fieldCurvature.inverseFocusPerRadius2 * corner * corner));
  }
  if (ImGui::Button("no lens effects")) {
    e = LensEffects{};
    changed = true;
  }
  if (changed) {
    try {
      validateLensEffects(c, "the panel's lens");
      cam_.camera = c;
      dirty_ = true;
    } catch (const InputError& error) {
      reportError(error.what());
    }
  }
  std::string passes;
  for (const PlannedPass& pass : plan_.passes) {
    passes += (passes.empty() ? "" : ", ") + pass.name;
    for (const std::string& variant : pass.variants) passes += "+" + variant;
  }
  ImGui::TextWrapped("passes: %s", passes.c_str());
  for (const std::string& warning : plan_.warnings) ImGui::TextWrapped("note: %s", warning.c_str());
}

void Viewer::sectionCompare() {
  if (!ImGui::CollapsingHeader("Compare and outside view", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::Checkbox("show the post-process gather baseline", &showBaseline_)) baselineValid_ = false;
  if (showBaseline_ && ImGui::SliderInt("gather taps", &baselineTaps_, 8, 128)) baselineValid_ = false;
  if (ImGui::Checkbox("outside view (the lecture's diagram)", &showOutside_)) outsideDirty_ = true;
  if (showOutside_) {
    ImGui::TextWrapped("Yellow: PRP. White: window on the view plane (plane of focus). Grey: view volume. "
                       "Cyan: aperture; orange: samples done. Red: rays through the window centre.");
    ImGui::Checkbox("enlarge the aperture in the diagram", &enlargeAperture_);
    if (enlargeAperture_ && !cam_.camera.isPinhole())
      ImGui::Text("aperture drawn x%.0f (radius %.4g)", readableApertureScale(cam_.camera), cam_.camera.apertureRadius);
  }
}

void Viewer::sectionFiles() {
  if (!ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::InputText("##camera", cameraPath_.data(), cameraPath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save camera")) {
    try {
      writeTextFileAtomically(cameraPath_.data(), toCameraJson(cam_.camera));
      status_ = cat("wrote ", cameraPath_.data(), " (lenslab render --camera loads it)");
    } catch (const std::exception& e) {
      reportError(e.what());
    }
  }
  ImGui::InputText("##image", imagePath_.data(), imagePath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save image")) {
    try {
      checkImageExtension(imagePath_.data());
      writeImage(imagePath_.data(), renderer_.resolve());
      status_ = cat("wrote ", imagePath_.data(), " (", renderer_.samplesDone(), " samples)");
    } catch (const std::exception& e) {
      reportError(e.what());
    }
  }
  ImGui::InputText("##window", windowPath_.data(), windowPath_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save window")) saveWindowPending_ = true;  // read once this frame is drawn
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
}

void Viewer::sectionHelp() {
  if (!ImGui::CollapsingHeader("Controls")) return;
  ImGui::TextWrapped("Click the image: focus there. Left drag: orbit about the focus point. Right drag: look "
                     "around from the PRP. Wheel: move forward. W/A/S/D/Q/E: fly (Shift: faster). "
                     "Outside view: left drag orbits, wheel zooms. Ctrl+click a field to type. Esc: quit.");
}

void Viewer::panel() {
  const float width = static_cast<float>(windowWidth_) - static_cast<float>(imageRect_.x + std::max(imageRect_.width, outsideRect_.width));
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(windowWidth_) - width, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(windowHeight_)));
  ImGui::Begin("lenslab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.0f);  // room for the labels on the right
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::TextWrapped("%s", cam_.camera.source.c_str());
  sectionProgress();
  sectionLecture();
  sectionMatrices();
  sectionPhysical();
  sectionSamples();
  sectionLensEffects();
  sectionCompare();
  sectionFiles();
  sectionHelp();
  ImGui::PopItemWidth();
  ImGui::End();
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
    j["renderer"] = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
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
    if (scripted()) glFinish();  // scripted frames are timed with the GPU done
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

}  // namespace

int runView(const ViewOptions& o) {
  if (!o.screenshot.empty()) checkImageExtension(o.screenshot);  // fail before any work
  if (o.frames < 0) throw InputError(cat("--frames ", o.frames, ": give a number of frames (0 = interactive)"));
  if (!o.screenshot.empty() && o.frames == 0) throw InputError("--screenshot needs --frames N (scripted mode)");
  const PlanOptions planOptions = toPlanOptions(o.lens);
  const auto [scenePath, cameraPath] = resolveSceneAndCamera(o.scene, o.cameraFile, "camera.json");
  const Scene scene = loadGltf(scenePath);
  if (scene.triangleCount() == 0) throw InputError(cat(scenePath.string(), ": the scene has no triangles to render"));
  const double requestedAspect = o.width && o.height ? static_cast<double>(*o.width) / *o.height : 0.0;
  const SelectedCamera selected = selectCamera(scene, cameraPath, requestedAspect);
  EditableCamera camera{applyLensOptions(selected.camera, o.lens), selected.physical};
  if (!o.lens.focusDistance.empty()) camera.physical.reset();  // refocused in the lecture form
  // Interactive default: 640 px wide, so that llvmpipe keeps up; scripted runs follow `render`.
  const std::optional<int> width = o.width || o.height || o.frames > 0 ? o.width : std::optional<int>(640);
  const ImageSize size = resolveImageSize(camera.camera, width, o.height);

  GlfwLibrary glfw;
  const glm::ivec2 windowSize = o.windowSize ? *o.windowSize
                                : o.noUi     ? glm::ivec2(size.widthPx, size.heightPx)
                                             : glm::ivec2(1440, 900);
  WindowOwner window(windowSize.x, windowSize.y);
  glfwMakeContextCurrent(window.window);
  loadGlFunctions(glfwGetProcAddress, "the GLFW window");
  ImGuiSession imgui(window.window);
  Viewer viewer(o, window.window, scene, std::move(camera), size, planOptions);
  return viewer.run();
}

}  // namespace lenslab::view
