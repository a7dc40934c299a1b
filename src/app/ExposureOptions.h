#pragma once
// --exposure, --shutter, --iso and --view-transform (render, raycast, capture, view): how a run's
// PNG files and the viewer's window show its linear radiance (docs/exposure.md). The EXR files
// never go through them.
#include "camera/Exposure.h"
#include "io/ToneMap.h"

#include <CLI/CLI.hpp>

#include <string>

namespace lenslab {

struct ExposureOptions {
  ExposureRequest request;             // --exposure EV, or --shutter SECONDS and --iso ISO
  std::string viewTransform = "none";  // --view-transform NAME (io/ToneMap.h)
};

void addExposureOptions(CLI::App& command, ExposureRequest& request, std::string& viewTransform);
inline void addExposureOptions(CLI::App& command, ExposureOptions& o) {
  addExposureOptions(command, o.request, o.viewTransform);
}

// resolveDisplay (io/ToneMap.h) of the options.
inline DisplaySettings resolveDisplay(const ExposureOptions& o, const SelectedCamera& camera) {
  return resolveDisplay(o.request, o.viewTransform, camera);
}

// --shutter's text: seconds ("0.008") or a fraction as photographers write it ("1/125"). Throws
// InputError naming the option and the range.
double parseShutterSeconds(const std::string& text);

}  // namespace lenslab
