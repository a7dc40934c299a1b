// lenslab view: the interactive window demo (src/view/ViewApp.h), and its scripted mode for tests.
#include "app/CliOptions.h"
#include "app/Commands.h"
#include "app/EnvironmentOptions.h"
#include "app/ExposureOptions.h"
#include "core/Error.h"
#include "core/ParseNumber.h"
#include "io/OutputPath.h"
#include "view/ViewApp.h"

#include <cmath>
#include <memory>

namespace lenslab {

std::function<int()> addViewCommand(CLI::App& app) {
  auto o = std::make_shared<view::ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Open a window: the image converging, every camera and lens parameter, click to focus, the lecture's diagram");
  cmd->add_option("scene", o->scene, "glTF 2.0 scene (.gltf or .glb); default: the bundled 'rows' scene");
  cmd->add_option("--camera", o->cameraFile,
                  "camera JSON (lecture, physical or OpenCV-intrinsics form, with any lens effects); default as for "
                  "render; the lens "
                  "and pose options override it field by field");
  cmd->add_option("--width", o->width, "image width in pixels (default 640 in a window, 960 scripted as in render)");
  cmd->add_option("--height", o->height, "image height in pixels");
  addSamplingOptions(*cmd, o->lens);
  addSeedOption(*cmd, o->lens);
  addFocusOptions(*cmd, o->lens);
  addLensOverrideOptions(*cmd, o->lens);
  addTargetOption(*cmd, o->lens);
  addCameraOptions(*cmd, o->camera);
  addTimeOption(
      *cmd, o->timeSeconds,
      "pose the scene's glTF animation at this time (seconds), as render --time does; default: the rest pose");
  addBackgroundOption(*cmd, o->background);
  addExposureOptions(*cmd, o->exposure, o->viewTransform);
  addEnvironmentOptions(*cmd, o->environment);
  cmd->add_option(
      "--frames", o->frames,
      "scripted: run at least N frames (and on until the accumulation is complete), write --screenshot, exit");
  cmd->add_option("--screenshot", o->screenshot,
                  "scripted: .png or .exr; the window with the panel, or with --no-ui the image as render writes it");
  cmd->add_flag("--no-ui", o->noUi, "no panel and no outside view: the window shows the image only");
  cmd->add_flag("!--no-outside-view", o->outsideView, "start without the outside view");
  cmd->add_flag("--baseline", o->showBaseline, "start showing the post-process gather depth of field (for comparison)");
  addPairOption(*cmd, "--click", [o](double x, double y) { o->click = glm::dvec2(x, y); },
                "scripted: click image pixel X,Y on the first frame (focus there)", {.unit = "pixels"});
  addPairOption(*cmd, "--window-size",
                [o](double w, double h) { o->windowSize = glm::ivec2(static_cast<int>(w), static_cast<int>(h)); },
                "window size W,H in screen coordinates", {.min = 1.0, .max = 16384.0, .unit = "screen coordinates"})
      ->check([](const std::string& text) {
        const std::optional<double> v = parseDouble(text);
        return v && *v == std::floor(*v) ? std::string()
                                         : std::string("give the window size as two whole numbers from 1 to 16384");
      });
  cmd->add_option("--frame-budget-ms", o->frameBudgetMs, "accumulation work per frame, at least one sample")
      ->check(numberIn({.min = 1.0, .max = 1000.0, .unit = "milliseconds"}))
      ->capture_default_str();
  addColmapOptions(*cmd, o->camera);
  cmd->add_option("--save-camera", o->saveCamera,
                  "scripted: write the final camera as JSON (lecture form), as the panel's Save camera does");
  cmd->add_option("--stats", o->statsFile, "scripted: write frames, samples, ms per sample and focus distance as JSON");
  return [cmd, o]() {
    if (!cmd->parsed()) return -1;
    // The viewer's image converges frame by frame; its panel's slider is its exposure meter.
    if (o->exposure.meter)
      throw InputError(
          "--exposure auto: view takes --exposure EV (the panel's Display slider changes it); auto meters a finished "
          "frame in render, raycast and capture");
    // Each file the scripted run writes is checked before the window opens (io/OutputPath.h).
    if (!o->screenshot.empty()) checkOutputPath(o->screenshot, OutputKind::Image, "--screenshot");
    if (!o->saveCamera.empty()) checkOutputPath(o->saveCamera, OutputKind::Any, "--save-camera");
    if (!o->statsFile.empty()) checkOutputPath(o->statsFile, OutputKind::Json, "--stats");
    return view::runView(*o);
  };
}

}  // namespace lenslab
