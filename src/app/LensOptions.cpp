#include "app/LensOptions.h"

#include "camera/LensMap.h"
#include "camera/Projection.h"
#include "core/Error.h"
#include "core/Text.h"
#include "render/Renderer.h"

#include <cmath>
#include <iostream>
#include <unistd.h>

namespace lenslab {

void addLensOptions(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--pattern", o.pattern, "aperture pattern: " + patternNames())
      ->check(CLI::IsMember({"lecture17", "concentric", "r2", "random"}))
      ->capture_default_str();
  cmd.add_option("--aperture-samples", o.apertureSamples,
                 "scene passes, one per aperture point: a number, or auto (from the largest circle of confusion in view)")
      ->capture_default_str();
  cmd.add_option("--max-samples", o.maxSamples, "the most aperture samples auto may choose")
      ->check(CLI::Range(1, 65536))
      ->capture_default_str();
  cmd.add_option("--seed", o.seed, "seed for the aperture and sub-pixel samples")->capture_default_str();
  cmd.add_option("--focus-distance", o.focusDistance,
                 "put the plane of focus this far from the PRP (world units, or infinity)");
  cmd.add_option_function<std::string>("--focus-at", [&o](const std::string& text) {
       double x = 0.0, y = 0.0;
       char comma = 0;
       std::istringstream in(text);
       if (!(in >> x >> comma >> y) || comma != ',' || !in.eof())
         throw CLI::ValidationError("--focus-at", "give a pixel as X,Y (e.g. 480,320)");
       o.focusAt = glm::dvec2(x, y);
     },
     "focus on the depth under pixel X,Y of the image");
}

void addBackgroundOption(CLI::App& cmd, std::optional<glm::vec3>& background) {
  cmd.add_option_function<std::vector<double>>("--background", [&background](const std::vector<double>& rgb) {
       for (const double v : rgb)
         if (!std::isfinite(v) || v < 0.0 || v > 65504.0)
           throw CLI::ValidationError("--background", "give three linear values, each from 0 to 65504 (e.g. 0.5,0.6,0.8)");
       background = glm::vec3(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]), static_cast<float>(rgb[2]));
     },
     "colour where no surface is seen, linear R,G,B (e.g. 0,0,0); default: the scene's (a dark blue grey, 0.05,0.06,0.08)")
      ->delimiter(',')
      ->expected(3);
}

void applyBackground(Scene& scene, const std::optional<glm::vec3>& background) {
  if (background) scene.lighting.background = *background;
}

PlanOptions toPlanOptions(const LensOptions& o) {
  PlanOptions p;
  const auto pattern = patternFromName(o.pattern);
  if (!pattern) throw InputError(cat("--pattern ", o.pattern, ": use one of ", patternNames()));
  p.pattern = *pattern;
  if (o.apertureSamples != "auto") {
    std::size_t used = 0;
    int n = 0;
    try {
      n = std::stoi(o.apertureSamples, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != o.apertureSamples.size() || n < 1 || n > 65536)
      throw InputError(cat("--aperture-samples ", o.apertureSamples, ": give a whole number from 1 to 65536, or auto"));
    p.apertureSamples = n;
  }
  p.maxSamples = o.maxSamples;
  p.seed = o.seed;
  return p;
}

Camera applyLensOptions(const Camera& camera, const LensOptions& o) {
  if (o.focusDistance.empty()) return camera;
  double d = 0.0;
  if (o.focusDistance == "infinity" || o.focusDistance == "inf") {
    d = std::numeric_limits<double>::infinity();
  } else {
    std::size_t used = 0;
    try {
      d = std::stod(o.focusDistance, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != o.focusDistance.size()) throw InputError(cat("--focus-distance ", o.focusDistance, ": give a distance or infinity"));
  }
  Camera c = refocused(camera, d, "--focus-distance");
  c.source += cat(", refocused to ", o.focusDistance);
  return c;
}

DepthAtPixel rasterDepth(Renderer& renderer) {
  return [&renderer](const Camera& camera, ImageSize size, int x, int y) {
    const std::vector<float> depth = renderer.pinholeDepth(camera, size);
    const double zNdc = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size.widthPx) + static_cast<std::size_t>(x)];
    return depthFromReverseZ(camera.view, zNdc);
  };
}

Camera focusOnPixel(const Camera& camera, ImageSize size, glm::dvec2 pixel, const DepthAtPixel& depthAt) {
  const int x = static_cast<int>(std::floor(pixel.x)), y = static_cast<int>(std::floor(pixel.y));
  if (x < 0 || y < 0 || x >= size.widthPx || y >= size.heightPx)
    throw InputError(cat("--focus-at ", pixel.x, ",", pixel.y, ": the pixel is outside the ", size.widthPx, "x",
                         size.heightPx, " image"));
  double distance = 0.0;
  if (camera.effects.needsRemap()) {
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    const Overscan o = overscanFor(camera, size);
    const glm::dvec2 p = undistortedSample(camera, Channel::Green, centre, size).pixel + glm::dvec2(o.padPx);
    distance = depthAt(o.camera, o.size, static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
  } else {
    distance = depthAt(camera, size, x, y);
  }
  if (!std::isfinite(distance) || !(distance > 0.0))
    throw InputError(cat("--focus-at ", pixel.x, ",", pixel.y, ": nothing of the scene is under that pixel to focus on"));
  Camera c = refocused(camera, distance, "--focus-at");
  c.source += cat(", focused at pixel ", pixel.x, ",", pixel.y, " (depth ", distance, ")");
  return c;
}

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

void printProgress(int done, int total, double seconds) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
            << std::string(static_cast<std::size_t>(kWidth - filled), ' ') << "] " << done << "/" << total
            << " samples, " << cat(seconds) << " s" << std::flush;
}

}  // namespace lenslab
