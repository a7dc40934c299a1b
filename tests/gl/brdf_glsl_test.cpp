// brdf.glsl is one definition compiled twice: as GLSL by the GPU driver, and as C++ by the
// compiler (scene/Brdf.cpp). The two agree on random inputs: a full-screen pass evaluates the
// GLSL per pixel into a float framebuffer, one random case per pixel, and each pixel is compared
// with the C++ result for the same case.
#include "gl/FullScreenPass.h"
#include "gl/Framebuffer.h"
#include "gl/Shader.h"
#include "../common/gl_test_context.h"
#include "../common/shader_dir_override.h"
#include "scene/Brdf.h"

#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

constexpr int kWidth = 64, kHeight = 64;  // 4096 cases, over 1000 of them lit by their punctual light
constexpr int kFloatsPerCase = 32;

// The probe: reads case i from a storage buffer and writes the punctual term (mode 0) or the
// image-light term with brdf.glsl's dfgLookup (mode 1) or with the filtered lookup scene.frag
// uses (mode 2, dfg_filtered.glsl).
const char* kProbe = R"(#version 450 core
layout(std430, binding = 0) readonly buffer Cases { float data[]; };
layout(binding = 9) uniform sampler2D dfgTable;
layout(location = 0) uniform int mode;
out vec4 outColor;
vec3 dfgTexel(int x, int y) { return texelFetch(dfgTable, ivec2(x, y), 0).rgb; }
#include "../common/brdf.glsl"
#include "../common/dfg_filtered.glsl"
vec3 at3(int i) { return vec3(data[i], data[i + 1], data[i + 2]); }
void main() {
  int k = (int(gl_FragCoord.y) * 64 + int(gl_FragCoord.x)) * 32;  // kWidth, kFloatsPerCase
  Surface s;
  s.baseColor = at3(k);
  s.metallic = data[k + 3];
  s.perceptualRoughness = data[k + 4];
  s.occlusion = data[k + 5];
  s.n = at3(k + 6);
  s.v = at3(k + 9);
  Light l;
  l.type = int(data[k + 15]);
  l.intensity = at3(k + 16);
  l.position = at3(k + 19);
  l.direction = at3(k + 22);
  l.range = data[k + 25];
  l.spotScale = data[k + 26];
  l.spotOffset = data[k + 27];
  vec3 dfg = mode == 1 ? dfgLookup(dot(s.n, s.v), s.perceptualRoughness) : dfgFiltered(dot(s.n, s.v), s.perceptualRoughness);
  vec3 c = mode == 0 ? punctualRadiance(s, l, at3(k + 12)) : imageLightRadiance(s, at3(k + 28), vec3(data[k + 31]), dfg);
  outColor = vec4(c, 1.0);
}
)";

struct Case {
  ShadingSurface surface;
  ShadingLight light;
  glm::vec3 p{0.0f};
  glm::vec3 diffuseRadiance{0.0f};
  float specularRadiance = 0.0f;
};

std::vector<Case> randomCases(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto unit = [&] {
    while (true) {
      const glm::vec3 d(2.0f * u(rng) - 1.0f, 2.0f * u(rng) - 1.0f, 2.0f * u(rng) - 1.0f);
      const float len = glm::length(d);
      if (len > 0.1f && len <= 1.0f) return d / len;
    }
  };
  const auto in = [&](float lo, float hi) { return lo + (hi - lo) * u(rng); };
  std::vector<Case> cases(kWidth * kHeight);
  for (Case& c : cases) {
    c.surface.baseColor = {u(rng), u(rng), u(rng)};
    c.surface.metallic = u(rng);
    c.surface.perceptualRoughness = u(rng);
    c.surface.occlusion = u(rng);
    c.surface.n = unit();
    c.surface.v = unit();
    if (u(rng) < 0.8f && glm::dot(c.surface.n, c.surface.v) < 0.0f)
      c.surface.v = -c.surface.v;  // mostly in front, some silhouettes
    c.p = {in(-1, 1), in(-1, 1), in(-1, 1)};
    c.light.type = std::min(2, static_cast<int>(3.0f * u(rng)));
    c.light.intensity = {in(0, 100), in(0, 100), in(0, 100)};
    c.light.position = {in(-3, 3), in(-3, 3), in(-3, 3)};
    c.light.direction = unit();
    c.light.range = u(rng) < 0.5f ? 0.0f : in(1, 6);
    const float outer = in(0.05f, 1.5f);
    const glm::vec2 cone = spotScaleOffset(in(0.0f, 0.99f) * outer, outer);
    c.light.spotScale = cone.x;
    c.light.spotOffset = cone.y;
    c.diffuseRadiance = {in(0, 4), in(0, 4), in(0, 4)};
    c.specularRadiance = in(0, 4);
  }
  return cases;
}

std::vector<float> packed(const std::vector<Case>& cases) {
  std::vector<float> data;
  for (const Case& c : cases) {
    const ShadingSurface& s = c.surface;
    const ShadingLight& l = c.light;
    const float values[kFloatsPerCase] = {s.baseColor.r,
                                          s.baseColor.g,
                                          s.baseColor.b,
                                          s.metallic,
                                          s.perceptualRoughness,
                                          s.occlusion,
                                          s.n.x,
                                          s.n.y,
                                          s.n.z,
                                          s.v.x,
                                          s.v.y,
                                          s.v.z,
                                          c.p.x,
                                          c.p.y,
                                          c.p.z,
                                          static_cast<float>(l.type),
                                          l.intensity.r,
                                          l.intensity.g,
                                          l.intensity.b,
                                          l.position.x,
                                          l.position.y,
                                          l.position.z,
                                          l.direction.x,
                                          l.direction.y,
                                          l.direction.z,
                                          l.range,
                                          l.spotScale,
                                          l.spotOffset,
                                          c.diffuseRadiance.r,
                                          c.diffuseRadiance.g,
                                          c.diffuseRadiance.b,
                                          c.specularRadiance};
    data.insert(data.end(), std::begin(values), std::end(values));
  }
  return data;
}

TEST(BrdfGlsl, AgreesWithItsCppCompilationOnRandomInputs) {
  LENSLAB_REQUIRE_GL();
  const fs::path source = fs::path(LENSLAB_TEST_ASSET_DIR).parent_path() / "shaders";
  const fs::path dir = fs::temp_directory_path() / ("lenslab-brdf-probe-" + std::to_string(getpid()));
  fs::create_directories(dir / "common");
  fs::create_directories(dir / "probe");
  fs::copy_file(source / "common/brdf.glsl", dir / "common/brdf.glsl", fs::copy_options::overwrite_existing);
  fs::copy_file(source / "common/dfg_filtered.glsl", dir / "common/dfg_filtered.glsl",
                fs::copy_options::overwrite_existing);
  fs::copy_file(source / "common/fullscreen.vert", dir / "common/fullscreen.vert",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir / "probe/brdf_probe.frag") << kProbe;
  gl::Program program;
  {
    const ShaderDirOverride override(dir);
    program = gl::buildProgram("common/fullscreen.vert", "probe/brdf_probe.frag");
  }
  fs::remove_all(dir);

  const std::vector<Case> cases = randomCases(23);
  const std::vector<float> data = packed(cases);
  gl::Buffer buffer = gl::Buffer::create();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
  gl::Texture table = gl::Texture::create();
  glTextureStorage2D(table.id(), 1, GL_RGB32F, kDfgTableSize, kDfgTableSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(table.id(), 0, 0, 0, kDfgTableSize, kDfgTableSize, GL_RGB, GL_FLOAT, dfgTable().data());
  glTextureParameteri(table.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // as ScenePass sets it (texelFetch ignores it)
  glTextureParameteri(table.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(table.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(table.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTextureUnit(9, table.id());
  glBindSampler(9, 0);

  const gl::FullScreenPass pass;
  gl::RenderTarget target(kWidth, kHeight);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  for (int mode = 0; mode < 3; ++mode) {
    target.bind();
    glProgramUniform1i(program.id(), 0, mode);
    pass.draw(program);
    const Image image = target.readColor();  // rows from the top
    double worst = 0.0;
    int lit = 0;
    for (int yTop = 0; yTop < kHeight; ++yTop)
      for (int x = 0; x < kWidth; ++x) {
        const Case& c = cases[static_cast<std::size_t>((kHeight - 1 - yTop) * kWidth + x)];
        const glm::vec3 expected =
            mode == 0
                ? punctualRadiance(c.surface, c.light, c.p)
                : imageLightRadiance(c.surface, c.diffuseRadiance, glm::vec3(c.specularRadiance),
                                     dfgLookup(glm::dot(c.surface.n, c.surface.v), c.surface.perceptualRoughness));
        const glm::vec4 got = image.at(x, yTop);
        // Relative to the case's brightest channel (a channel near 0 beside a bright one is
        // judged on the case's scale, not its own).
        const float scale = std::max({std::abs(expected.r), std::abs(expected.g), std::abs(expected.b)});
        lit += scale > 0.0f;
        for (int k = 0; k < 3; ++k) {
          ASSERT_TRUE(std::isfinite(got[k])) << "mode " << mode << " pixel " << x << "," << yTop;
          const double error = scale > 0.0f ? std::abs(got[k] - expected[k]) / scale : std::abs(got[k]);
          worst = std::max(worst, error);
          EXPECT_LE(error, 1e-5) << "mode " << mode << " pixel " << x << "," << yTop << " channel " << k << ": GLSL "
                                 << got[k] << ", C++ " << expected[k];
        }
      }
    std::cout << "[ measure  ] brdf.glsl GLSL vs C++, "
              << (mode == 0   ? "punctual"
                  : mode == 1 ? "image light"
                              : "image light, filtered DFG")
              << ": " << cases.size() << " random cases (" << lit << " lit), worst relative difference " << worst
              << "\n";
    EXPECT_GE(lit, 1000) << "the cases must light something";
  }
}

}  // namespace
}  // namespace lenslab
