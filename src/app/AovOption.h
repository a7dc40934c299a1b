#pragma once
// --aov LIST, --aov-format and --normal-convention (render, raycast, capture): the options of
// app/AovOutputs.h.
#include "app/AovOutputs.h"

#include <CLI/CLI.hpp>

namespace lenslab {

// Registers --aov (a comma-separated list, or the option repeated, each name one of aovNames()),
// --aov-format and --normal-convention on `command`; CLI11 refuses an unknown value in one line
// naming the valid ones.
void addAovOptions(CLI::App& command, AovRequest& request);

}  // namespace lenslab
