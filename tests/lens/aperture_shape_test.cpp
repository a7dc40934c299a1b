// The aperture's shape (lens/ApertureShape.h): one area-preserving map from the unit disk onto a
// polygon of N blades (rounded by the roundness, squeezed by an anamorphic lens) that keeps the
// samples' strata compact.
#include "lens/ApertureShape.h"
#include "lens/AperturePattern.h"
#include "lens/LensBarrel.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace lenslab {
namespace {

double polygonArea(const std::vector<glm::dvec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
  return 0.5 * a;  // anticlockwise: positive
}

// Whether `q` lies inside the convex, anticlockwise polygon `p` (up to `tolerance`).
bool inside(const std::vector<glm::dvec2>& p, glm::dvec2 q, double tolerance) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
    const glm::dvec2 edge = b - a, toQ = q - a;
    if (edge.x * toQ.y - edge.y * toQ.x < -tolerance * glm::length(edge)) return false;
  }
  return true;
}

const std::vector<ApertureShape>& shapes() {
  static const std::vector<ApertureShape> all = {
      {3, 0.0, 0.0, 1.0}, {5, 12.0, 0.0, 1.0}, {6, 0.0, 0.0, 1.0}, {9, -40.0, 0.0, 1.0}, {6, 30.0, 0.5, 1.0},
      {8, 0.0, 0.9, 1.0}, {7, 5.0, 0.0, 2.0},  {0, 0.0, 0.0, 1.5}, {64, 0.0, 0.0, 1.0},  {6, 0.0, 0.3, 0.75},
  };
  return all;
}

TEST(ApertureShape, EqualAreasOfTheDiskStayEqualAreas) {
  // The map's Jacobian determinant is 1 everywhere (the shape has the disk's area π), measured by
  // central differences away from the seams between blades, where it is only piecewise smooth.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const ApertureShape& s : shapes()) {
    double worst = 0.0;
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec2 p = concentricDisk({u(rng), u(rng)}) * 0.98;
      if (glm::length(p) < 0.05) continue;
      if (s.blades > 0) {
        const double alpha = glm::pi<double>() / s.blades;
        const double fromSeam =
            std::remainder(std::atan2(p.y, p.x) - glm::half_pi<double>() - glm::radians(s.rotationDeg), 2.0 * alpha);
        if (std::abs(fromSeam) < 1e-3) continue;  // a vertex's direction: the seam between two blades
      }
      const double h = 1e-6;
      const glm::dvec2 dx =
          (apertureFromDisk(p + glm::dvec2(h, 0.0), s) - apertureFromDisk(p - glm::dvec2(h, 0.0), s)) / (2.0 * h);
      const glm::dvec2 dy =
          (apertureFromDisk(p + glm::dvec2(0.0, h), s) - apertureFromDisk(p - glm::dvec2(0.0, h), s)) / (2.0 * h);
      worst = std::max(worst, std::abs(dx.x * dy.y - dx.y * dy.x - 1.0));
      ++checked;
    }
    EXPECT_GT(checked, 1500);
    EXPECT_LT(worst, 1e-5) << describeAperture(s);
  }
}

TEST(ApertureShape, DiskFromApertureUndoesTheMap) {
  // Both ways round, over the whole disk and a little beyond it (the cell filter asks for points of
  // a cell's image that lie past the rim), the seams between blades included.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (const ApertureShape& s : shapes()) {
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const glm::dvec2 p(u(rng), u(rng));
      worst = std::max(worst, glm::length(diskFromAperture(apertureFromDisk(p, s), s) - p));
      worst = std::max(worst, glm::length(apertureFromDisk(diskFromAperture(p, s), s) - p));
    }
    for (const glm::dvec2& vertex : apertureVertices(s))
      worst = std::max(worst, glm::length(apertureFromDisk(diskFromAperture(vertex, s), s) - vertex));
    EXPECT_LT(worst, 1e-12) << describeAperture(s);
  }
  // A mutation that forgets the squeeze or the sector's area fails the round trip above; the
  // sectors' numbers describe the same map.
  const ApertureSectors sectors = apertureSectors({6, 30.0, 0.5, 2.0});
  EXPECT_EQ(sectors.blades, 6);
  EXPECT_NEAR(sectors.halfAngleRad, glm::pi<double>() / 6.0, 1e-15);
  EXPECT_NEAR(sectors.squeezeRoot, std::sqrt(2.0), 1e-15);
  EXPECT_EQ(apertureSectors({0, 0.0, 0.0, 1.0}).blades, 0);
}

TEST(ApertureShape, TheDiskFillsThePolygonExactly) {
  for (const ApertureShape& s : shapes()) {
    if (s.blades == 0 || s.roundness > 0.0) continue;
    const std::vector<glm::dvec2> v = apertureVertices(s);
    ASSERT_EQ(v.size(), static_cast<std::size_t>(s.blades));
    EXPECT_NEAR(polygonArea(v), glm::pi<double>(), 1e-9) << describeAperture(s) << ": the round aperture's area";
    // The first vertex straight up, turned by the rotation (before the squeeze).
    const glm::dvec2 first = v[0] * glm::dvec2(std::sqrt(s.anamorphicSqueeze), 1.0 / std::sqrt(s.anamorphicSqueeze));
    EXPECT_NEAR(std::atan2(first.y, first.x), glm::half_pi<double>() + glm::radians(s.rotationDeg), 1e-12)
        << describeAperture(s);
    // Every point of the disk lands inside; the disk's rim lands on the polygon's edges, its
    // centre at the centre.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 4000; ++i) EXPECT_TRUE(inside(v, apertureFromDisk(concentricDisk({u(rng), u(rng)}), s), 1e-12));
    for (int i = 0; i < 360; ++i) {
      const double a = glm::radians(i + 0.5);
      const glm::dvec2 rim = apertureFromDisk({std::cos(a), std::sin(a)}, s);
      EXPECT_TRUE(inside(v, rim, 1e-12));
      EXPECT_FALSE(inside(v, rim * 1.000001, 0.0)) << "the rim at " << i << " deg is not on an edge";
    }
    EXPECT_EQ(apertureFromDisk({0.0, 0.0}, s), glm::dvec2(0.0));
  }
}

TEST(ApertureShape, RoundnessBlendsThePolygonIntoTheCircle) {
  for (const double roundness : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const ApertureShape s{6, 0.0, roundness, 1.0};
    const std::vector<glm::dvec2> outline = apertureOutline(s, 2000);
    EXPECT_NEAR(polygonArea(outline), glm::pi<double>(), 1e-5) << "roundness " << roundness;
    // The rim of the disk maps onto the outline: as far out as the outline in the same direction.
    double reach = 0.0;
    for (int i = 0; i < 720; ++i) {
      const double a = glm::radians(i * 0.5 + 0.25);
      reach = std::max(reach, glm::length(apertureFromDisk({std::cos(a), std::sin(a)}, s)));
    }
    EXPECT_LE(reach, apertureReach(s) * (1.0 + 1e-12));
    // The farthest points are the corners where blades meet; the disk's rim reaches them in their
    // own directions (a vertex straight up here).
    for (int k = 0; k < 6; ++k) {
      const double a = glm::half_pi<double>() + glm::two_pi<double>() * k / 6.0;
      EXPECT_NEAR(glm::length(apertureFromDisk({std::cos(a), std::sin(a)}, s)), apertureReach(s), 1e-9)
          << "roundness " << roundness;
    }
  }
  // Roundness 1 is the circle: the map is the identity.
  const glm::dvec2 p(0.3, -0.55);
  EXPECT_EQ(apertureFromDisk(p, ApertureShape{6, 10.0, 1.0, 1.0}), p);
  EXPECT_EQ(apertureFromDisk(p, ApertureShape{}), p);
  EXPECT_TRUE((ApertureShape{6, 10.0, 1.0, 1.0}).isRound());
  EXPECT_FALSE((ApertureShape{6, 0.0, 0.0, 1.0}).isRound());
}

TEST(ApertureShape, TheSqueezeMakesTheShapeTallerByItsRatioAndKeepsTheArea) {
  const ApertureShape oval{0, 0.0, 0.0, 2.0};
  const std::vector<glm::dvec2> outline = apertureOutline(oval, 4000);
  double width = 0.0, height = 0.0;
  for (const glm::dvec2& p : outline) width = std::max(width, std::abs(p.x)), height = std::max(height, std::abs(p.y));
  EXPECT_NEAR(height / width, 2.0, 1e-6);
  EXPECT_NEAR(polygonArea(outline), glm::pi<double>(), 1e-5);
  EXPECT_NEAR(apertureReach(oval), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(apertureReach(ApertureShape{0, 0.0, 0.0, 0.5}), std::sqrt(2.0), 1e-12);
}

TEST(ApertureShape, StrataStayCompact) {
  // A 32 × 32 grid of strata on the square, through the concentric map and then the shape: no
  // stratum is stretched much beyond what the concentric map alone makes of it.
  constexpr int n = 32;
  for (const ApertureShape& s : shapes()) {
    double worstDisk = 0.0, worstShape = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::vector<glm::dvec2> disk, shaped;
        for (int c = 0; c <= 4; ++c)
          for (int d = 0; d <= 4; ++d) {
            const glm::dvec2 p = concentricDisk({(i + c / 4.0) / n, (j + d / 4.0) / n});
            disk.push_back(p);
            shaped.push_back(apertureFromDisk(p, s));
          }
        for (std::size_t a = 0; a < disk.size(); ++a)
          for (std::size_t b = a + 1; b < disk.size(); ++b) {
            worstDisk = std::max(worstDisk, glm::length(disk[a] - disk[b]));
            worstShape = std::max(worstShape, glm::length(shaped[a] - shaped[b]));
          }
      }
    EXPECT_LT(worstShape, 2.5 * worstDisk)
        << describeAperture(s) << ": a stratum " << worstShape << " across against " << worstDisk << " on the disk";
  }
}

TEST(ApertureShape, OutOfRangeShapesNameTheirField) {
  const auto field = [](ApertureShape s) {
    const std::optional<ApertureProblem> p = apertureShapeProblem(s);
    return p ? p->field : std::string();
  };
  EXPECT_EQ(field({}), "");
  EXPECT_EQ(field({3, 0.0, 0.0, 1.0}), "");
  EXPECT_EQ(field({2, 0.0, 0.0, 1.0}), "blades");
  EXPECT_EQ(field({-1, 0.0, 0.0, 1.0}), "blades");
  EXPECT_EQ(field({65, 0.0, 0.0, 1.0}), "blades");
  EXPECT_EQ(field({6, std::nan(""), 0.0, 1.0}), "rotation_deg");
  EXPECT_EQ(field({6, 0.0, -0.1, 1.0}), "roundness");
  EXPECT_EQ(field({6, 0.0, 1.5, 1.0}), "roundness");
  EXPECT_EQ(field({6, 0.0, 0.0, 0.0}), "anamorphic_squeeze");
  EXPECT_EQ(field({6, 0.0, 0.0, 11.0}), "anamorphic_squeeze");
  EXPECT_EQ(field({6, 0.0, 0.0, std::nan("")}), "anamorphic_squeeze");
  EXPECT_NE(apertureShapeProblem({2, 0.0, 0.0, 1.0})->message.find("3 to 64"), std::string::npos);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

TEST(LensBarrel, TheCatsEyeIsTheTwoCirclesOverlap) {
  // The share of a round aperture the opening lets through, counted over a fine grid of aperture
  // points with throughBarrel, against the closed-form overlap.
  const LensBarrel barrel{0.04, 0.015};
  const double radius = 0.0125, inverseFocus = 0.5;
  for (const glm::dvec2 n : {glm::dvec2(0.0, 0.0), glm::dvec2(0.2, 0.0), glm::dvec2(0.3, -0.4), glm::dvec2(0.0, 0.6),
                             glm::dvec2(2.0, 0.0)}) {
    int inside = 0, through = 0;
    constexpr int kGrid = 600;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const glm::dvec2 p = radius * glm::dvec2(2.0 * (i + 0.5) / kGrid - 1.0, 2.0 * (j + 0.5) / kGrid - 1.0);
        if (glm::dot(p, p) > radius * radius) continue;
        ++inside;
        through += throughBarrel(barrel, p, n, inverseFocus);
      }
    EXPECT_NEAR(static_cast<double>(through) / inside, roundApertureThroughBarrel(barrel, radius, n, inverseFocus),
                2e-3)
        << "n = (" << n.x << ", " << n.y << ")";
  }
  EXPECT_EQ(roundApertureThroughBarrel(barrel, radius, {0.0, 0.0}, inverseFocus), 1.0);  // 0.0125·0.98 inside 0.015
  EXPECT_EQ(roundApertureThroughBarrel(barrel, radius, {2.0, 0.0}, inverseFocus), 0.0);  // 0.08 away: no overlap
  EXPECT_EQ(roundApertureThroughBarrel(LensBarrel{}, radius, {2.0, 0.0}, inverseFocus), 1.0);  // no barrel
}

TEST(LensBarrel, MillimetresBecomeWorldUnitsAndBadValuesNameTheirField) {
  const LensBarrel b = barrelFromMillimetres(40.0, 30.0);
  EXPECT_DOUBLE_EQ(b.distance, 0.04);
  EXPECT_DOUBLE_EQ(b.radius, 0.015);
  EXPECT_FALSE(barrelProblem(40.0, 30.0));
  EXPECT_EQ(barrelProblem(0.0, 30.0)->field, "distance_mm");
  EXPECT_EQ(barrelProblem(std::nan(""), 30.0)->field, "distance_mm");
  EXPECT_EQ(barrelProblem(40.0, -1.0)->field, "diameter_mm");
  EXPECT_EQ(barrelProblem(40.0, 1e9)->field, "diameter_mm");
}

}  // namespace
}  // namespace lenslab
