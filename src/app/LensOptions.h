#pragma once
// The lens options that `render` (and later `raycast`, `sweep`, `view`) share: aperture pattern,
// sample count, seed, focus.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "plan/FramePlan.h"
#include "scene/Scene.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
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

// --background R,G,B: the colour (linear RGB, each finite and ≥ 0) where no surface is seen; it
// replaces the scene's. Shared by render, raycast, sweep and view.
void addBackgroundOption(CLI::App& command, std::optional<glm::vec3>& background);
void applyBackground(Scene& scene, const std::optional<glm::vec3>& background);

// Throws InputError for a bad --pattern or --aperture-samples.
PlanOptions toPlanOptions(const LensOptions& options);

// --focus-distance applied to the camera.
Camera applyLensOptions(const Camera& camera, const LensOptions& options);

// Focuses on the depth under pixel (x, y) of a pinhole view, as `depthAt(camera, size, x, y)`
// reports it (world units from the PRP along −n, +infinity for background); throws InputError when
// nothing is there or the pixel is outside the image. With distortion or lateral colour the pixel is
// first taken back to the true perspective image (green's), which is looked up in the overscanned
// pinhole view the lens pass would sample.
using DepthAtPixel = std::function<double(const Camera&, ImageSize, int x, int y)>;
Camera focusOnPixel(const Camera& camera, ImageSize size, glm::dvec2 pixel, const DepthAtPixel& depthAt);

// depthAt through the rasterizer's pinhole depth buffer.
DepthAtPixel rasterDepth(Renderer& renderer);

bool isTerminal(std::FILE* stream);
void printProgress(int done, int total, double seconds);

}  // namespace lenslab
