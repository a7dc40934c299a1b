// brdf.glsl as C++ (scene/Brdf.h) against closed forms: energy under uniform light, the punctual
// lights' units and falloffs, the DFG table against its integral and against the BRDF itself.
#include "camera/ProjectionCentre.h"
#include "camera/Projection.h"
#include "scene/Brdf.h"
#include "scene/ShadingLights.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lenslab {
namespace {

constexpr double kPi = 3.14159265358979323846;

ShadingSurface surface(glm::vec3 base, float metallic, float roughness, glm::vec3 n = {0, 0, 1},
                       glm::vec3 v = {0, 0, 1}) {
  ShadingSurface s;
  s.baseColor = base;
  s.metallic = metallic;
  s.perceptualRoughness = roughness;
  s.n = n;
  s.v = v;
  return s;
}

ShadingLight directional(glm::vec3 shines, float lux) {
  ShadingLight l;
  l.type = 0;
  l.direction = glm::normalize(shines);
  l.intensity = glm::vec3(lux);
  return l;
}

ShadingLight point(glm::vec3 position, float candela, float range = 0.0f) {
  ShadingLight l;
  l.type = 1;
  l.position = position;
  l.intensity = glm::vec3(candela);
  l.range = range;
  return l;
}

// Radiance reflected toward s.v under uniform radiance 1 from the whole sky, by quadrature of the
// punctual term over the hemisphere (each cell a directional light of illuminance dω facing it).
double furnaceByQuadrature(const ShadingSurface& s, int steps) {
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double theta = (i + 0.5) / steps * 0.5 * kPi;
    for (int j = 0; j < 2 * steps; ++j) {
      const double phi = (j + 0.5) / (2 * steps) * 2.0 * kPi;
      const glm::vec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const double dOmega = std::sin(theta) * (0.5 * kPi / steps) * (kPi / steps);
      sum += punctualRadiance(s, directional(-l, static_cast<float>(dOmega)), glm::vec3(0.0f)).g;
    }
  }
  return sum;
}

glm::vec3 unitAt(float nv) { return {std::sqrt(1.0f - nv * nv), 0.0f, nv}; }

TEST(Brdf, WhiteMetalUnderUniformLightReflectsAtMostOneAndAlmostAllWhenSmooth) {
  for (float roughness : {0.0f, 0.05f, 0.1f, 0.3f, 0.6f, 1.0f})
    for (float nv : {0.05f, 0.2f, 0.5f, 0.8f, 1.0f}) {
      const ShadingSurface s = surface(glm::vec3(1.0f), 1.0f, roughness, {0, 0, 1}, unitAt(nv));
      const float reflected = imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(1.0f), dfgLookup(nv, roughness)).g;
      EXPECT_LE(reflected, 1.0f + 1e-4f) << "roughness " << roughness << " n.v " << nv;
      EXPECT_GT(reflected, 0.0f);
      if (roughness <= 0.1f && nv >= 0.2f) {
        EXPECT_GE(reflected, 0.97f) << "roughness " << roughness << " n.v " << nv;
      }
    }
}

// Under uniform radiance 1 the image light returns what the punctual term integrated over the
// hemisphere returns, lobe by lobe: not 1, since glTF's BRDF is not energy-conserving (its diffuse
// (1 − F(v·h)) c_diff / π keeps ≈ 0.97 of the light at every view while the specular lobe adds
// F0·A + B on top, and the single-scattering GGX lobe loses light when rough).
TEST(Brdf, WhiteDielectricUnderUniformLightReflectsWhatItsBrdfIntegratesTo) {
  for (float roughness : {0.1f, 0.5f, 1.0f})
    for (float nv : {0.1f, 0.3f, 0.5f, 1.0f}) {
      const ShadingSurface s = surface(glm::vec3(1.0f), 0.0f, roughness, {0, 0, 1}, unitAt(nv));
      const ShadingSurface black = surface(glm::vec3(0.0f), 0.0f, roughness, {0, 0, 1}, unitAt(nv));
      // The diffuse lobe alone: the same surface less its specular (a black dielectric's), both
      // by quadrature; and the image light with no specular radiance.
      const double all = furnaceByQuadrature(s, 256);
      const double specular = furnaceByQuadrature(black, 256);
      const float diffuse = imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(0.0f), dfgLookup(nv, roughness)).g;
      EXPECT_NEAR(diffuse, all - specular, 0.005) << "roughness " << roughness << " n.v " << nv;
      EXPECT_LE(all - specular, 1.0 - 0.04 + 1e-3) << "the diffuse keeps at most 1 − F0";
      const glm::vec3 dfg = dfgLookup(nv, roughness);
      if (roughness >= 0.3f) {
        EXPECT_NEAR(specular, 0.04 * dfg.x + dfg.y, 0.01) << "roughness " << roughness << " n.v " << nv;
      }
    }
}

// The table (importance-sampled, interpolated) against the BRDF it stands for, integrated by
// quadrature through punctualRadiance: a white metal's albedo and a white dielectric's specular
// plus diffuse. Rough enough for the quadrature.
TEST(Brdf, DfgTableMatchesTheBrdfItSummarises) {
  for (float metallic : {1.0f, 0.0f})
    for (float roughness : {0.3f, 0.5f, 0.8f, 1.0f})
      for (float nv : {0.15f, 0.5f, 0.9f}) {
        const ShadingSurface s = surface(glm::vec3(1.0f), metallic, roughness, {0, 0, 1}, unitAt(nv));
        const double table = imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(1.0f), dfgLookup(nv, roughness)).g;
        EXPECT_NEAR(table, furnaceByQuadrature(s, 384), 0.02)
            << "metallic " << metallic << " roughness " << roughness << " n.v " << nv;
      }
  // And the interpolation between texel centres against the integral itself.
  for (float roughness : {0.2f, 0.45f, 0.77f})
    for (float nv : {0.3f, 0.62f, 0.95f}) {
      const glm::vec2 direct = dfgIntegral(nv, roughness * roughness, 8192);
      const glm::vec3 looked = dfgLookup(nv, roughness);
      EXPECT_NEAR(looked.x, direct.x, 0.01f) << roughness << " " << nv;
      EXPECT_NEAR(looked.y, direct.y, 0.01f) << roughness << " " << nv;
    }
}

// The table's texels lie on the domain's edges, so the ends of each axis read their own integral:
// n·v 1 and roughness 1 are not the clamped texel centre 31.5/32 (which gave F0 0.75 a 6 % larger
// albedo at roughness 1, n·v 1). Bound 0.5 %: the integral's own sampling noise is far below.
TEST(Brdf, DfgTableReachesTheEdgesOfItsDomain) {
  for (float roughness : {0.045f, 0.5f, 1.0f})
    for (float nv : {0.3f, 0.7f, 1.0f}) {
      const glm::vec2 direct = dfgIntegral(nv, roughness * roughness, 8192);
      const glm::vec3 looked = dfgLookup(nv, roughness);
      const float albedoDirect = 0.75f * direct.x + direct.y, albedoLooked = 0.75f * looked.x + looked.y;
      EXPECT_NEAR(albedoLooked / albedoDirect, 1.0f, 0.005f) << "roughness " << roughness << " n.v " << nv;
    }
}

// The table is baked into the source (src/scene/DfgTableValues.inc). Each texel must still be the
// integral it stands for, with the BRDF as it is now: after a change to brdf.glsl's visibility or
// Fresnel this fails until tools/update-dfg-table.sh is run. (1e-6: libm's last bits may differ
// between CPUs; a change to the BRDF moves the integral by far more.) A spread of texels, not all
// (each costs about 2 ms, mostly K): every 7th in row order, which as 7 and the row length share
// no factor falls on every row and every column, and every texel of the four edges, where the
// domain's limits are (n·v at kDfgMinNv and 1, roughness 0 and 1). A change to the BRDF moves
// nearly every texel.
TEST(DfgTable, BakedValuesAreTheIntegralTheyStandFor) {
  const std::vector<glm::vec3>& baked = dfgTable();
  ASSERT_EQ(baked.size(), static_cast<std::size_t>(kDfgTableSize * kDfgTableSize));
  const int last = kDfgTableSize - 1;
  double worst = 0.0;
  int checked = 0;
  for (int y = 0; y < kDfgTableSize; ++y)
    for (int x = 0; x < kDfgTableSize; ++x) {
      const bool edge = x == 0 || y == 0 || x == last || y == last;
      if (!edge && (y * kDfgTableSize + x) % 7 != 0) continue;
      ++checked;
      const glm::vec3 integral = dfgTexelIntegral(x, y);
      const glm::vec3 value = baked[static_cast<std::size_t>(y * kDfgTableSize + x)];
      worst = std::max({worst, double(std::abs(value.x - integral.x)), double(std::abs(value.y - integral.y)),
                        double(std::abs(value.z - integral.z))});
      ASSERT_NEAR(value.x, integral.x, 1e-6) << "texel (" << x << ", " << y << "): run tools/update-dfg-table.sh";
      ASSERT_NEAR(value.y, integral.y, 1e-6) << "texel (" << x << ", " << y << "): run tools/update-dfg-table.sh";
      ASSERT_NEAR(value.z, integral.z, 1e-6) << "texel (" << x << ", " << y << "): run tools/update-dfg-table.sh";
    }
  std::printf("baked DFG table vs its integral at %d texels: worst difference %.2g\n", checked, worst);
}

// Appendix B's closed form, computed here in double, independently of brdf.glsl.
double closedForm(double base, double metallic, double roughness, glm::dvec3 n, glm::dvec3 v, glm::dvec3 l,
                  double illuminance) {
  const double nl = glm::dot(n, l), nv = glm::dot(n, v);
  if (nl <= 0.0) return 0.0;
  const glm::dvec3 h = glm::normalize(l + v);
  const double a = roughness * roughness, a2 = a * a, nh = glm::dot(n, h), vh = glm::dot(v, h);
  const double f0 = 0.04 * (1.0 - metallic) + base * metallic;
  const double f = f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0);
  const double d = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
  const double vis = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
  return ((1.0 - f) * base * (1.0 - metallic) / kPi + f * d * vis) * illuminance * nl;
}

TEST(Brdf, DirectionalLightInLuxOnATiltedPlane) {
  const glm::vec3 v = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
  for (double tiltDeg : {0.0, 20.0, 45.0, 70.0, 89.0, 95.0})
    for (float metallic : {0.0f, 1.0f}) {
      const double t = tiltDeg * kPi / 180.0;
      const glm::dvec3 n(std::sin(t), 0.0, std::cos(t));  // the plane tilted away from the light
      const ShadingSurface s = surface(glm::vec3(0.7f), metallic, 0.5f, glm::vec3(n), v);
      const float got = punctualRadiance(s, directional({0, 0, -1}, 1000.0f), glm::vec3(5.0f)).g;
      const double expected = closedForm(0.7, metallic, 0.5, n, glm::dvec3(v), {0, 0, 1}, 1000.0);
      EXPECT_NEAR(got, expected, 1e-5 * 1000.0) << "tilt " << tiltDeg;
      if (tiltDeg > 90.0) {
        EXPECT_EQ(got, 0.0f);
      }
    }
}

TEST(Brdf, PointLightFallsOffWithTheInverseSquareAndTheRangeWindow) {
  const ShadingSurface s = surface(glm::vec3(0.8f), 0.0f, 1.0f);
  const float at1 = punctualRadiance(s, point({0, 0, 1}, 100.0f), glm::vec3(0.0f)).g;
  EXPECT_NEAR(at1, closedForm(0.8, 0.0, 1.0, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 100.0), 1e-4);
  for (float d : {0.5f, 2.0f, 10.0f, 1000.0f})
    EXPECT_NEAR(punctualRadiance(s, point({0, 0, d}, 100.0f), glm::vec3(0.0f)).g * d * d / at1, 1.0f, 1e-5f) << d;
  // Range: the extension's window clamp(1 − (d/range)⁴, 0, 1).
  EXPECT_NEAR(punctualRadiance(s, point({0, 0, 1}, 100.0f, 2.0f), glm::vec3(0.0f)).g / at1, 1.0f - 1.0f / 16.0f, 1e-5f);
  EXPECT_EQ(punctualRadiance(s, point({0, 0, 2}, 100.0f, 2.0f), glm::vec3(0.0f)).g, 0.0f);
  EXPECT_EQ(punctualRadiance(s, point({0, 0, 3}, 100.0f, 2.0f), glm::vec3(0.0f)).g, 0.0f);
  // A light at the point itself, or behind the surface, gives nothing (and no NaN).
  EXPECT_EQ(punctualRadiance(s, point({0, 0, 0}, 100.0f), glm::vec3(0.0f)), glm::vec3(0.0f));
  EXPECT_EQ(punctualRadiance(s, point({0, 0, -1}, 100.0f), glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(Brdf, SpotConeIsFullInsideTheInnerAngleAndZeroOutsideTheOuter) {
  const ShadingSurface s = surface(glm::vec3(0.8f), 0.0f, 1.0f);
  const float inner = 0.2f, outer = 0.5f;
  const glm::vec2 cone = spotScaleOffset(inner, outer);
  const auto seenAt = [&](float offAxis) {  // the spot 1 above the point, turned offAxis from it
    ShadingLight l = point({0, 0, 1}, 100.0f);
    l.type = 2;
    l.direction = glm::vec3(std::sin(offAxis), 0.0f, -std::cos(offAxis));
    l.spotScale = cone.x;
    l.spotOffset = cone.y;
    return punctualRadiance(s, l, glm::vec3(0.0f)).g;
  };
  const float full = punctualRadiance(s, point({0, 0, 1}, 100.0f), glm::vec3(0.0f)).g;
  EXPECT_NEAR(seenAt(0.0f), full, 1e-5f * full);
  EXPECT_NEAR(seenAt(inner - 1e-3f), full, 1e-5f * full);
  EXPECT_LT(seenAt(inner + 0.05f), full);
  EXPECT_GT(seenAt(outer - 0.05f), 0.0f);
  EXPECT_EQ(seenAt(outer + 1e-3f), 0.0f);
  // Halfway in cosine: (½)² of the full light.
  const float half = std::acos(0.5f * (std::cos(inner) + std::cos(outer)));
  EXPECT_NEAR(seenAt(half) / full, 0.25f, 1e-3f);
}

TEST(Brdf, NoNanAtSilhouettesOrDegenerateVectors) {
  const ShadingLight lights[] = {directional({0, 0, -1}, 10.0f), point({0, 0, 1}, 10.0f),
                                 directional({0, 0, 1}, 10.0f)};
  for (float roughness : {0.0f, 0.5f, 1.0f})
    for (const glm::vec3 v : {glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0.0f)})
      for (const ShadingLight& l : lights) {
        const ShadingSurface s = surface(glm::vec3(1.0f), 0.5f, roughness, {0, 0, 1}, v);
        const glm::vec3 c =
            punctualRadiance(s, l, glm::vec3(0.0f)) +
            imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(1.0f), dfgLookup(glm::dot(s.n, s.v), roughness));
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k])) << roughness;
      }
  // v = −l exactly (no half vector).
  const ShadingSurface s = surface(glm::vec3(1.0f), 0.0f, 0.5f, {0, 0, 1}, glm::normalize(glm::vec3(1, 0, -1)));
  EXPECT_TRUE(
      std::isfinite(punctualRadiance(s, directional(glm::normalize(glm::vec3(1, 0, -1)), 1.0f), glm::vec3(0.0f)).g));
}

// The specular dominant direction: unit, the reflected direction for a near-mirror, the normal at
// roughness 1, and in between (in the plane of n and v, leaning from r toward n) as roughness grows.
TEST(Brdf, SpecularDominantDirectionLeansFromTheReflectionTowardTheNormal) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  for (float nv : {0.1f, 0.5f, 0.9f}) {
    const glm::vec3 v = unitAt(nv);
    const glm::vec3 r = glm::reflect(-v, n);
    EXPECT_NEAR(glm::dot(specularDominantDirection(n, v, 0.0f), r), 1.0f, 1e-4f) << nv;
    EXPECT_NEAR(glm::dot(specularDominantDirection(n, v, 1.0f), n), 1.0f, 1e-6f) << nv;
    float previous = glm::dot(r, n);
    for (float roughness : {0.25f, 0.5f, 0.75f}) {
      const glm::vec3 d = specularDominantDirection(n, v, roughness);
      EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
      EXPECT_NEAR(d.y, 0.0f, 1e-6f) << "in the plane of n and v";
      EXPECT_GT(glm::dot(d, n), previous) << "rougher leans further toward n";
      previous = glm::dot(d, n);
    }
  }
}

TEST(Brdf, OcclusionDimsTheSurroundOnly) {
  ShadingSurface s = surface(glm::vec3(0.5f), 0.0f, 0.5f);
  const glm::vec3 dfg = dfgLookup(1.0f, 0.5f);
  const float open = imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(1.0f), dfg).g;
  const float lit = punctualRadiance(s, directional({0, 0, -1}, 3.0f), glm::vec3(0.0f)).g;
  s.occlusion = 0.25f;
  EXPECT_NEAR(imageLightRadiance(s, glm::vec3(1.0f), glm::vec3(1.0f), dfg).g, 0.25f * open, 1e-6f);
  EXPECT_EQ(punctualRadiance(s, directional({0, 0, -1}, 3.0f), glm::vec3(0.0f)).g, lit);
}

// The default light keeps the former look: a white Lambert surface facing it, its diffuse part,
// reflects lighting.diffuse.
TEST(ShadingLights, TheDefaultLightGivesAWhiteLambertSurfaceTheFormerDiffuse) {
  Scene scene;
  const std::vector<ShadingLight> lights = shadingLights(scene, glm::dvec3(1e7, 0.0, 0.0));
  ASSERT_EQ(lights.size(), 1u);
  EXPECT_NEAR(lights[0].intensity.g / kPi, scene.lighting.diffuse, 1e-6);
  EXPECT_NEAR(glm::dot(-lights[0].direction, scene.lighting.toLight), 1.0f, 1e-6f);
  PunctualLight far;
  far.worldPosition = glm::dvec3(1e7 + 1.5, 2.0, 0.0);
  scene.lights.push_back(far);
  const std::vector<ShadingLight> placed = shadingLights(scene, glm::dvec3(1e7, 0.0, 0.0));
  ASSERT_EQ(placed.size(), 1u) << "the file's lights replace the default one";
  EXPECT_EQ(placed[0].position, glm::vec3(1.5f, 2.0f, 0.0f)) << "relative to the origin, in double first";
}

TEST(ProjectionCentre, IsTheEyeOfAPerspectiveViewAndADirectionForAParallelOne) {
  const glm::dvec3 eye(1e6 + 0.25, -3.0, 7.5);
  const glm::dmat4 viewFromWorld = glm::lookAt(eye, eye + glm::dvec3(0.2, 0.1, -1.0), glm::dvec3(0, 1, 0));
  const glm::dmat4 perspective = glm::frustum(-0.1, 0.13, -0.07, 0.08, 0.05, 100.0) * viewFromWorld;
  const ProjectionCentre c = projectionCentre(perspective);
  EXPECT_FALSE(c.atInfinity);
  EXPECT_NEAR(glm::length(c.point - eye), 0.0, 1e-6);
  // lenslab's clip space is reverse-Z (z / w grows toward the viewer): GL's convention flipped.
  const glm::dmat4 reverseZ(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, -1, 0),
                            glm::dvec4(0, 0, 0, 1));
  const glm::dmat4 parallel = reverseZ * glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 10.0) * viewFromWorld;
  const ProjectionCentre p = projectionCentre(parallel);
  EXPECT_TRUE(p.atInfinity);
  EXPECT_NEAR(glm::dot(p.towardViewer, -glm::normalize(glm::dvec3(0.2, 0.1, -1.0))), 1.0, 1e-9);
}

}  // namespace
}  // namespace lenslab
