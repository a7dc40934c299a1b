#pragma once
// A reflected-light meter on a rendered frame: what `--exposure auto` exposes by (docs/exposure.md).
//
// The rule, one and fixed:
//   Y = 0.2126 R + 0.7152 G + 0.0722 B                 each pixel's luminance (linear Rec.709)
//   log2 L = 0.75 · mean(log2 Y, central circle) + 0.25 · mean(log2 Y, the rest of the frame)
//   EV100 = log2(L · 100 / K),  K = 12.5                the reflected-light meter's calibration
//                                                       (ISO 2720, as Sekonic, Nikon and Canon use)
// L is a centre-weighted geometric mean: the central circle (its diameter half the frame's shorter
// side, its centre the frame's) holds three quarters of the weight, as a camera's centre-weighted
// meter gives its central circle 60 to 80 %; a geometric mean, so that a small bright lamp in view
// moves the reading by its share of the frame in stops, not by its brightness. Each pixel counts
// once, by its centre. At that EV100 the exposure scale (camera/Exposure.h) puts L at the linear
// value 12.5 / (1.2 · 100) = 0.104, 3.26 stops under the value 1 where `none` clips.
//
// Pixels with no light are left out: those darker than 2^-16 of the frame's plain average
// luminance (16 stops, more than a sensor records under its average; a geometric mean cannot take
// a 0), and any that is not finite. A background colour or an environment counts, as the sky or
// the studio's walls count for a camera's meter; a black background where nothing is seen does
// not, as it sends no light. A frame with no pixel left gives no reading.
#include "core/Image.h"

#include <cstdint>
#include <optional>

namespace lenslab {

inline constexpr double kReflectedMeterK = 12.5;      // ISO 2720's reflected-light calibration (cd·s/m²)
inline constexpr double kCentreCircleWeight = 0.75;   // of the reading, from the central circle
inline constexpr double kCentreCircleDiameter = 0.5;  // of the frame's shorter side
inline constexpr double kMeterFloorStops = 16.0;      // pixels this far under the frame's average are left out

// Y of linear Rec.709 RGB.
double luminance(double r, double g, double b);
// Whether pixel (x, y) of a width × height frame lies, by its centre, in the central circle.
bool inCentreCircle(int x, int y, int width, int height);
// EV100 = log2(L · 100 / K) of an average luminance L (cd/m²) at the reflected meter's K.
double ev100ForMeteredLuminance(double averageLuminance);

struct MeterReading {
  std::optional<double> ev100;  // none: no pixel holds light (a black frame)
  double luminance = 0.0;       // L, the centre-weighted geometric mean; 0 for a black frame
  std::int64_t pixels = 0;      // the pixels metered (the rest held no light)
};

// The frame's reading by the rule above.
MeterReading meterFrame(const Image& image);

}  // namespace lenslab
