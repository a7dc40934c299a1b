// KHR_texture_transform's matrix and the shared texture-coordinate and normal-map functions
// (shaders/common/material_maps.glsl compiled as C++) against their closed forms.
#include "scene/MaterialMaps.h"
#include "scene/TextureTransform.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>

namespace lenslab {
namespace {

TEST(UvFromTexCoord, ComposesOffsetRotationAndScaleAsTheExtensionSays) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> any(-3.0f, 3.0f);
  for (int i = 0; i < 100; ++i) {
    const glm::vec2 offset(any(random), any(random)), scale(any(random), any(random)), uv(any(random), any(random));
    const float rotation = any(random);
    const glm::vec3 mapped = uvFromTexCoord(offset, rotation, scale) * glm::vec3(uv, 1.0f);
    // The extension's README: translation · rotation · scale, rotation = mat3(cos, −sin, 0, sin, cos, 0, 0, 0, 1).
    const float su = scale.x * uv.x, sv = scale.y * uv.y, c = std::cos(rotation), s = std::sin(rotation);
    EXPECT_NEAR(mapped.x, c * su + s * sv + offset.x, 1e-5f);
    EXPECT_NEAR(mapped.y, -s * su + c * sv + offset.y, 1e-5f);
    EXPECT_NEAR(mapped.z, 1.0f, 1e-6f);
  }
  EXPECT_EQ(uvFromTexCoord(glm::vec2(0.0f), 0.0f, glm::vec2(1.0f)), glm::mat3(1.0f));
  // A step (a derivative) moves without the offset.
  const glm::mat3 m = uvFromTexCoord({5.0f, 7.0f}, 0.0f, {2.0f, 0.5f});
  EXPECT_EQ(uvStepFromTexCoordStep(m, {1.0f, 1.0f}), glm::vec2(2.0f, 0.5f));
}

TEST(SlotUv, PicksTheSetAndAppliesTheTransform) {
  const glm::mat3 shift = uvFromTexCoord({0.25f, 0.5f}, 0.0f, glm::vec2(1.0f));
  EXPECT_EQ(slotUv({0.1f, 0.2f}, {0.7f, 0.9f}, 0, glm::mat3(1.0f)), glm::vec2(0.1f, 0.2f));
  EXPECT_EQ(slotUv({0.1f, 0.2f}, {0.5f, 0.25f}, 1, shift), glm::vec2(0.75f, 0.75f));
}

// The texel of a tangent-space normal m (−1…1) as an 8-bit-free float texel (0…1).
glm::vec3 texelOf(glm::vec3 m) { return 0.5f * (m + glm::vec3(1.0f)); }

TEST(MappedNormal, IsTheTangentFrameTimesTheMapsNormal) {
  const glm::vec3 n(0, 0, 1), t(1, 0, 0);
  EXPECT_NEAR(glm::length(mappedNormal(n, t, 1.0f, texelOf({0, 0, 1}), 1.0f) - n), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(mappedNormal(n, t, 1.0f, texelOf({1, 0, 0}), 1.0f) - t), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(mappedNormal(n, t, 1.0f, texelOf({0, 1, 0}), 1.0f) - glm::vec3(0, 1, 0)), 0.0f,
              1e-6f);  // b = cross(n, t)
  EXPECT_NEAR(glm::length(mappedNormal(n, t, -1.0f, texelOf({0, 1, 0}), 1.0f) - glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
  // Random frames and texels: the result is normalize(t·m.x + b·m.y + n·m.z) with the scale on x, y.
  std::mt19937 random(3);
  std::uniform_real_distribution<float> any(-1.0f, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 normal = glm::normalize(glm::vec3(any(random), any(random), any(random)));
    const glm::vec3 tangent = glm::normalize(glm::cross(normal, glm::vec3(any(random), any(random), any(random))));
    const glm::vec3 m(any(random), any(random), 0.5f + 0.5f * std::abs(any(random)));
    const float scale = 2.0f * std::abs(any(random)), w = any(random) < 0.0f ? -1.0f : 1.0f;
    const glm::vec3 scaled = glm::normalize(glm::vec3(m.x * scale, m.y * scale, m.z));
    const glm::vec3 expected =
        glm::normalize(tangent * scaled.x + w * glm::cross(normal, tangent) * scaled.y + normal * scaled.z);
    const glm::vec3 got = mappedNormal(3.0f * normal, 0.5f * tangent, w, texelOf(m), scale);  // lengths do not matter
    EXPECT_NEAR(glm::length(got - expected), 0.0f, 1e-5f);
  }
}

TEST(MappedNormal, DegenerateInputsLeaveTheGeometricNormalNeverNaN) {
  const glm::vec3 n(0, 0.6f, 0.8f);
  for (const glm::vec3 tangent : {glm::vec3(0.0f), n, glm::vec3(1e-30f, 0, 0)}) {
    const glm::vec3 got = mappedNormal(n, tangent, 1.0f, texelOf({0.3f, 0.2f, 0.9f}), 1.0f);
    EXPECT_NEAR(glm::length(got - n), 0.0f, 1e-6f);
  }
  // A texel of (0.5, 0.5, 0.5) maps to the zero vector: no direction, the geometric normal.
  EXPECT_NEAR(glm::length(mappedNormal(n, {1, 0, 0}, 1.0f, glm::vec3(0.5f), 1.0f) - n), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace lenslab
