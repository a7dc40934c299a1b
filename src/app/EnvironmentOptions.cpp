#include "app/EnvironmentOptions.h"

#include "app/CliOptions.h"

namespace lenslab {

void addEnvironmentOptions(CLI::App& cmd, EnvironmentRequest& r) {
  cmd.add_option("--environment", r.file,
                 "equirectangular environment (.hdr or .exr, linear radiance, width = 2 × height): the background both "
                 "renderers show and the image light; prefiltered once and cached (docs/environment.md)")
      ->type_name("FILE");
  cmd.add_option("--environment-intensity", r.intensity, "multiplies the environment's radiance (default 1)")
      ->check(numberIn({.min = 0.0, .max = 1e30, .unit = "times the file's radiance"}))
      ->type_name("X");
  cmd.add_option("--environment-rotation", r.rotationDegrees,
                 "turns the environment about world +Y (right-handed; at 90 the image centre is seen towards -X)")
      ->check(numberIn({.min = -36000.0, .max = 36000.0, .unit = "degrees"}))
      ->type_name("DEG");
}

}  // namespace lenslab
