#include "lens/LensEffects.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lenslab {
namespace {

// lenslab's normalised frame has y up, OpenCV's y down: the same point is (x, −y) there.
glm::dvec2 flipY(glm::dvec2 p) { return {p.x, -p.y}; }

struct Radial {
  double g;  // 1 + α r + (k1 + β) r² + γ r³ + k2 r⁴ + k3 r⁶
  double h;  // g'(r) / r, so that ∂g/∂x = h·x (0 at the centre, where the α term has no derivative)
};

Radial radial(const Distortion& d, double r) {
  const double r2 = r * r;
  const double k1 = d.k1 + d.beta;
  Radial out;
  out.g = 1.0 + r * (d.alpha + r * (k1 + r * d.gamma)) + r2 * r2 * (d.k2 + r2 * d.k3);
  out.h = 2.0 * k1 + 3.0 * d.gamma * r + 4.0 * d.k2 * r2 + 6.0 * d.k3 * r2 * r2 + (r > 0.0 ? d.alpha / r : 0.0);
  return out;
}

}  // namespace

bool Distortion::isZero() const {
  return k1 == 0.0 && k2 == 0.0 && p1 == 0.0 && p2 == 0.0 && k3 == 0.0 && alpha == 0.0 && beta == 0.0 &&
         gamma == 0.0;
}

glm::dvec2 Distortion::distort(glm::dvec2 undistorted) const {
  const glm::dvec2 p = flipY(undistorted);  // OpenCV's frame from here on
  const double x = p.x, y = p.y;
  const double r2 = x * x + y * y;
  const double g = radial(*this, std::sqrt(r2)).g;
  const glm::dvec2 d(x * g + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
                     y * g + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y);
  return flipY(d);
}

glm::dmat2 Distortion::jacobian(glm::dvec2 undistorted) const {
  const glm::dvec2 p = flipY(undistorted);
  const double x = p.x, y = p.y;
  const Radial rad = radial(*this, std::sqrt(x * x + y * y));
  // OpenCV's frame: J = [[∂xd/∂x, ∂xd/∂y], [∂yd/∂x, ∂yd/∂y]].
  const double dxdx = rad.g + rad.h * x * x + 2.0 * p1 * y + 6.0 * p2 * x;
  const double dxdy = rad.h * x * y + 2.0 * p1 * x + 2.0 * p2 * y;
  const double dydx = rad.h * x * y + 2.0 * p1 * x + 2.0 * p2 * y;
  const double dydy = rad.g + rad.h * y * y + 6.0 * p1 * y + 2.0 * p2 * x;
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
  for (const glm::dvec2 c : {distortedMin, distortedMax, glm::dvec2(distortedMin.x, distortedMax.y),
                             glm::dvec2(distortedMax.x, distortedMin.y)})
    extent = std::max(extent, glm::length(c));
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

bool Vignetting::isZero() const { return a1 == 0.0 && a2 == 0.0 && a3 == 0.0; }

double Vignetting::gain(double r2) const {
  const double g = 1.0 + r2 * (a1 + r2 * (a2 + r2 * a3));
  return g > 0.0 ? g : 0.0;  // also 0 for NaN: a pixel is never given a negative or undefined light
}

namespace {

// The polynomial without the clamp, in t = r².
double vignettingPolynomial(const Vignetting& v, double t) { return 1.0 + t * (v.a1 + t * (v.a2 + t * v.a3)); }

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
    if (!(vignettingPolynomial(v, end) > 0.0)) {
      double hi = end;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (vignettingPolynomial(v, mid) > 0.0 ? lo : hi) = mid;
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
  for (const double end : monotoneStretchEnds(v, r2Max)) largest = std::max(largest, vignettingPolynomial(v, end));
  return largest;
}

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

std::optional<glm::dvec2> LensEffects::undistortChannel(Channel c, glm::dvec2 distorted, glm::dvec2 guess) const {
  // Lateral colour scales the channel's image about the principal point, after the distortion.
  const glm::dvec2 green = distorted / (1.0 + chromatic.lateral(c));
  return distortion.undistort(green, guess);
}

glm::dvec2 LensEffects::distortChannel(Channel c, glm::dvec2 undistorted) const {
  return distortion.distort(undistorted) * (1.0 + chromatic.lateral(c));
}

double LensEffects::inverseFocusShift(Channel c, glm::dvec2 undistorted) const {
  return chromatic.inverseFocusShift(c) + fieldCurvature.inverseFocusPerRadius2 * glm::dot(undistorted, undistorted);
}

}  // namespace lenslab
