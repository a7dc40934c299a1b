#pragma once
// --exposure, --shutter, --iso and --view-transform (render, raycast, capture, view): the options of
// app/ExposureSettings.h.
#include "app/ExposureSettings.h"

#include <CLI/CLI.hpp>

#include <string>

namespace lenslab {

void addExposureOptions(CLI::App& command, ExposureRequest& request, std::string& viewTransform);
inline void addExposureOptions(CLI::App& command, ExposureOptions& o) {
  addExposureOptions(command, o.request, o.viewTransform);
}

}  // namespace lenslab
