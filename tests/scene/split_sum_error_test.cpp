// The split sum against the integral it approximates (scene/EnvironmentIntegral.h): the Monte
// Carlo estimator checked in a white furnace, then the split sum held to a documented bound where
// it is meant to be good (a smooth environment, the view within 45° of the normal).
//
// The whole grid of docs/environment.md ("How far the split sum is from the true integral"), on
// studio.hdr and the smooth environment at the renderers' prefilter settings, is printed by
//   build/tests/lenslab_unit_tests --gtest_also_run_disabled_tests --gtest_filter='SplitSumError.DISABLED_Table'
#include "io/EnvironmentFile.h"
#include "scene/Brdf.h"
#include "scene/EnvironmentIntegral.h"
#include "scene/EnvironmentPrefilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace lenslab {
namespace {

// An equirectangular image of `radiance` at each texel's centre direction.
EnvironmentImage analyticEnvironment(int width, const std::function<glm::dvec3(const glm::dvec3&)>& radiance) {
  EnvironmentImage image{width, width / 2, std::vector<glm::vec3>(static_cast<std::size_t>(width) * (width / 2))};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec3 d = directionFromUv({(static_cast<float>(x) + 0.5f) / static_cast<float>(image.width),
                                           (static_cast<float>(y) + 0.5f) / static_cast<float>(image.height)});
      image.at(x, y) = glm::vec3(radiance(glm::dvec3(d)));
    }
  return image;
}

// Smooth: linear in the direction, a bluish sky brighter above and a warm side towards +X; every
// channel ≥ 0.2. Here the split sum's prefiltering loses nothing to detail, so what is left is
// the approximation itself (the lobe taken about the reflected direction, separated from F·V).
glm::dvec3 smoothSky(const glm::dvec3& d) {
  return glm::dvec3(1.0, 0.95, 0.9) + 0.6 * d.y * glm::dvec3(0.8, 0.9, 1.0) + 0.3 * d.x * glm::dvec3(1.0, 0.5, 0.0);
}

// The grid's normals: up, down, towards the image's centre, sideways, and two in between.
const glm::dvec3 kNormals[] = {
    {0.0, 1.0, 0.0},   {0.0, -1.0, 0.0}, {0.0, 0.0, -1.0}, {1.0, 0.0, 0.0}, {0.57735, 0.57735, 0.57735},
    {-0.32, -0.5, 0.8}};
const float kRoughness[] = {0.045f, 0.25f, 0.5f, 0.75f, 1.0f};
const float kMetallic[] = {0.0f, 1.0f};
const float kNv[] = {1.0f, 0.7f, 0.3f, 0.1f};

// A surface facing `normal`, seen at n·v = nv (v tilted from n within the plane of n and a
// tangent), with a coloured base so that a metal's F0 is coloured.
ShadingSurface surfaceAt(const glm::dvec3& normal, float nv, float roughness, float metallic) {
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 side = std::abs(n.y) > 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 t = glm::normalize(glm::cross(n, side));
  ShadingSurface s;
  s.baseColor = {0.9f, 0.75f, 0.6f};
  s.metallic = metallic;
  s.perceptualRoughness = roughness;
  s.n = glm::vec3(n);
  s.v = glm::vec3(glm::normalize(double(nv) * n + std::sqrt(std::max(0.0, 1.0 - double(nv) * nv)) * t));
  return s;
}

struct Comparison {
  double relativeError;     // (split sum − integral) / integral, in luminance
  double relativeStdError;  // the estimate's own standard error, the same way
};

Comparison compare(const EnvironmentLookup& lookup, const EnvironmentIntegral& integral, const ShadingSurface& s,
                   int samples, std::uint64_t seed) {
  const RadianceEstimate truth = integral.outgoingRadiance(s, samples, seed);
  const double split = luminance(glm::dvec3(splitSumRadiance(lookup, s)));
  const double mean = luminance(truth.mean);
  // The luminance's standard error is at most the weighted sum of the channels' (they correlate).
  return {(split - mean) / mean, luminance(truth.standardError) / mean};
}

// --- the estimator itself ---

// A constant environment L: a white metal reflects L·(A + B), its directional albedo, which
// dfgIntegral computes apart (its own quadrature over half vectors, no environment); at the
// smallest roughness the albedo is 1 within 0.2 %, the closed form L.
TEST(EnvironmentIntegral, WhiteFurnaceGivesTheDirectionalAlbedo) {
  const double L = 0.7;
  const EnvironmentIntegral integral(analyticEnvironment(16, [&](const glm::dvec3&) { return glm::dvec3(L); }));
  for (const float roughness : {0.045f, 0.5f, 1.0f})
    for (const float nv : {1.0f, 0.3f}) {
      ShadingSurface s = surfaceAt({0.3, 0.8, -0.5}, nv, roughness, 1.0f);
      s.baseColor = glm::vec3(1.0f);
      const RadianceEstimate e = integral.outgoingRadiance(s, 40000, 7);
      const float alpha = std::max(roughness, 0.045f) * std::max(roughness, 0.045f);
      const glm::vec2 ab = dfgIntegral(nv, alpha, 1 << 16);
      const double expected = L * (ab.x + ab.y);
      SCOPED_TRACE(testing::Message() << "roughness " << roughness << ", n·v " << nv);
      EXPECT_LT(e.standardError.g, 0.005 * L) << "the estimate's own noise";
      EXPECT_NEAR(e.mean.g, expected, 4.0 * e.standardError.g + 0.002 * L);
      if (roughness < 0.1f && nv == 1.0f) {
        EXPECT_NEAR(e.mean.g, L, 0.002 * L) << "a mirror returns L";
      }
    }
}

// The same furnace through the diffuse lobe: a dielectric under L returns
// L·(c_diff·(1 − ∫F(v·h) (n·l)/π dl) + F0·A + B); with F's (1 − v·h)⁵ term at most 1 − F0,
// the result lies between the two bounds below whatever the estimator's sampling.
TEST(EnvironmentIntegral, WhiteFurnaceDielectricWithinItsBounds) {
  const double L = 1.0;
  const EnvironmentIntegral integral(analyticEnvironment(16, [&](const glm::dvec3&) { return glm::dvec3(L); }));
  for (const float roughness : {0.25f, 1.0f}) {
    ShadingSurface s = surfaceAt({0.0, 1.0, 0.0}, 1.0f, roughness, 0.0f);
    s.baseColor = glm::vec3(1.0f);
    const RadianceEstimate e = integral.outgoingRadiance(s, 40000, 3);
    const glm::vec2 ab = dfgIntegral(1.0f, roughness * roughness, 1 << 16);
    const double specular = 0.04 * ab.x + ab.y;
    // Diffuse: c_diff ∫(1 − F)(n·l)/π with F between F0 and 1 over the hemisphere's v·h.
    EXPECT_GT(e.mean.g, specular + 0.0 - 4.0 * e.standardError.g) << roughness;
    EXPECT_LT(e.mean.g, specular + (1.0 - 0.04) + 4.0 * e.standardError.g) << roughness;
    // At n·v = 1 and v·h ≥ cos 45° over most of the lobe, F stays near F0: the diffuse takes
    // nearly 1 − F0.
    EXPECT_GT(e.mean.g, specular + 0.85) << roughness;
  }
}

// The environment strategy's density integrates to 1 over the sphere and follows the luminance.
TEST(EnvironmentIntegral, EnvironmentDensityIsNormalised) {
  const EnvironmentIntegral integral(analyticEnvironment(32, smoothSky));
  double sum = 0.0;
  const int rows = 200, columns = 400;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x) {
      const double cosTheta = 1.0 - 2.0 * (y + 0.5) / rows;
      const double phi = 2.0 * 3.14159265358979 * (x + 0.5) / columns;
      const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
      sum += integral.environmentPdf({sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)});
    }
  EXPECT_NEAR(sum * 4.0 * 3.14159265358979 / (rows * columns), 1.0, 0.01);
  EXPECT_GT(integral.environmentPdf({0.0, 0.99, 0.1}), integral.environmentPdf({0.0, -0.99, 0.1})) << "brighter above";
}

// --- the split sum ---

// The worst of a grid's comparisons.
struct Worst {
  double relativeError = 0.0;     // |relative error|
  double relativeStdError = 0.0;  // the estimates' own noise
};

// The split sum against the integral on the smooth environment at each normal × roughness ×
// metallic × n·v (seeds 1, 2, … in that order), metals only up to `metalRoughnessMax`, each
// held to |relative error| < `bound`. The prefiltered maps are smaller than the renderers' (64
// columns, not 256), which on a linear environment changes the lookups by far less than the
// bounds, and keeps these tests fast.
Worst smoothSkyGrid(std::initializer_list<float> metallics, float metalRoughnessMax, std::initializer_list<float> nvs,
                    int samples, double bound) {
  const EnvironmentImage sky = analyticEnvironment(64, smoothSky);
  PrefilterSettings settings;
  settings.diffuseWidth = 32;
  settings.diffuseSourceWidth = 64;
  settings.specularWidth = 64;
  const EnvironmentLookup lookup(std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(sky, settings)),
                                 {});
  const EnvironmentIntegral integral(sky);
  Worst worst;
  std::uint64_t seed = 1;
  for (const glm::dvec3& n : kNormals)
    for (const float roughness : kRoughness)
      for (const float metallic : metallics)
        for (const float nv : nvs) {
          if (metallic > 0.0f && roughness > metalRoughnessMax) continue;
          const Comparison c = compare(lookup, integral, surfaceAt(n, nv, roughness, metallic), samples, seed++);
          EXPECT_LT(std::abs(c.relativeError), bound) << "n (" << n.x << ", " << n.y << ", " << n.z << "), roughness "
                                                      << roughness << ", metallic " << metallic << ", n·v " << nv;
          worst.relativeError = std::max(worst.relativeError, std::abs(c.relativeError));
          worst.relativeStdError = std::max(worst.relativeStdError, c.relativeStdError);
        }
  return worst;
}

// The renderers' split sum against the integral on the smooth environment where it is meant to be
// good: the view within about 45° of the normal (n·v ≥ 0.7), dielectrics of every roughness and
// metals up to roughness 0.25, six normals: within 2 % (docs/environment.md's table shows at most
// 0.7 % there). Rougher metals are outside this bound (the table).
TEST(SplitSumError, SmallOnASmoothEnvironmentAwayFromGrazing) {
  const Worst worst = smoothSkyGrid({0.0f, 1.0f}, 0.25f, {1.0f, 0.7f}, 48000, 0.02);
  EXPECT_LT(worst.relativeStdError, 0.01) << "the integral's own noise is well below the bound";
  std::printf(
      "split sum on the smooth environment, n·v ≥ 0.7: worst |relative error| %.4f, worst estimate noise %.5f\n",
      worst.relativeError, worst.relativeStdError);
}

// Dielectrics at grazing views (n·v 0.3 and 0.1) on the smooth environment: the image light's
// diffuse is the integral of the glTF diffuse lobe (1 − F(v·h)) c_diff/π, as the punctual lights
// have it, so these stay close too (docs/environment.md's table: within 2.3 %; a diffuse weighted by
// 1 − E(n·v) instead is 13 % and 35 % too dark here). Bound 5 %: smaller maps, as above.
TEST(SplitSumError, DielectricsCloseAtGrazingViewsOnASmoothEnvironment) {
  const Worst worst = smoothSkyGrid({0.0f}, 0.0f, {0.3f, 0.1f}, 24000, 0.05);
  std::printf("split sum on the smooth environment, dielectrics at n·v ≤ 0.3: worst |relative error| %.4f\n",
              worst.relativeError);
}

// --- the table (docs/environment.md) ---

struct GridRow {
  std::string environment;
  float metallic, roughness, nv;
  int normal;
  Comparison c;
};

std::vector<GridRow> grid(const std::string& name, const EnvironmentLookup& lookup, const EnvironmentImage& source,
                          int samples) {
  const EnvironmentIntegral integral(source);
  std::vector<GridRow> rows;
  std::uint64_t seed = 1;
  for (const float metallic : kMetallic)
    for (const float roughness : kRoughness)
      for (const float nv : kNv)
        for (int k = 0; k < static_cast<int>(std::size(kNormals)); ++k)
          rows.push_back({name, metallic, roughness, nv, k,
                          compare(lookup, integral, surfaceAt(kNormals[k], nv, roughness, metallic), samples, seed++)});
  return rows;
}

void printSummary(const std::vector<GridRow>& rows, const std::string& name) {
  std::printf(
      "\n%s: relative error of the split sum, the largest over the six normals (signed) and in brackets the "
      "median |error|, in %%\n\n",
      name.c_str());
  std::printf("| metallic | roughness | n·v 1 | n·v 0.7 | n·v 0.3 | n·v 0.1 |\n|---|---|---|---|---|---|\n");
  for (const float metallic : kMetallic)
    for (const float roughness : kRoughness) {
      std::printf("| %g | %g |", metallic, roughness);
      for (const float nv : kNv) {
        double worst = 0.0;
        std::vector<double> magnitudes;
        for (const GridRow& r : rows)
          if (r.metallic == metallic && r.roughness == roughness && r.nv == nv) {
            if (std::abs(r.c.relativeError) > std::abs(worst)) worst = r.c.relativeError;
            magnitudes.push_back(std::abs(r.c.relativeError));
          }
        std::sort(magnitudes.begin(), magnitudes.end());
        const double median = 0.5 * (magnitudes[(magnitudes.size() - 1) / 2] + magnitudes[magnitudes.size() / 2]);
        std::printf(" %+.1f (%.1f) |", 100.0 * worst, 100.0 * median);
      }
      std::printf("\n");
    }
}

TEST(SplitSumError, DISABLED_Table) {
  const int samples = 1 << 20;
  const std::string studioPath = std::string(LENSLAB_UNIT_ASSET_DIR) + "/environments/studio.hdr";
  // The renderers' own maps: the same settings and cache as --environment.
  const LoadedEnvironment studio = loadEnvironment(studioPath, PrefilterSettings{}, environmentCacheFolder());
  const EnvironmentImage sky = analyticEnvironment(256, smoothSky);
  const auto skyMaps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(sky, PrefilterSettings{}));
  std::vector<GridRow> rows = grid("smooth", EnvironmentLookup(skyMaps, {}), sky, samples);
  const std::vector<GridRow> studioRows =
      grid("studio.hdr", EnvironmentLookup(studio.maps, {}), studio.maps->background, samples);
  rows.insert(rows.end(), studioRows.begin(), studioRows.end());
  std::printf("environment,metallic,roughness,n_dot_v,normal_x,normal_y,normal_z,relative_error,relative_std_error\n");
  double worstNoise = 0.0;
  for (const GridRow& r : rows) {
    const glm::dvec3& n = kNormals[r.normal];
    std::printf("%s,%g,%g,%g,%g,%g,%g,%.5f,%.5f\n", r.environment.c_str(), r.metallic, r.roughness, r.nv, n.x, n.y, n.z,
                r.c.relativeError, r.c.relativeStdError);
    worstNoise = std::max(worstNoise, r.c.relativeStdError);
  }
  printSummary(std::vector<GridRow>(rows.begin(), rows.end() - static_cast<std::ptrdiff_t>(studioRows.size())),
               "smooth environment (256 × 128)");
  printSummary(studioRows, "studio.hdr (1024 × 512)");
  std::printf("\nthe integral's own noise: at most %.3f %% (relative standard error, %d samples a case)\n",
              100.0 * worstNoise, samples);
}

}  // namespace
}  // namespace lenslab
