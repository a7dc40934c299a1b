#pragma once
// `lenslab view`: the interactive window demo. A GLFW window with a GL 4.5 core context, the
// camera's image converging by progressive accumulation, a Dear ImGui panel with every camera and
// lens parameter, and an outside view that draws the lecture's diagram of the camera in the scene.
// Scripted mode (--frames) runs a fixed number of frames and writes a screenshot, for tests.
#include "camera/Exposure.h"
#include "io/EnvironmentFile.h"
#include "plan/CameraOptions.h"
#include "plan/UserOptions.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace lenslab::view {

struct ViewOptions {
  std::string scene;
  std::string cameraFile;
  std::optional<int> width;  // the rendered image, as in `render`
  std::optional<int> height;
  LensOptions lens;
  CameraOptions camera;               // lens, pose, glTF camera and animation clip over the base camera
  std::optional<double> timeSeconds;  // pose the playing animation at this time; none = the rest pose
  std::optional<glm::vec3> background;
  int frames = 0;                        // > 0: scripted; run at least this many frames, then exit
  std::string screenshot;                // written at the end of a scripted run (.png or .exr)
  bool noUi = false;                     // no panel, no outside view: the screenshot is the image alone
  bool outsideView = true;               // start with the outside view shown
  bool showBaseline = false;             // start showing the post-process gather baseline
  std::optional<glm::dvec2> click;       // a scripted click in the image (image pixels)
  std::string statsFile;                 // what a scripted run did, as JSON
  std::string saveCamera;                // scripted: the camera at the end, as the panel's "Save camera" writes it
  std::optional<glm::ivec2> windowSize;  // window size in screen coordinates
  double frameBudgetMs = 16.0;           // accumulation work per frame (at least one sample)
  ExposureRequest exposure;              // the display's starting exposure, as render's (io/ToneMap.h)
  std::string viewTransform = "none";    // and view transform; the panel changes both
  EnvironmentRequest environment;        // --environment and its intensity and rotation
};

// Returns the exit code; throws InputError for bad input (files, cameras, options) and
// std::runtime_error when no window can be opened.
int runView(const ViewOptions& options);

}  // namespace lenslab::view
