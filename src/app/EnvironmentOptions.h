#pragma once
// --environment FILE, --environment-intensity X and --environment-rotation DEG (render, raycast,
// capture, view, sweep): an equirectangular .hdr or .exr as the background and the image light
// (io/EnvironmentFile.h, docs/environment.md).
#include "io/EnvironmentFile.h"

#include <CLI/CLI.hpp>

namespace lenslab {

void addEnvironmentOptions(CLI::App& command, EnvironmentRequest& request);

}  // namespace lenslab
