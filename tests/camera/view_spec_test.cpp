#include "camera/ViewSpec.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace lenslab {
namespace {

ViewSpec validSpec() {
  ViewSpec s;
  s.vrp = {1.0, 2.0, 3.0};
  s.vpn = {0.3, 0.2, 1.0};
  s.vup = {0.0, 1.0, 0.0};
  s.prp = {0.0, 0.0, 2.0};
  s.window = {-1.0, -0.5, 1.0, 0.5};
  s.nearDistance = 0.01;
  return s;
}

// Expects validate() to throw an InputError whose message contains `fragment` and the file name.
void expectRefused(const ViewSpec& spec, const std::string& fragment) {
  try {
    validate(spec, "cam.json");
    FAIL() << "accepted a degenerate camera; expected an error mentioning " << fragment;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cam.json"), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

TEST(ViewSpec, BasisIsOrthonormalAndRightHandedForRandomInputs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    ViewSpec s = validSpec();
    s.vpn = {d(rng), d(rng), d(rng)};
    s.vup = {d(rng), d(rng), d(rng)};
    if (glm::length(glm::cross(s.vpn, s.vup)) < 1e-3) continue;
    const ViewBasis b = viewBasis(s);
    EXPECT_NEAR(glm::length(b.u), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(b.v), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(b.n), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(b.u, b.v), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(b.u, b.n), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(b.v, b.n), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(b.u, b.v), b.n), 1.0, 1e-12) << "right-handed: u x v = n";
    EXPECT_GT(glm::dot(glm::normalize(s.vpn), b.n), 0.999999) << "n points along VPN";
    EXPECT_GT(glm::dot(s.vup, b.v), 0.0) << "VUP projects onto +v";
  }
}

TEST(ViewSpec, AcceptsAValidCamera) { EXPECT_NO_THROW(validate(validSpec(), "cam.json")); }

TEST(ViewSpec, RefusesDegenerateCameras) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  ViewSpec s = validSpec();
  s.vpn = {0, 0, 0};
  expectRefused(s, "vpn");
  s = validSpec();
  s.vup = 5.0 * glm::normalize(s.vpn);
  expectRefused(s, "parallel");
  s = validSpec();
  s.window = {1, -1, 1, 1};
  expectRefused(s, "window");
  s = validSpec();
  s.window = {-1, 1, 1, -1};
  expectRefused(s, "inverted");
  s = validSpec();
  s.prp = {0, 0, 0};
  expectRefused(s, "view plane");
  s = validSpec();
  s.prp = {0, 0, -1};
  expectRefused(s, "prp");
  s = validSpec();
  s.nearDistance = 10;
  s.farDistance = 5;
  expectRefused(s, "near");
  s = validSpec();
  s.nearDistance = 1;
  s.farDistance = 1;
  expectRefused(s, "near");
  s = validSpec();
  s.nearDistance = 0;
  expectRefused(s, "near");
  s = validSpec();
  s.vrp.x = nan;
  expectRefused(s, "vrp");
  s = validSpec();
  s.prp.y = inf;
  expectRefused(s, "prp");
  s = validSpec();
  s.window.umax = nan;
  expectRefused(s, "window");
  s = validSpec();
  s.farDistance = nan;
  expectRefused(s, "far");
  s = validSpec();
  s.projection = Projection::Parallel;
  expectRefused(s, "far must be finite");
}

// The view plane scaled toward the PRP (window and near with it): taken down to kMinPrpDistance,
// refused in one line below, with the smallest valid value in the message.
TEST(ViewSpec, TakesThePrpDownToTheSmallestDistanceAndRefusesItBelow) {
  const auto scaled = [](double n) {
    ViewSpec s = validSpec();
    s.prp = {0, 0, n};
    s.window = {-n, -n, n, n};
    s.nearDistance = n / 1000;
    return s;
  };
  EXPECT_NO_THROW(validate(scaled(kMinPrpDistance), "cam.json"));
  expectRefused(scaled(0.5 * kMinPrpDistance), "prp.n");
  try {
    validate(scaled(0.5 * kMinPrpDistance), "cam.json");
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find("1e-300"), std::string::npos) << m;
  }
}

TEST(ViewSpec, TakesAFieldOfViewDownTo1e12RadAndRefusesItBelow) {
  ViewSpec s = validSpec();
  s.window = {-0.5e-12 * s.prp.z, -0.5e-12 * s.prp.z, 0.5e-12 * s.prp.z, 0.5e-12 * s.prp.z};
  s.window.umax *= 1.01;
  s.window.vmax *= 1.01;
  EXPECT_NO_THROW(validate(s, "cam.json"));
  s.window.vmax = s.window.vmin + 0.5e-12 * s.prp.z;
  expectRefused(s, "field of view");
}

TEST(ViewSpec, DirectionOfProjectionIsWindowCentreMinusPrp) {
  ViewSpec s = validSpec();
  s.window = {0.0, 1.0, 4.0, 3.0};
  s.prp = {1.0, 1.0, 5.0};
  const glm::dvec3 dop = directionOfProjection(s);
  EXPECT_DOUBLE_EQ(dop.x, 1.0);
  EXPECT_DOUBLE_EQ(dop.y, 1.0);
  EXPECT_DOUBLE_EQ(dop.z, -5.0);
}

}  // namespace
}  // namespace lenslab
