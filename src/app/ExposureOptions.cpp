#include "app/ExposureOptions.h"

#include "app/CliOptions.h"
#include "core/Error.h"
#include "core/ParseNumber.h"
#include "core/Text.h"

namespace lenslab {

double parseShutterSeconds(const std::string& text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return readNumber("--shutter", text, kShutterSecondsRange);
  const std::optional<double> numerator = parseDouble(text.substr(0, slash));
  const std::optional<double> denominator = parseDouble(text.substr(slash + 1));
  if (!numerator || !denominator || !(*numerator > 0.0) || !(*denominator > 0.0))
    throw InputError(cat("--shutter: ", excerpt(text), " is not a shutter time; give seconds (",
                         numberText(kShutterSecondsRange.min), " to ", numberText(kShutterSecondsRange.max),
                         ") or a fraction such as 1/125"));
  return checkedNumber("--shutter", *numerator / *denominator, kShutterSecondsRange);
}

void addExposureOptions(CLI::App& cmd, ExposureRequest& request, std::string& viewTransform) {
  CLI::Option* stops =
      cmd.add_option("--exposure", request.stops,
                     "exposure in stops for PNG output and the display: linear values x 2^EV (0: unchanged; the EXR is "
                     "never exposed); over the camera file's shutter_s and iso")
          ->check(numberIn(kExposureStopsRange))
          ->type_name("EV");
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
