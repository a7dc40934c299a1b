// Distortion: the model (Brown–Conrady in OpenCV's convention with the lecture's series) and its
// module (LensEffectModule.h).
//
// Camera file: "distortion": {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6", "s1", "s2", "s3", "s4",
// "alpha", "beta", "gamma"} (missing keys 0), or OpenCV's distCoeffs array as "distortion" or, in
// the OpenCV form, "dist".
// Path: each coefficient linear. Plan: the lens remap pass ("distortion" variant).
#include "lens/effects/Distortion.h"

#include "core/NumberInput.h"
#include "core/Text.h"
#include "lens/effects/LensEffectModule.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab {
namespace {

// lenslab's normalised frame has y up, OpenCV's y down: the same point is (x, −y) there.
glm::dvec2 flipY(glm::dvec2 p) { return {p.x, -p.y}; }

struct Radial {
  double g;  // (1 + α r + (k1 + β) r² + γ r³ + k2 r⁴ + k3 r⁶) / (1 + k4 r² + k5 r⁴ + k6 r⁶)
  double h;  // g'(r) / r, so that ∂g/∂x = h·x (0 at the centre, where the α term has no derivative)
};

// The fisheye's θ_d(θ) and dθ_d/dθ.
struct FisheyeRadius {
  double value, slope;
};
FisheyeRadius fisheyeRadius(const Distortion& d, double theta) {
  const double t2 = theta * theta;
  const double poly = 1.0 + t2 * (d.k1 + t2 * (d.k2 + t2 * (d.k3 + t2 * d.k4)));
  const double slope = 1.0 + t2 * (3.0 * d.k1 + t2 * (5.0 * d.k2 + t2 * (7.0 * d.k3 + t2 * 9.0 * d.k4)));
  return {theta * poly, slope};
}

// The fisheye as a radial factor of the true perspective radius r = tan θ: g = θ_d / r.
Radial fisheyeRadial(const Distortion& d, double r) {
  const double theta = std::atan(r);
  const FisheyeRadius f = fisheyeRadius(d, theta);
  const double g = r > 0.0 ? f.value / r : 1.0;
  // Near the centre g = 1 + (k1 − 1/3) r² + O(r⁴), so h = 2(k1 − 1/3) + O(r²); the closed form
  // below would lose its digits to cancellation there.
  if (r < 1e-4) return {g, 2.0 * (d.k1 - 1.0 / 3.0)};
  const double slopePerR = f.slope / (1.0 + r * r);  // dθ_d/dr = dθ_d/dθ · dθ/dr
  return {g, (slopePerR - g) / (r * r)};             // g'/r with g' = (dθ_d/dr − g) / r
}

Radial radial(const Distortion& d, double r) {
  if (d.fisheye) return fisheyeRadial(d, r);
  const double r2 = r * r;
  const double k1 = d.k1 + d.beta;
  const double top = 1.0 + r * (d.alpha + r * (k1 + r * d.gamma)) + r2 * r2 * (d.k2 + r2 * d.k3);
  const double topH =
      2.0 * k1 + 3.0 * d.gamma * r + 4.0 * d.k2 * r2 + 6.0 * d.k3 * r2 * r2 + (r > 0.0 ? d.alpha / r : 0.0);
  const double bottom = 1.0 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
  const double bottomH = 2.0 * d.k4 + 4.0 * d.k5 * r2 + 6.0 * d.k6 * r2 * r2;
  // (top / bottom)' / r by the quotient rule; a denominator at or below 0 is the rational model's
  // pole, beyond which no lens maps: the Jacobian below turns singular there (a fold).
  return {top / bottom, (topH * bottom - top * bottomH) / (bottom * bottom)};
}

bool radialDefined(const Distortion& d, double r2) {
  return d.fisheye || 1.0 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6)) > 0.0;
}

}  // namespace

bool Distortion::isZero() const {
  if (fisheye) return false;  // k1 = … = k4 = 0 is the equidistant fisheye
  for (const DistortionTerm& t : kDistortionTerms)
    if (this->*t.value != 0.0) return false;
  return true;
}

std::vector<double> Distortion::distCoeffs() const {
  std::size_t n = 5;
  for (std::size_t i = 5; i < kOpenCvDistortionTerms; ++i)
    if (this->*kDistortionTerms[i].value != 0.0) n = i < 8 ? 8 : 12;
  std::vector<double> c;
  for (std::size_t i = 0; i < n; ++i) c.push_back(this->*kDistortionTerms[i].value);
  return c;
}

std::optional<Distortion::FisheyeReach> Distortion::fisheyeReach() const {
  if (!fisheye) return std::nullopt;
  // dθ_d/dθ is a polynomial in θ²: walk [0, 90°] for its first zero, then bisect on it.
  constexpr int kSteps = 4096;
  const double right = M_PI / 2.0;
  double before = 0.0;
  for (int i = 1; i <= kSteps; ++i) {
    const double theta = right * i / kSteps;
    if (fisheyeRadius(*this, theta).slope > 0.0) {
      before = theta;
      continue;
    }
    double lo = before, hi = theta;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (fisheyeRadius(*this, mid).slope > 0.0 ? lo : hi) = mid;
    }
    return FisheyeReach{lo, fisheyeRadius(*this, lo).value, true};
  }
  return FisheyeReach{right, fisheyeRadius(*this, right).value, false};
}

std::string distortionTermsText(const Distortion& d) {
  std::string text;
  if (d.fisheye) {
    const std::pair<const char*, double> terms[] = {{"k1", d.k1}, {"k2", d.k2}, {"k3", d.k3}, {"k4", d.k4}};
    for (const auto& [name, value] : terms)
      if (value != 0.0) text += cat(text.empty() ? "" : ", ", name, " = ", value);
    return text.empty() ? "the equidistant fisheye" : cat("fisheye ", text);
  }
  for (const DistortionTerm& t : kDistortionTerms)
    if (d.*t.value != 0.0) text += cat(text.empty() ? "" : ", ", t.name, " = ", d.*t.value);
  return text;
}

Distortion distortionFromDistCoeffs(const std::vector<double>& coefficients) {
  Distortion d;
  for (std::size_t i = 0; i < coefficients.size() && i < kOpenCvDistortionTerms; ++i)
    d.*kDistortionTerms[i].value = coefficients[i];
  return d;
}

glm::dvec2 Distortion::distort(glm::dvec2 undistorted) const {
  const glm::dvec2 p = flipY(undistorted);  // OpenCV's frame from here on
  const double x = p.x, y = p.y;
  const double r2 = x * x + y * y;
  const double g = radial(*this, std::sqrt(r2)).g;
  const glm::dvec2 d(x * g + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x) + r2 * (s1 + s2 * r2),
                     y * g + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y + r2 * (s3 + s4 * r2));
  return flipY(d);
}

glm::dmat2 Distortion::jacobian(glm::dvec2 undistorted) const {
  const glm::dvec2 p = flipY(undistorted);
  const double x = p.x, y = p.y;
  const double r2 = x * x + y * y;
  if (!radialDefined(*this, r2)) return glm::dmat2(0.0);
  const Radial rad = radial(*this, std::sqrt(r2));
  // The thin prism's s r² + s' r⁴ has gradient (2s + 4s' r²)·(x, y).
  const double prismX = 2.0 * s1 + 4.0 * s2 * r2, prismY = 2.0 * s3 + 4.0 * s4 * r2;
  // OpenCV's frame: J = [[∂xd/∂x, ∂xd/∂y], [∂yd/∂x, ∂yd/∂y]].
  const double dxdx = rad.g + rad.h * x * x + 2.0 * p1 * y + 6.0 * p2 * x + prismX * x;
  const double dxdy = rad.h * x * y + 2.0 * p1 * x + 2.0 * p2 * y + prismX * y;
  const double dydx = rad.h * x * y + 2.0 * p1 * x + 2.0 * p2 * y + prismY * x;
  const double dydy = rad.g + rad.h * y * y + 6.0 * p1 * y + 2.0 * p2 * x + prismY * y;
  // Back to y up: F·J·F with F = diag(1, −1) flips the off-diagonal signs. glm is column-major.
  return glm::dmat2(glm::dvec2(dxdx, -dydx), glm::dvec2(-dxdy, dydy));
}

namespace {

// Newton's method in double from `guess`; empty when it does not settle on the branch that
// contains the centre (where the Jacobian's determinant is positive).
std::optional<glm::dvec2> newton(const Distortion& d, glm::dvec2 distorted, glm::dvec2 guess) {
  glm::dvec2 x = guess;
  for (int i = 0; i < 64; ++i) {
    const glm::dmat2 j = d.jacobian(x);
    const double det = glm::determinant(j);
    if (!(std::abs(det) > 1e-300)) return std::nullopt;
    const glm::dvec2 step = glm::inverse(j) * (d.distort(x) - distorted);
    x -= step;
    if (!std::isfinite(x.x) || !std::isfinite(x.y)) return std::nullopt;
    if (glm::length(step) <= 1e-13 * std::max(1.0, glm::length(x))) {
      // Only the branch that contains the centre is the lens's: beyond a fold lies its mirror
      // (det J < 0), beyond the radial factor's zero a point reflection (det J > 0 again, but the
      // point lands on the other side of the centre), and a polynomial that turns back up has an
      // outer branch (det J > 0, same side). The segment from the centre must not cross a fold.
      for (int k = 1; k <= 8; ++k)
        if (!(glm::determinant(d.jacobian(x * (k / 8.0))) > 0.0)) return std::nullopt;
      if (!(glm::dot(d.distort(x), x) >= 0.0)) return std::nullopt;
      return x;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<glm::dvec2> Distortion::undistort(glm::dvec2 distorted, glm::dvec2 guess) const {
  if (isZero()) return distorted;
  if (const auto x = newton(*this, distorted, guess)) return x;
  // Strong distortion can throw Newton off its branch from a poor guess. Continuation from the
  // centre then: the target slides from (0, 0) to `distorted` along the segment, each step solved
  // from the last solution, so the path never leaves the branch that contains the centre and stops
  // only at a real fold (a singular Jacobian on the way).
  for (int steps = 8; steps <= 2048; steps *= 4) {
    glm::dvec2 x(0.0);
    bool reached = true;
    for (int i = 1; i <= steps && reached; ++i) {
      const auto next = newton(*this, distorted * (static_cast<double>(i) / steps), x);
      reached = next.has_value();
      if (next) x = *next;
    }
    if (reached) return x;
  }
  return std::nullopt;
}

std::optional<FoldOver> findFoldOver(const Distortion& distortion, glm::dvec2 distortedMin, glm::dvec2 distortedMax) {
  if (distortion.isZero()) return std::nullopt;
  const auto inside = [&](glm::dvec2 p) {
    return p.x >= distortedMin.x && p.x <= distortedMax.x && p.y >= distortedMin.y && p.y <= distortedMax.y;
  };
  double extent = 0.0;  // the farthest corner of the region from the principal point
  glm::dvec2 farthest(0.0);
  for (const glm::dvec2 c : {distortedMin, distortedMax, glm::dvec2(distortedMin.x, distortedMax.y),
                             glm::dvec2(distortedMax.x, distortedMin.y)})
    if (glm::length(c) > extent) extent = glm::length(c), farthest = c;
  // The fisheye is radial in θ: it folds where dθ_d/dθ reaches 0, toward every direction at once.
  if (const auto reach = distortion.fisheyeReach()) {
    if (!reach->folds || reach->distortedRadius > extent) return std::nullopt;
    const glm::dvec2 direction = farthest / extent;
    return FoldOver{std::tan(reach->theta) * direction, reach->distortedRadius * direction};
  }
  // Walk outward along rays from the centre, over the branch of the map that the inverse uses
  // (the one that contains the centre): up to the first point where the Jacobian's determinant
  // stops being positive. That point folds the image if its distorted position is inside the
  // region; beyond it the polynomial may come back into the region (a mirrored ring, outside any
  // real lens's field stop), which the inverse never uses.
  constexpr int kAngles = 360;
  constexpr int kSteps = 1000;
  const double step = extent / kSteps;
  const double giveUp = 16.0 * extent;
  std::optional<FoldOver> nearest;
  for (int a = 0; a < kAngles; ++a) {
    const double angle = 2.0 * M_PI * (a + 0.5) / kAngles;
    const glm::dvec2 direction(std::cos(angle), std::sin(angle));
    for (double t = 0.0;; t += step) {
      const glm::dvec2 p = t * direction;
      const glm::dvec2 d = distortion.distort(p);
      const bool folded = !(glm::determinant(distortion.jacobian(p)) > 0.0);
      // A polynomial that never carries this ray out of the region (it stalls) folds it too.
      const bool stalled = t + step >= giveUp;
      if (folded || stalled) {
        if (inside(d) && (!nearest || glm::length(p) < glm::length(nearest->undistorted))) nearest = FoldOver{p, d};
        break;
      }
      if (glm::length(d) > 2.0 * extent) break;
    }
  }
  return nearest;
}

namespace {

std::set<std::string> termNames() {
  std::set<std::string> names;
  for (const DistortionTerm& t : kDistortionTerms) names.insert(t.name);
  return names;
}

// OpenCV's distCoeffs as a calibration prints them: 4, 5, 8 (the rational model), 12 (and the thin
// prism) or 14 numbers; the 14's last two (τx, τy: a tilted sensor) must be 0.
Distortion distCoeffsOf(const KeyReader& r, const std::string& key) {
  const std::size_t n = r.arraySize(key);
  if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
    r.fail(key, cat("as an array is OpenCV's distCoeffs: 4, 5, 8, 12 or 14 numbers (k1, k2, p1, p2[, k3[, k4, k5, "
                    "k6[, s1, s2, s3, s4[, tauX, tauY]]]]), not ",
                    excerpt(r.text(key))));
  std::vector<double> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::optional<double> value = r.element(key, i);
    if (!value) r.fail(key, "must hold finite numbers");
    c[i] = *value;
  }
  for (std::size_t i = kOpenCvDistortionTerms; i < n; ++i)
    if (c[i] != 0.0)
      r.fail(key, cat("has ", i == 12 ? "tauX" : "tauY", " = ", c[i], " (element ", i,
                      "): a tilted sensor (OpenCV's CALIB_TILTED_MODEL) is not modelled; its terms must be 0"));
  return distortionFromDistCoeffs(c);
}

// "model": "fisheye" with k1 … k4 (cv::fisheye's D), or OpenCV's standard model ("opencv", the default).
void readObject(const KeyReader& r, Distortion& d) {
  std::set<std::string> names = termNames();
  names.insert("model");
  const std::unique_ptr<KeyReader> o = r.object("distortion", names);
  if (o->has("model")) {
    const std::string model = o->string("model");
    if (model != "opencv" && model != "fisheye")
      o->fail("model", cat("is \"", excerpt(model),
                           "\"; use \"opencv\" (Brown–Conrady, the default) or \"fisheye\" "
                           "(OpenCV's fisheye model: k1, k2, k3, k4 on the angle from the axis)"));
    d.fisheye = model == "fisheye";
  }
  for (const DistortionTerm& t : kDistortionTerms) {
    if (!o->has(t.name)) continue;
    const std::string name = t.name;
    if (d.fisheye && name != "k1" && name != "k2" && name != "k3" && name != "k4")
      o->fail(name,
              "is not a term of the fisheye model, which takes k1, k2, k3 and k4 (θ_d = θ(1 + k1 θ² + k2 θ⁴ "
              "+ k3 θ⁶ + k4 θ⁸)); leave it out or use \"model\": \"opencv\"");
    d.*t.value = o->number(t.name);
  }
}

void read(const KeyReader& r, const LensFrame&, Lens& lens) {
  Distortion& d = lens.effects.distortion;
  if (r.has("dist") && r.has("distortion")) r.fail("dist", "and \"distortion\" both give the distortion; give one");
  if (r.has("dist")) {
    if (!r.isArray("dist"))
      r.fail("dist", cat("is OpenCV's distCoeffs array [k1, k2, p1, p2, k3, ...], not ", r.text("dist")));
    d = distCoeffsOf(r, "dist");
  }
  if (!r.has("distortion")) return;
  if (r.isArray("distortion")) {
    d = distCoeffsOf(r, "distortion");
    return;
  }
  readObject(r, d);
}

void write(const Lens& lens, const LensFrame&, KeyWriter& camera) {
  const Distortion& k = lens.effects.distortion;
  if (k.isZero()) return;
  KeyWriter& d = camera.object("distortion");
  if (k.fisheye) d.string("model", "fisheye");
  for (const DistortionTerm& t : kDistortionTerms)
    if (k.*t.value != 0.0) d.number(t.name, k.*t.value);
}

void interpolate(const Lens& a, const Lens& b, double u, Lens& out) {
  const Distortion &x = a.effects.distortion, &y = b.effects.distortion;
  Distortion& d = out.effects.distortion;
  for (const DistortionTerm& t : kDistortionTerms) d.*t.value = lerpValue(x.*t.value, y.*t.value, u);
  d.fisheye = x.fisheye;  // the path reader refuses keys of different models
}

void plan(const Lens& lens, const PlanView&, EffectNeeds& needs) {
  if (lens.effects.distortion.isZero()) return;
  needs.lensVariants.push_back("distortion");
  needs.remapTables = std::max(needs.remapTables, 1);
}

}  // namespace

extern const LensEffectModule kDistortionModule;
const LensEffectModule kDistortionModule{"distortion", "lens/remap.frag", read, write, interpolate, plan};

}  // namespace lenslab
