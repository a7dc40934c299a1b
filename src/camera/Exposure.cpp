#include "camera/Exposure.h"

#include "core/Error.h"
#include "core/Text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lenslab {

double ev100(double fNumber, double shutterSeconds, double iso) {
  return std::log2(fNumber * fNumber / shutterSeconds) - std::log2(iso / 100.0);
}

double exposureScaleForEv100(double ev) {
  // 78 / (0.65 · 100): ISO 12232's saturation constant over the lens's transmission, at ISO 100.
  constexpr double kSaturation = 78.0 / (0.65 * 100.0);
  return 1.0 / (kSaturation * std::exp2(ev));
}

double exposureScaleForStops(double stops) { return std::exp2(stops); }

double ev100ForScale(double scale) { return -std::log2(scale / exposureScaleForEv100(0.0)); }

namespace {

// EV100 of the camera's own f-number, shutter_s and iso (default 100), where it has them.
std::optional<double> cameraEv100(const SelectedCamera& selected) {
  const std::optional<PhysicalCamera>& p = selected.physical;
  if (!p || !p->shutterSeconds || !std::isfinite(p->fNumber)) return std::nullopt;
  return ev100(p->fNumber, *p->shutterSeconds, p->iso.value_or(100.0));
}

}  // namespace

Exposure resolveExposure(const ExposureRequest& r, const SelectedCamera& selected) {
  Exposure e;
  e.cameraEv100 = cameraEv100(selected);
  if (r.meter) {
    if (r.shutterSeconds || r.iso)
      throw InputError(
          "--exposure auto meters the frame; --shutter and --iso set the exposure physically: give one "
          "or the other");
    e.source = "--exposure auto";
    return e;
  }
  if (r.stops) {
    if (r.shutterSeconds || r.iso)
      throw InputError(
          cat("--exposure sets the exposure in stops; --shutter and --iso set it physically: give one or the other"));
    e.stops = checkedNumber("--exposure", *r.stops, kExposureStopsRange);
    e.scale = exposureScaleForStops(e.stops);
    e.source = "--exposure";
    return e;
  }
  const std::optional<PhysicalCamera>& p = selected.physical;
  const std::optional<double> shutter = r.shutterSeconds ? r.shutterSeconds : p ? p->shutterSeconds : std::nullopt;
  const std::optional<double> iso = r.iso ? r.iso : p ? p->iso : std::nullopt;
  const char* shutterName = r.shutterSeconds ? "--shutter" : "shutter_s";
  const char* isoName = r.iso ? "--iso" : "iso";
  if (!shutter && !iso) return e;
  if (!shutter)
    throw InputError(cat(isoName,
                         ": an ISO exposes the image only with a shutter time: give --shutter SECONDS (or the camera "
                         "file's shutter_s) too, or --exposure EV"));
  checkedNumber(shutterName, *shutter, kShutterSecondsRange);
  if (iso) checkedNumber(isoName, *iso, kIsoRange);
  if (!p || !std::isfinite(p->fNumber))
    throw InputError(
        cat(shutterName, ": a physical exposure needs the lens's f-number, and ", selected.camera.source,
            p ? " is a pinhole" : " is not in the physical form",
            ": give --f-number N (with --focal-length for a lecture or OpenCV camera), or --exposure EV instead"));
  e.shutterSeconds = shutter;
  e.iso = iso.value_or(100.0);
  e.fNumber = p->fNumber;
  e.ev100 = ev100(p->fNumber, *shutter, *e.iso);
  e.scale = exposureScaleForEv100(*e.ev100);
  e.stops = std::log2(e.scale);
  e.source = "physical";
  return e;
}

Exposure exposedByMeter(Exposure e, const MeterReading& reading) {
  e.meterReading = reading;
  if (e.source != "--exposure auto") return e;
  e.stops = 0.0;
  if (reading.ev100)
    e.stops =
        std::clamp(std::log2(exposureScaleForEv100(*reading.ev100)), kExposureStopsRange.min, kExposureStopsRange.max);
  e.scale = exposureScaleForStops(e.stops);
  return e;
}

std::string describe(const Exposure& e) {
  char text[200];
  if (e.source == "--exposure auto" && e.meterReading && e.meterReading->ev100) {
    std::snprintf(text, sizeof text, "metered EV100 %.3g (--exposure auto): scale %.3g", *e.meterReading->ev100,
                  e.scale);
  } else if (e.source == "--exposure auto") {
    std::snprintf(text, sizeof text, "%+.3g EV (--exposure auto: %s)", e.stops,
                  e.meterReading ? "no light to meter" : "not metered yet");
  } else if (e.ev100) {
    // Shutter times under a second as photographers write them: 1/125 s.
    const double t = *e.shutterSeconds;
    char shutter[40];
    if (t < 1.0)
      std::snprintf(shutter, sizeof shutter, "1/%.4g s", 1.0 / t);
    else
      std::snprintf(shutter, sizeof shutter, "%.4g s", t);
    std::snprintf(text, sizeof text, "f/%.3g, %s, ISO %.6g: EV100 %.3g, scale %.3g", *e.fNumber, shutter, *e.iso,
                  *e.ev100, e.scale);
  } else {
    std::snprintf(text, sizeof text, "%+.3g EV%s", e.stops, e.source == "--exposure" ? " (--exposure)" : "");
  }
  return text;
}

}  // namespace lenslab
