// lens/ApertureCells: the aperture cut into N equal cells, one per view of the cell filter. Each
// sample lies in its own cell, the cells tile the unit disk without overlap (every point of the
// disk in exactly one), each holds π/N of it; 'sobol' at a power of two is the pattern's own points,
// one in each box of its net; the concentric map's inverse undoes it.
#include "lens/ApertureCells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace lenslab {
namespace {

glm::dvec2 randomDiskPoint(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    const glm::dvec2 p(u(rng), u(rng));
    if (glm::dot(p, p) < 1.0) return p;
  }
}

TEST(ConcentricSquare, UndoesTheConcentricMap) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec2 square(u(rng), u(rng));
    const glm::dvec2 back = concentricSquare(concentricDisk(square));
    ASSERT_NEAR(back.x, square.x, 1e-12) << i;
    ASSERT_NEAR(back.y, square.y, 1e-12) << i;
  }
}

TEST(ConcentricSquare, APointOutsideTheDiskIsOutsideTheSquare) {
  for (const glm::dvec2 p :
       {glm::dvec2(1.2, 0.0), glm::dvec2(0.0, -1.5), glm::dvec2(-0.9, 0.9), glm::dvec2(2.0, 1.0)}) {
    const glm::dvec2 u = concentricSquare(p);
    EXPECT_TRUE(u.x < 0.0 || u.x > 1.0 || u.y < 0.0 || u.y > 1.0) << p.x << ", " << p.y;
  }
}

struct CellCase {
  AperturePattern pattern;
  int count;
};

class Cells : public testing::TestWithParam<CellCase> {};

TEST_P(Cells, EachSampleLiesInItsOwnCellOfAnEqualShare) {
  const CellCase c = GetParam();
  const CellSamples cells = makeCellSamples(c.pattern, c.count, 7);
  ASSERT_EQ(cells.samples.size(), static_cast<std::size_t>(c.count));
  ASSERT_EQ(cells.cells.size(), static_cast<std::size_t>(c.count));
  double total = 0.0;
  for (int i = 0; i < c.count; ++i) {
    const ApertureCell& cell = cells.cells[static_cast<std::size_t>(i)];
    EXPECT_TRUE(cell.contains(cells.samples[static_cast<std::size_t>(i)].lens)) << "sample " << i;
    EXPECT_NEAR(cell.area(), std::numbers::pi / c.count, 1e-12) << "cell " << i;
    total += cell.area();
    for (const glm::dvec2& p : cell.outline(8)) EXPECT_LE(glm::length(p), 1.0 + 1e-12);
    const glm::dvec2 pixel = cells.samples[static_cast<std::size_t>(i)].pixel;
    EXPECT_TRUE(pixel.x >= -0.5 && pixel.x < 0.5 && pixel.y >= -0.5 && pixel.y < 0.5);
  }
  EXPECT_NEAR(total, std::numbers::pi, 1e-9);
}

TEST_P(Cells, TileTheDiskWithoutOverlap) {
  const CellCase c = GetParam();
  const CellSamples cells = makeCellSamples(c.pattern, c.count, 7);
  std::mt19937 rng(11);
  std::vector<int> hits(static_cast<std::size_t>(c.count), 0);
  constexpr int kPoints = 40000;
  for (int i = 0; i < kPoints; ++i) {
    const glm::dvec2 p = randomDiskPoint(rng);
    int inside = 0;
    for (int k = 0; k < c.count; ++k)
      if (cells.cells[static_cast<std::size_t>(k)].contains(p)) {
        ++inside;
        ++hits[static_cast<std::size_t>(k)];
      }
    ASSERT_EQ(inside, 1) << "point " << p.x << ", " << p.y;
  }
  // Equal areas: each cell's share of uniform points within 5 standard deviations of 1/N.
  const double share = 1.0 / c.count, sigma = std::sqrt(share * (1.0 - share) / kPoints);
  for (int k = 0; k < c.count; ++k)
    EXPECT_NEAR(hits[static_cast<std::size_t>(k)] / double(kPoints), share, 5.0 * sigma + 1e-12) << "cell " << k;
}

INSTANTIATE_TEST_SUITE_P(RingsAndSobol, Cells,
                         testing::Values(CellCase{AperturePattern::Rings, 1}, CellCase{AperturePattern::Rings, 2},
                                         CellCase{AperturePattern::Rings, 3}, CellCase{AperturePattern::Rings, 7},
                                         CellCase{AperturePattern::Rings, 16}, CellCase{AperturePattern::Rings, 30},
                                         CellCase{AperturePattern::Sobol, 1}, CellCase{AperturePattern::Sobol, 2},
                                         CellCase{AperturePattern::Sobol, 4}, CellCase{AperturePattern::Sobol, 8},
                                         CellCase{AperturePattern::Sobol, 16}, CellCase{AperturePattern::Sobol, 64}));

TEST(Cells, SobolCellsAreThePatternsOwnPointsOnePerBox) {
  for (const int count : {4, 8, 32, 256}) {
    const CellSamples cells = makeCellSamples(AperturePattern::Sobol, count, 3);
    const std::vector<LensSample> pattern = makeApertureSamples(AperturePattern::Sobol, count, 3);
    for (int i = 0; i < count; ++i) {
      EXPECT_EQ(cells.samples[static_cast<std::size_t>(i)].lens, pattern[static_cast<std::size_t>(i)].lens);
      for (int j = 0; j < i; ++j)
        EXPECT_NE(cells.cells[static_cast<std::size_t>(i)].squareMin,
                  cells.cells[static_cast<std::size_t>(j)].squareMin)
            << count << " points: " << i << " and " << j << " share a box";
    }
  }
}

TEST(Cells, TheMomentRectangleHasTheCellsAreaAndCentroid) {
  // A ring sector's centroid: along its middle angle at (2/3)(r1³ − r0³)/(r1² − r0²) · sin(h)/h,
  // h half its sweep.
  const ApertureCell sector{0.5, 0.8, 0.3, 1.2};
  const ApertureCell::Rectangle r = sector.momentRectangle();
  const double h = 0.6, along = 2.0 / 3.0 * (0.512 - 0.125) / (0.64 - 0.25) * std::sin(h) / h;
  EXPECT_NEAR(r.centre.x, along * std::cos(0.9), 1e-3);
  EXPECT_NEAR(r.centre.y, along * std::sin(0.9), 1e-3);
  // 0.3 deep and about 0.78 wide at its middle radius: the long axis runs across the sector.
  EXPECT_GT(glm::length(r.axis0), glm::length(r.axis1));
  EXPECT_NEAR(std::abs(glm::dot(glm::normalize(r.axis0), glm::dvec2(std::cos(0.9), std::sin(0.9)))), 0.0, 1e-6);
  for (const int count : {4, 16, 64}) {
    const CellSamples cells = makeCellSamples(AperturePattern::Sobol, count, 5);
    for (const ApertureCell& c : cells.cells) {
      const ApertureCell::Rectangle m = c.momentRectangle();
      const double area = 4.0 * std::abs(m.axis0.x * m.axis1.y - m.axis0.y * m.axis1.x);
      EXPECT_NEAR(area, c.area(), 1e-9 * c.area()) << count << " cells";
      EXPECT_TRUE(c.contains(m.centre)) << count << " cells: the centroid of a box's image lies in it";
      EXPECT_NEAR(glm::dot(m.axis0, m.axis1), 0.0, 1e-12);
    }
  }
}

TEST(Cells, OnAShapedApertureTheMomentRectangleIsTheCellImages) {
  // The cell carried onto six blades, squeezed: the rectangle keeps the image's area (the map keeps
  // areas) and its centroid, against the mean of points spread uniformly over the cell and mapped.
  const ApertureShape shape{6, 20.0, 0.2, 1.5};
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const int count : {4, 16}) {
    const CellSamples cells = makeCellSamples(AperturePattern::Sobol, count, 5);
    for (const ApertureCell& c : cells.cells) {
      const ApertureCell::Rectangle m = c.momentRectangle(shape);
      const double area = 4.0 * std::abs(m.axis0.x * m.axis1.y - m.axis0.y * m.axis1.x);
      EXPECT_NEAR(area, c.area(), 1e-9 * c.area()) << count << " cells";
      glm::dvec2 mean(0.0);
      const int n = 20000;
      for (int i = 0; i < n; ++i) {
        const glm::dvec2 square = c.squareMin + glm::dvec2(u(rng), u(rng)) * (c.squareMax - c.squareMin);
        mean += apertureFromDisk(concentricDisk(square), shape) / double(n);
      }
      EXPECT_NEAR(glm::length(m.centre - mean), 0.0, 0.01) << count << " cells";
      EXPECT_TRUE(c.contains(diskFromAperture(m.centre, shape))) << count << " cells";
      // Not the disk's rectangle: the shape moved it.
      EXPECT_GT(glm::length(m.centre - c.momentRectangle().centre), 0.01);
    }
  }
}

TEST(Cells, OnlyRingsAndPowersOfTwoOfSobolHaveCells) {
  EXPECT_TRUE(hasCells(AperturePattern::Rings, 5));
  EXPECT_TRUE(hasCells(AperturePattern::Sobol, 64));
  EXPECT_FALSE(hasCells(AperturePattern::Sobol, 24));
  EXPECT_FALSE(hasCells(AperturePattern::Concentric, 16));
  EXPECT_THROW(makeCellSamples(AperturePattern::Sobol, 24, 1), std::logic_error);
}

}  // namespace
}  // namespace lenslab
