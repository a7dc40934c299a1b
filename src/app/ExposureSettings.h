#pragma once
// How a run's PNG files and the viewer's window show its linear radiance (--exposure, --shutter,
// --iso and --view-transform; docs/exposure.md): the settings and the meter, without the
// command-line library (app/ExposureOptions.h registers the options). The EXR files never go
// through them.
#include "camera/Exposure.h"
#include "core/Image.h"
#include "io/ToneMap.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct ExposureOptions {
  ExposureRequest request;             // --exposure EV, or --shutter SECONDS and --iso ISO
  std::string viewTransform = "none";  // --view-transform NAME (io/ToneMap.h)
};

// resolveDisplay (io/ToneMap.h) of the options.
inline DisplaySettings resolveDisplay(const ExposureOptions& o, const SelectedCamera& camera) {
  return resolveDisplay(o.request, o.viewTransform, camera);
}

// A physical exposure is warned of when the frame's metered average L shows in a PNG within this
// many sRGB codes of black or of white: nearly black or nearly white. Through `none` that is 2.85
// stops under the meter or 2.82 over; PBR Neutral's toe darkens the shadows, and under it the
// warning comes from 1.1 stops under.
inline constexpr int kNearlyBlackOrWhiteCodes = 32;

// The frame's meter reading (camera/Metering.h) recorded in display.exposure, and for --exposure
// auto the exposure it gives (or `held`'s: capture holds its first frame's for the sequence), in
// display.encoding too. Metered for --exposure auto, for a physical exposure, and when `asked`
// (--stats); else left as it is. The warnings, one line each without "lenslab: warning: ": a black
// frame under --exposure auto (exposure 0 stops); a physical exposure that shows the frame's
// metered average nearly black or nearly white in the PNG `out` (naming the reading, and settings
// that would meet it).
std::vector<std::string> meterForFile(DisplaySettings& display, const Image& image, const std::filesystem::path& out,
                                      bool asked, const std::optional<Exposure>& held = std::nullopt);

// --shutter's text: seconds ("0.008") or a fraction as photographers write it ("1/125"). Throws
// InputError naming the option and the range.
double parseShutterSeconds(const std::string& text);

}  // namespace lenslab
