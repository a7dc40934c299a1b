#pragma once
// --stats: what a run did, as JSON, for scripts and reports.
#include "app/LensRequest.h"
#include "camera/Exposure.h"
#include "camera/ImageSize.h"
#include "camera/PhysicalCamera.h"
#include "io/AtomicFile.h"
#include "io/EnvironmentFile.h"
#include "io/ToneMap.h"
#include "plan/FramePlan.h"
#include "plan/TileBudget.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lenslab {

struct RunStats {
  std::string command;
  std::string scene;
  std::string camera;
  ImageSize size;
  std::string backend;
  std::string renderer;
  std::size_t triangles = 0;
  FramePlan plan;
  double seconds = 0.0;                   // the whole command, from start to the image written
  double contextSeconds = 0.0;            // creating the GL context
  double setupSeconds = 0.0;              // uploading the scene and compiling shaders
  double renderSeconds = 0.0;             // the frame, GPU work finished (glFinish), with read-back
  double writeSeconds = 0.0;              // encoding and writing the image
  double prepassSeconds = 0.0;            // the pinhole depth pre-pass and its blur map (part of renderSeconds)
  std::optional<FrameEstimate> estimate;  // with --target-psnr
  // The lens as rendered (after --focus-distance / --focus-at): "lens" in the JSON.
  double focusDistance = 0.0;              // from the PRP along the view direction; +infinity allowed
  double apertureRadius = 0.0;             // world units; 0 = a pinhole
  ApertureShape aperture;                  // its shape (lens/ApertureShape.h)
  LensBarrel barrel;                       // the barrel in front of it (lens/LensBarrel.h)
  std::optional<PhysicalCamera> physical;  // focal length, f-number, sensor, eye, target when there is one
  // How PNG output shows the radiance (app/ExposureOptions.h): "display" in the JSON.
  Exposure exposure;
  ViewTransform viewTransform = ViewTransform::None;
  // The environment (--environment): "environment" in the JSON, absent without one.
  std::optional<EnvironmentSummary> environment;

  // With --lens: the focus distance asked for and, where the fitted lens focuses elsewhere, why.
  std::optional<double> askedFocusDistance;
  std::string focusNote;

  // The camera's source, focus, aperture and physical description.
  void setCamera(const SelectedCamera& selected);
  // The same for the thin lens fitted to a real one, with what `focus` says of its focus.
  void setCamera(const SelectedCamera& fitted, const FocusExplanation& focus);
  // The exposure and view transform.
  void setDisplay(const DisplaySettings& display) {
    exposure = display.exposure;
    viewTransform = display.encoding.transform;
  }
};

std::string toJson(const RunStats& stats);
// Into `outputs`: the file appears with the run's image when the set is committed, or not at all.
void writeStats(OutputSet& outputs, const std::filesystem::path& path, const RunStats& stats);

}  // namespace lenslab
