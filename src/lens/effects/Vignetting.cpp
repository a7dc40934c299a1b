#include "lens/effects/Vignetting.h"

#include "core/Text.h"
#include "lens/effects/LensEffectModule.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab {

// The GLSL, as C++ in double precision (scene/Brdf.cpp does the same with common/brdf.glsl).
namespace glsl {
#define VIGNETTING_REAL double
#include "../../../shaders/common/vignetting_gain.glsl"
#undef VIGNETTING_REAL
}  // namespace glsl

double vignettingPolynomial(double r2, double a1, double a2, double a3) {
  return glsl::vignettingPolynomial(r2, a1, a2, a3);
}

bool Vignetting::isZero() const { return a1 == 0.0 && a2 == 0.0 && a3 == 0.0; }

double Vignetting::gain(double r2) const { return glsl::vignettingGainAt(r2, a1, a2, a3); }

namespace {

// The cubic's turning points (g' = a1 + 2 a2 t + 3 a3 t² = 0) strictly inside (0, r2Max), in
// order, then r2Max: between these the gain is monotone.
std::vector<double> monotoneStretchEnds(const Vignetting& v, double r2Max) {
  std::vector<double> ends;
  const double qa = 3.0 * v.a3, qb = 2.0 * v.a2, qc = v.a1;
  if (qa != 0.0) {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0)
      for (const double sign : {-1.0, 1.0}) ends.push_back((-qb + sign * std::sqrt(disc)) / (2.0 * qa));
  } else if (qb != 0.0) {
    ends.push_back(-qc / qb);
  }
  ends.erase(std::remove_if(ends.begin(), ends.end(), [&](double t) { return !(t > 0.0 && t < r2Max); }), ends.end());
  std::sort(ends.begin(), ends.end());
  ends.push_back(r2Max);
  return ends;
}

}  // namespace

std::optional<double> vignettingZeroWithin(const Vignetting& v, double r2Max) {
  if (v.isZero() || !(r2Max > 0.0)) return std::nullopt;
  // The first monotone stretch that ends at g ≤ 0 holds the first crossing and no other: found
  // exactly, then pinned down by bisection.
  double lo = 0.0;
  for (const double end : monotoneStretchEnds(v, r2Max)) {
    if (!(v.polynomial(end) > 0.0)) {
      double hi = end;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (v.polynomial(mid) > 0.0 ? lo : hi) = mid;
      }
      return hi;
    }
    lo = end;
  }
  return std::nullopt;
}

double vignettingLargestGain(const Vignetting& v, double r2Max) {
  double largest = 1.0;  // the centre's
  if (v.isZero() || !(r2Max > 0.0)) return largest;
  for (const double end : monotoneStretchEnds(v, r2Max)) largest = std::max(largest, v.polynomial(end));
  return largest;
}

namespace {

const std::set<std::string> kKeys = {"a1", "a2", "a3"};

void read(const KeyReader& camera, const LensFrame& frame, Lens& lens) {
  if (!camera.has("vignetting")) return;
  // Missing keys are 0; validateLensEffects refuses a gain that reaches 0 inside the image.
  const std::unique_ptr<KeyReader> o = camera.object("vignetting", kKeys);
  Vignetting& v = lens.effects.vignetting;
  if (o->has("a1")) v.a1 = o->number("a1");
  if (o->has("a2")) v.a2 = o->number("a2");
  if (o->has("a3")) v.a3 = o->number("a3");
  if (!v.isZero() && !frame.perspective) camera.fail("vignetting", "needs a perspective projection");
}

void write(const Lens& lens, const LensFrame&, KeyWriter& camera) {
  const Vignetting& v = lens.effects.vignetting;
  if (v.isZero()) return;
  KeyWriter& o = camera.object("vignetting");
  for (const auto& [key, value] : {std::pair{"a1", v.a1}, {"a2", v.a2}, {"a3", v.a3}})
    if (value != 0.0) o.number(key, value);
}

void interpolate(const Lens& a, const Lens& b, double u, Lens& out) {
  const Vignetting &va = a.effects.vignetting, &vb = b.effects.vignetting;
  out.effects.vignetting = {lerpValue(va.a1, vb.a1, u), lerpValue(va.a2, vb.a2, u), lerpValue(va.a3, vb.a3, u)};
}

void plan(const Lens& lens, const PlanView&, EffectNeeds& needs) {
  const Vignetting& v = lens.effects.vignetting;
  if (v.isZero()) return;
  needs.finalGain = cat("the lens's relative illumination 1 + a1 r^2 + a2 r^4 + a3 r^6 (a1 = ", v.a1, ", a2 = ", v.a2,
                        ", a3 = ", v.a3, ") at each pixel's place on the film");
}

}  // namespace

const LensEffectModule kVignettingModule{"vignetting", "common/vignetting.glsl", read, write, interpolate, plan};

}  // namespace lenslab
