#include "app/CliOptions.h"

#include "core/Text.h"
#include "lens/AperturePattern.h"

#include <cmath>

namespace lenslab {

void addSamplingOptions(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--pattern", o.pattern, "aperture pattern: " + patternNames() + " (default: concentric; sobol with --target-psnr)")
      ->check(CLI::IsMember(patternNameList()));
  CLI::Option* samples =
      cmd.add_option("--aperture-samples", o.apertureSamples,
                     "scene passes, one per aperture point: a number, or auto (from the largest circle of confusion in view)")
          ->check(CLI::IsMember({"auto"}) | CLI::Range(1, 65536))
          ->capture_default_str();
  CLI::Option* max = cmd.add_option("--max-samples", o.maxSamples, "the most aperture samples auto may choose (with --target-psnr: per tile)")
                         ->check(CLI::Range(1, 65536))
                         ->capture_default_str();
  // A fixed count leaves nothing for a cap to do: say so rather than ignore it.
  cmd.parse_complete_callback([samples, max, &o] {
    if (max->count() > 0 && samples->count() > 0 && o.apertureSamples != "auto")
      throw CLI::ValidationError("--max-samples", cat("caps the count that auto (or --target-psnr) chooses; --aperture-samples ",
                                                      o.apertureSamples, " fixes it: give one or the other"));
  });
}

void addSeedOption(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--seed", o.seed, "seed for the aperture and sub-pixel samples")->capture_default_str();
}

void addFocusOptions(CLI::App& cmd, LensOptions& o) {
  CLI::Option* distance = cmd.add_option("--focus-distance", o.focusDistance,
                                         "put the plane of focus this far from the PRP (world units, or infinity)");
  // --focus-at sets the focus after --focus-distance would: one of the two.
  addPairOption(cmd, "--focus-at", [&o](double x, double y) { o.focusAt = glm::dvec2(x, y); },
                "focus on the depth under pixel X,Y of the image")
      ->excludes(distance);
}

void addTargetOption(CLI::App& cmd, LensOptions& o) {
  cmd.add_option("--target-psnr", o.targetPsnrDb,
                 "render to an error instead of a count: each 32-px tile gets its own number of samples, in a "
                 "progressive order, until the estimated PSNR of the image against its own converged limit reaches DB "
                 "(--max-samples still caps each tile)")
      ->check(CLI::Range(10.0, 100.0))
      ->type_name("DB");
}

CLI::Option* addPairOption(CLI::App& cmd, const std::string& name, std::function<void(double, double)> set,
                           const std::string& description) {
  return cmd.add_option_function<std::vector<double>>(name, [set](const std::vector<double>& xy) { set(xy[0], xy[1]); },
                                                      description)
      ->delimiter(',')
      ->expected(2)
      ->type_name("X,Y");
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

}  // namespace lenslab
