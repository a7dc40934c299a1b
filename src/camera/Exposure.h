#pragma once
// Photographic exposure: how much of the scene's linear radiance reaches the image, as a
// photographer sets it (f-number N, shutter time t, ISO sensitivity S) or as a number of stops.
//
// Exposure value at ISO 100 (the EV printed on light meters and in exposure tables):
//   EV100 = log2(N² / t) − log2(S / 100)
// The scale from scene luminance (cd/m²) to the image's linear value, by the saturation-based
// sensitivity of ISO 12232: the luminance that just saturates the sensor is
//   L_max = (78 / (q·S)) · (N² / t) = 1.2 · 2^EV100      (q = 0.65, the lens's transmission and
//                                                           vignetting; 78 / (0.65·100) = 1.2)
// so a value of 1 in the image is L_max:  scale = 1 / (1.2 · 2^EV100). Filament's and Frostbite's
// physically based cameras (Lagarde and de Rousiers, "Moving Frostbite to PBR", 2014) use the same
// relation. lenslab reads its scene's linear values as luminance in cd/m².
//
// A number of stops instead (`--exposure EV`): scale = 2^EV; 0 leaves the values as they are.
// Or metered on the rendered frame (`--exposure auto`): the EV100 of camera/Metering.h's reading.
#include "camera/Metering.h"
#include "camera/PhysicalCamera.h"
#include "core/NumberInput.h"

#include <optional>
#include <string>

namespace lenslab {

// What the fields take. Shutter: 1/64000 s (the fastest electronic shutters) to an hour; ISO: 1 to
// 10^7 (sensors range from ISO 25 to a few million).
inline constexpr NumberRange kShutterSecondsRange{.min = 1.0 / 64000.0, .max = 3600.0, .unit = "seconds"};
inline constexpr NumberRange kIsoRange{.min = 1.0, .max = 1e7, .unit = "ISO"};
inline constexpr NumberRange kExposureStopsRange{.min = -64.0, .max = 64.0, .unit = "stops"};

// EV100 = log2(N² / t) − log2(S / 100).
double ev100(double fNumber, double shutterSeconds, double iso);
// 1 / (1.2 · 2^EV100): the factor that maps luminance (cd/m²) to the image's linear value.
double exposureScaleForEv100(double ev100);
// 2^stops.
double exposureScaleForStops(double stops);
// The EV100 whose scale is `scale`: −log2(1.2 · scale), exposureScaleForEv100's inverse.
double ev100ForScale(double scale);

// What a user asked for: stops (--exposure), the meter (--exposure auto), or the physical
// settings (--shutter, --iso over the camera file's shutter_s and iso), or none of them.
struct ExposureRequest {
  std::optional<double> stops;           // --exposure EV
  bool meter = false;                    // --exposure auto
  std::optional<double> shutterSeconds;  // --shutter
  std::optional<double> iso;             // --iso
};

// The exposure a run applies to its PNG and its display, and where it came from.
struct Exposure {
  double scale = 1.0;                                  // linear values are multiplied by it
  double stops = 0.0;                                  // log2(scale)
  std::optional<double> ev100;                         // when set physically
  std::optional<double> shutterSeconds, iso, fNumber;  // the physical settings used
  std::string source = "none";                         // "none", "--exposure", "--exposure auto" or "physical"
  std::optional<double> cameraEv100;                   // the camera's own, where it has an f-number and a shutter time
  std::optional<MeterReading> meterReading;            // the frame's, when it was metered (app/ExposureOptions.h)
};

// Which exposure applies, in this order: --exposure (stops, or auto: scale 1 until exposedByMeter
// sets it from the frame) wins over the camera's physical settings (the command line overrides
// the camera file, field by field as for the lens); refused together with --shutter or --iso on
// the command line. Else the physical settings: the shutter
// time from --shutter or the file's shutter_s, the ISO from --iso or the file's iso (default 100,
// EV100's reference), the f-number from the camera's physical description. Else 0 EV: scale 1.
// Throws InputError naming the option or field: a shutter time or ISO out of range, an ISO without
// a shutter time, a physical exposure for a camera without a finite f-number (a pinhole, or a
// camera not in the physical form).
Exposure resolveExposure(const ExposureRequest& request, const SelectedCamera& camera);
// `exposure` with `reading` recorded, and for --exposure auto the scale of the reading's EV100
// (held within --exposure's ±64 stops); a black frame (no reading) leaves it at 0 stops.
Exposure exposedByMeter(Exposure exposure, const MeterReading& reading);
// "0 EV", "+1.5 EV (--exposure)", "f/2.8, 1/100 s, ISO 100: EV100 9.61, scale 0.00106",
// "metered EV100 2.54 (--exposure auto): scale 0.0478": for stats and the viewer.
std::string describe(const Exposure& exposure);

}  // namespace lenslab
