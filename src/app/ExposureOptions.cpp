#include "app/ExposureOptions.h"

#include "app/CliOptions.h"
#include "core/Error.h"
#include "core/ParseNumber.h"

namespace lenslab {

void addExposureOptions(CLI::App& cmd, ExposureRequest& request, std::string& viewTransform) {
  CLI::Option* stops =
      cmd.add_option_function<std::string>(
             "--exposure",
             [&request](const std::string& text) {
               request.meter = text == "auto";
               if (!request.meter) request.stops = readNumber("--exposure", text, kExposureStopsRange);
             },
             "exposure for PNG output and the display: EV, linear values x 2^EV (0: unchanged), or auto: metered "
             "on the rendered frame, centre-weighted (docs/exposure.md); the EXR is never exposed; over the camera "
             "file's shutter_s and iso")
          ->check(CLI::Validator(
              [](std::string& text) {
                if (text == "auto") return std::string();
                const std::optional<std::string> problem = numberTextProblem(text, kExposureStopsRange);
                return problem ? *problem + ", or auto" : std::string();
              },
              std::string()))
          ->type_name("EV|auto");
  CLI::Option* shutter =
      cmd.add_option_function<std::string>(
             "--shutter", [&request](const std::string& text) { request.shutterSeconds = parseShutterSeconds(text); },
             "shutter time for a physical exposure, in seconds or as 1/125: with the camera's "
             "f-number and --iso, EV100 = log2(N^2/t) - log2(ISO/100) (docs/exposure.md)")
          ->check(CLI::Validator(
              [](std::string& text) {
                // Checked here, where CLI11 turns a problem into its one-line error.
                try {
                  parseShutterSeconds(text);
                  return std::string();
                } catch (const InputError& e) {
                  const std::string message = e.what();
                  return message.substr(message.find(": ") + 2);
                }
              },
              std::string()))
          ->type_name("SECONDS");
  CLI::Option* iso =
      cmd.add_option("--iso", request.iso, "sensitivity for a physical exposure (default 100), with --shutter")
          ->check(numberIn(kIsoRange))
          ->type_name("ISO");
  stops->excludes(shutter)->excludes(iso);
  cmd.add_option("--view-transform", viewTransform,
                 "how exposed values beyond 1 reach the PNG and the display: none (clip each channel at 1) or "
                 "pbr-neutral (Khronos PBR Neutral: compresses highlights, keeps hue)")
      ->check(CLI::IsMember({"none", "pbr-neutral"}))
      ->type_name("NAME")
      ->capture_default_str();
}

}  // namespace lenslab
