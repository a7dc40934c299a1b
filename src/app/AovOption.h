#pragma once
// --aov LIST (render, raycast, capture): the AOVs (core/Aovs.h) written as EXR channels beside
// the image (io/AovChannels.h names them).
#include "core/Aovs.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

// Registers --aov on `command`: a comma-separated list (or the option repeated), each name one of
// aovNames(); an unknown name is refused by CLI11 in one line naming the valid ones.
void addAovOption(CLI::App& command, std::vector<std::string>& names);

// Throws InputError (one line: --aov, the file, why) unless `image` can hold the AOVs: an EXR.
// Nothing to check when none is selected.
void checkAovOutput(const AovSelection& selection, const std::filesystem::path& image, const std::string& outOption);

}  // namespace lenslab
