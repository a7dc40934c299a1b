#pragma once
// The lens options that `render` (and later `raycast`, `sweep`, `view`) share: aperture pattern,
// sample count, seed, focus.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "plan/FramePlan.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>

namespace lenslab {

class Renderer;

struct LensOptions {
  std::string pattern = "concentric";
  std::string apertureSamples = "auto";
  int maxSamples = 256;
  std::uint32_t seed = 1;
  std::string focusDistance;              // a number or "infinity"; empty = the camera's
  std::optional<glm::dvec2> focusAt;      // pixel (x, y), from "X,Y"
};

void addLensOptions(CLI::App& command, LensOptions& options);

// Throws InputError for a bad --pattern or --aperture-samples.
PlanOptions toPlanOptions(const LensOptions& options);

// --focus-distance applied to the camera.
Camera applyLensOptions(const Camera& camera, const LensOptions& options);

// Focuses on the depth under pixel (x, y) of a pinhole view; throws InputError when nothing is
// there (background) or the pixel is outside the image.
Camera focusOnPixel(Renderer& renderer, const Camera& camera, ImageSize size, glm::dvec2 pixel);

bool isTerminal(std::FILE* stream);
void printProgress(int done, int total, double seconds);

}  // namespace lenslab
