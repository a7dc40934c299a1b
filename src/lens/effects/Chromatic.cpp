// Chromatic aberration: lateral and axial colour, one camera-file object and one model
// (Chromatic.h), two mechanisms in the frame; the model's functions and the module
// (LensEffectModule.h).
//
// Camera file: "chromatic": {"lateral_red", "lateral_blue", "focus_distance_red",
// "focus_distance_blue", "abbe_number"}: the axial part as each channel's plane of focus, or (the
// physical form) the glass's Abbe number. Path: the lateral scales and the inverse focus shifts
// linear. Plan: lateral colour a variant of the lens remap (a table per channel); axial colour
// three views per aperture sample, one per channel.
#include "lens/effects/Chromatic.h"

#include "core/Text.h"
#include "lens/effects/LensEffectModule.h"

namespace lenslab {

double Chromatic::lateral(Channel c) const {
  return c == Channel::Red ? lateralRed : c == Channel::Blue ? lateralBlue : 0.0;
}

double Chromatic::inverseFocusShift(Channel c) const {
  return c == Channel::Red ? inverseFocusShiftRed : c == Channel::Blue ? inverseFocusShiftBlue : 0.0;
}

std::array<double, 2> inverseFocusShiftsFromAbbe(double abbeNumber, double focalLength) {
  // Fraunhofer lines, micrometres: C (red), d (green, helium), F (blue).
  constexpr double kC = 0.6562725, kD = 0.5875618, kF = 0.4861327;
  const auto cauchy = [](double lambda) { return 1.0 / (lambda * lambda); };
  // n_d − n_C as a fraction of n_F − n_C under n = A + B/λ² (0.301; BK7's measured value is 0.308).
  const double redFraction = (cauchy(kD) - cauchy(kC)) / (cauchy(kF) - cauchy(kC));
  const double power = 1.0 / focalLength;
  return {-power * redFraction / abbeNumber, power * (1.0 - redFraction) / abbeNumber};
}

namespace {

const std::set<std::string> kKeys = {"lateral_red", "lateral_blue", "focus_distance_red", "focus_distance_blue",
                                     "abbe_number"};

void readAbbe(const KeyReader& o, const LensFrame& frame, Chromatic& c) {
  if (o.has("focus_distance_red") || o.has("focus_distance_blue"))
    o.fail("abbe_number", "and focus_distance_red/blue both set the axial aberration; give one");
  if (!frame.focalLength)
    o.fail("abbe_number",
           "needs the physical form (its focal_length_mm); in this form give "
           "focus_distance_red and focus_distance_blue");
  const double abbe = o.number("abbe_number");
  if (!(abbe > 0.0)) o.fail("abbe_number", cat("is ", abbe, "; glasses have Abbe numbers of about 20 to 90"));
  const auto shifts = inverseFocusShiftsFromAbbe(abbe, *frame.focalLength);
  c.inverseFocusShiftRed = shifts[0];
  c.inverseFocusShiftBlue = shifts[1];
}

void read(const KeyReader& camera, const LensFrame& frame, Lens& lens) {
  if (!camera.has("chromatic")) return;
  const std::unique_ptr<KeyReader> o = camera.object("chromatic", kKeys);
  Chromatic& c = lens.effects.chromatic;
  if (o->has("lateral_red")) c.lateralRed = o->number("lateral_red");
  if (o->has("lateral_blue")) c.lateralBlue = o->number("lateral_blue");
  if (o->has("abbe_number")) readAbbe(*o, frame, c);
  if (o->has("focus_distance_red"))
    c.inverseFocusShiftRed = inverseOfDistance(*o, "focus_distance_red") - frame.inverseFocus;
  if (o->has("focus_distance_blue"))
    c.inverseFocusShiftBlue = inverseOfDistance(*o, "focus_distance_blue") - frame.inverseFocus;
}

void write(const Lens& lens, const LensFrame& frame, KeyWriter& camera) {
  const Chromatic& c = lens.effects.chromatic;
  if (!c.hasLateral() && !c.hasAxial()) return;
  KeyWriter& o = camera.object("chromatic");
  if (c.lateralRed != 0.0) o.number("lateral_red", c.lateralRed);
  if (c.lateralBlue != 0.0) o.number("lateral_blue", c.lateralBlue);
  if (c.hasAxial()) {
    o.distance("focus_distance_red",
               distanceForInverse(frame.inverseFocus + c.inverseFocusShiftRed, frame, "chromatic.focus_distance_red"));
    o.distance("focus_distance_blue", distanceForInverse(frame.inverseFocus + c.inverseFocusShiftBlue, frame,
                                                         "chromatic.focus_distance_blue"));
  }
}

void interpolate(const Lens& a, const Lens& b, double u, Lens& out) {
  const Chromatic &x = a.effects.chromatic, &y = b.effects.chromatic;
  Chromatic& c = out.effects.chromatic;
  c.lateralRed = lerpValue(x.lateralRed, y.lateralRed, u);
  c.lateralBlue = lerpValue(x.lateralBlue, y.lateralBlue, u);
  // Carried as inverse focus shifts: linear there too.
  c.inverseFocusShiftRed = lerpValue(x.inverseFocusShiftRed, y.inverseFocusShiftRed, u);
  c.inverseFocusShiftBlue = lerpValue(x.inverseFocusShiftBlue, y.inverseFocusShiftBlue, u);
}

void plan(const Lens& lens, const PlanView&, EffectNeeds& needs) {
  const Chromatic& c = lens.effects.chromatic;
  if (c.hasLateral()) {
    needs.lensVariants.push_back("lateral-colour");
    needs.remapTables = 3;  // one inverse table per colour channel
  }
  if (c.hasAxial()) {
    needs.viewsPerSample = 3;
    needs.sceneVariants.push_back("channel-focus");
    needs.idleThroughPinhole = true;
  }
}

}  // namespace

extern const LensEffectModule kChromaticModule;
const LensEffectModule kChromaticModule{"chromatic", "lens/remap.frag", read, write, interpolate, plan};

}  // namespace lenslab
