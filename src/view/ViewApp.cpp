// lenslab view: GLFW's and Dear ImGui's lifetimes, and the Viewer they serve (Viewer.h). glad is
// loaded for the GLFW context (the renderer's GL calls go through it); Dear ImGui's OpenGL3
// backend brings its own loader.
#include "view/Viewer.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "core/Error.h"
#include "core/Text.h"
#include "gl/GlContext.h"
#include "plan/CameraSelection.h"
#include "io/ImageFile.h"
#include "plan/TilePlan.h"
#include "scene/GltfLoader.h"

#include <iostream>
#include <stdexcept>

namespace lenslab::view {
namespace {

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
      throw std::runtime_error(
          cat("cannot start GLFW (", lastGlfwError(), "); is DISPLAY set? Under CI: Xvfb :99 & DISPLAY=:99"));
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
    if (!window)
      throw std::runtime_error(cat("cannot open a window with an OpenGL 4.5 core context (", lastGlfwError(), ")"));
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

}  // namespace

int runView(const ViewOptions& o) {
  if (!o.screenshot.empty()) checkImageExtension(o.screenshot);  // fail before any work
  if (o.frames < 0) throw InputError(cat("--frames ", o.frames, ": give a number of frames (0 = interactive)"));
  // The scripted run's files are written when it ends; a window a person closes writes none.
  if (!o.screenshot.empty() && o.frames == 0) throw InputError("--screenshot needs --frames N (scripted mode)");
  if (!o.statsFile.empty() && o.frames == 0) throw InputError("--stats needs --frames N (scripted mode)");
  if (!o.saveCamera.empty() && o.frames == 0)
    throw InputError(
        "--save-camera needs --frames N (scripted mode); in the window, the panel's Save camera writes it");
  const PlanOptions planOptions = toPlanOptions(o.lens);
  const auto [scenePath, cameraPath] =
      resolveSceneAndCamera(o.scene, o.cameraFile, o.camera.namesBaseCamera() ? "" : "camera.json");
  Scene scene = loadGltf(scenePath);
  applyBackground(scene, o.background);
  applyEnvironment(scene, o.environment, std::cerr);
  for (const std::string& w : poseForOneImage(scene, o.camera.animation, o.timeSeconds))
    std::cerr << "lenslab: warning: " << w << "\n";
  if (scene.triangleCount() == 0) throw InputError(cat(scenePath.string(), ": the scene has no triangles to render"));
  const double requestedAspect = o.width && o.height ? static_cast<double>(*o.width) / *o.height : 0.0;
  const SelectedCamera selected = chooseCamera(scene, cameraPath, o.camera, requestedAspect);
  const SelectedCamera refocusedCamera = applyLensOptions(selected, o.lens);
  for (const std::string& w : focusWarnings(selected.camera, o.lens)) std::cerr << "lenslab: warning: " << w << "\n";
  EditableCamera camera{refocusedCamera.camera, refocusedCamera.physical};
  const DisplaySettings display = resolveDisplay(o.exposure, o.viewTransform, refocusedCamera);
  // Interactive default: 640 px wide, so that llvmpipe keeps up; scripted runs follow `render`.
  const int defaultWidth = o.frames > 0 ? kDefaultWidthPx : 640;
  const ImageSize size = resolveImageSize(camera.camera, o.width, o.height, defaultWidth);
  if (const std::string shape = pixelShapeWarning(camera.camera, o.width, o.height, size); !shape.empty())
    std::cerr << "lenslab: warning: " << shape << "\n";
  requireOneTarget(size, RenderTargetLimits{}, "view");

  GlfwLibrary glfw;
  const glm::ivec2 windowSize = o.windowSize ? *o.windowSize
                                : o.noUi     ? glm::ivec2(size.widthPx, size.heightPx)
                                             : glm::ivec2(1440, 900);
  WindowOwner window(windowSize.x, windowSize.y);
  glfwMakeContextCurrent(window.window);
  loadGlFunctions(glfwGetProcAddress, "the GLFW window");
  ImGuiSession imgui(window.window);
  Viewer viewer(o, window.window, scene, std::move(camera), size, planOptions, display);
  return viewer.run();
}

}  // namespace lenslab::view
