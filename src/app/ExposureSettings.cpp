#include "app/ExposureSettings.h"

#include "core/Error.h"
#include "core/ParseNumber.h"
#include "core/Text.h"
#include "io/ImageFile.h"

#include <cmath>

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

namespace {

// `v` (> 0) to two significant digits: a setting to suggest, not a measurement.
double twoDigits(double v) {
  const double unit = std::pow(10.0, std::floor(std::log10(v)) - 1.0);
  return std::round(v / unit) * unit;
}

// A shutter time as photographers write it: 1/125 under a second, else seconds; `round`ed to two digits.
std::string shutterText(double seconds, bool round) {
  const double shown = seconds < 1.0 ? 1.0 / seconds : seconds;
  return cat(seconds < 1.0 ? "1/" : "", round ? twoDigits(shown) : shown);
}

// What would meet the reading from a physical exposure, the f-number kept: the shutter time at its
// ISO, the ISO at its shutter time (each where it is in range).
std::string meetingSettings(const Exposure& e, double meteredEv100) {
  const double factor = std::exp2(*e.ev100 - meteredEv100);  // the light the reading wants, over the light given
  std::string s = "give --exposure auto";
  if (const double t = *e.shutterSeconds * factor; !numberProblem(t, kShutterSecondsRange))
    s += cat(", or --shutter ", shutterText(t, true), " (at ISO ", *e.iso, ")");
  if (const double iso = *e.iso * factor; !numberProblem(iso, kIsoRange))
    s += cat(", or --iso ", twoDigits(iso), " (at ", shutterText(*e.shutterSeconds, false), " s)");
  return s;
}

}  // namespace

std::vector<std::string> meterForFile(DisplaySettings& display, const Image& image, const std::filesystem::path& out,
                                      bool asked, const std::optional<Exposure>& held) {
  Exposure& e = display.exposure;
  std::vector<std::string> warnings;
  if (!asked && e.source != "--exposure auto" && e.source != "physical") return warnings;
  const MeterReading reading = meterFrame(image);
  e = exposedByMeter(e, reading);
  if (held && e.source == "--exposure auto") e.scale = held->scale, e.stops = held->stops;
  display.encoding.exposureScale = static_cast<float>(e.scale);
  if (!reading.ev100) {
    if (e.source == "--exposure auto" && !held)
      warnings.push_back("--exposure auto: no pixel of the frame holds light to meter: exposure 0 stops");
    return warnings;
  }
  if (e.source != "physical" || !isDisplayReferred(out)) return warnings;
  // The metered average as the PNG shows it: an sRGB code from 0 to 255.
  const int code = static_cast<int>(
      std::lround(255.0f * displayEncoded(glm::vec3(static_cast<float>(reading.luminance)), display.encoding).g));
  if (code >= kNearlyBlackOrWhiteCodes && code <= 255 - kNearlyBlackOrWhiteCodes) return warnings;
  const double off = *e.ev100 - *reading.ev100;  // a higher EV100 lets in less light
  warnings.push_back(cat(describe(e), " is ", std::round(std::abs(off) * 10.0) / 10.0, " stops ",
                         off > 0.0 ? "under" : "over", " the frame's metered EV100 ",
                         std::round(*reading.ev100 * 100.0) / 100.0, ": its metered average shows at ", code,
                         " of 255 (", off > 0.0 ? "nearly black" : "nearly white", ") through ",
                         viewTransformName(display.encoding.transform), "; ", meetingSettings(e, *reading.ev100)));
  return warnings;
}

}  // namespace lenslab
