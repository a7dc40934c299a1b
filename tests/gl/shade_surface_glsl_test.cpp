// shade_surface.glsl, the material assembled at a surface point, is one definition compiled twice:
// as GLSL by the GPU driver (scene.frag includes it) and as C++ by the compiler
// (scene/ShadeSurface.cpp, which the ray caster calls). The two agree on random inputs: a
// full-screen pass evaluates the GLSL per pixel, one random case per pixel, writing its results to
// a storage buffer, and each case is compared with the C++ result for the same inputs. The cases
// draw every map, every light kind, blend alpha beyond [0, 1], alpha masks, double-sided back
// faces, the environment or the uniform surround, and emission.
#include "gl/FullScreenPass.h"
#include "gl/Framebuffer.h"
#include "gl/Shader.h"
#include "../common/gl_test_context.h"
#include "../common/shader_dir_override.h"
#include "scene/Brdf.h"
#include "scene/ShadeSurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <vector>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

constexpr int kWidth = 64, kHeight = 64;  // 4096 cases
constexpr int kFloatsPerCase = 168;       // the layout below; lights from 64, 13 floats each
constexpr int kFirstLight = 64, kFloatsPerLight = 13;
constexpr int kResultsPerCase = 12;  // radiance, alpha, normal, cut out, base colour

// The probe: shade_surface.glsl's includer functions read case k of a storage buffer (the texels,
// the lights, the surround; the environment's lookups are smooth functions of their arguments, so
// that a wrong direction shows), and main writes what the shading makes of it.
const char* kProbe = R"(#version 450 core
layout(std430, binding = 0) readonly buffer Cases { float data[]; };
layout(std430, binding = 1) writeonly buffer Results { float result[]; };
layout(binding = 9) uniform sampler2D dfgTable;
out vec4 outColor;
int k;  // this case's first float
vec3 dfgTexel(int x, int y) { return texelFetch(dfgTable, ivec2(x, y), 0).rgb; }
#include "../common/dfg_filtered.glsl"
#include "../common/brdf.glsl"
#include "../common/material_maps.glsl"
float at(int i) { return data[k + i]; }
bool flag(int i) { return data[k + i] != 0.0; }
vec3 at3(int i) { return vec3(at(i), at(i + 1), at(i + 2)); }
vec4 at4(int i) { return vec4(at(i), at(i + 1), at(i + 2), at(i + 3)); }
vec4 baseColorTexel() { return at4(38); }
vec4 metallicRoughnessTexel() { return at4(42); }
float occlusionTexel() { return at(46); }
vec3 emissiveTexel() { return at3(47); }
vec3 normalTexel() { return at3(50); }
float ambientRadiance() { return at(53); }
bool environmentLit() { return flag(54); }
vec3 environmentDiffuseAt(vec3 n) { return at3(55) * (vec3(1.5) + n); }
vec3 environmentSpecularAt(vec3 r, float roughness) { return at3(58) * (vec3(1.5) + r) * (1.0 + roughness); }
int shadingLightCount() { return int(at(61)); }
Light shadingLight(int i) {
  int j = 64 + 13 * i;
  Light l;
  l.type = int(at(j));
  l.intensity = at3(j + 1);
  l.position = at3(j + 4);
  l.direction = at3(j + 7);
  l.range = at(j + 10);
  l.spotScale = at(j + 11);
  l.spotOffset = at(j + 12);
  return l;
}
vec3 dfgAt(float nv, float roughness) { return dfgFiltered(nv, roughness); }  // as scene.frag
#include "../common/shade_surface.glsl"
void main() {
  int c = int(gl_FragCoord.y) * 64 + int(gl_FragCoord.x);
  k = c * 168;
  SurfaceMaterial m;
  m.baseColorFactor = at4(0);
  m.hasBaseColorTexture = flag(4);
  m.alphaMask = flag(5);
  m.alphaCutoff = at(6);
  m.doubleSided = flag(7);
  m.unlit = flag(8);
  m.metallicFactor = at(9);
  m.roughnessFactor = at(10);
  m.hasMetallicRoughnessTexture = flag(11);
  m.hasOcclusionTexture = flag(12);
  m.occlusionStrength = at(13);
  m.normalMapped = flag(14);
  m.normalScale = at(15);
  m.emissive = at3(16);
  m.hasEmissiveTexture = flag(19);
  SurfacePoint p;
  p.vertexColor = at4(20);
  p.normal = at3(24);
  p.tangent = at3(27);
  p.handedness = at(30);
  p.frontFacing = flag(31);
  p.position = at3(32);
  p.towardViewer = at3(35);
  vec4 base = surfaceBaseColor(m, p.vertexColor);
  ShadedSurface s = shadeSurface(m, base, p);
  int r = c * 12;
  for (int i = 0; i < 3; ++i) {
    result[r + i] = s.radiance[i];
    result[r + 4 + i] = s.normal[i];
  }
  result[r + 3] = s.alpha;
  result[r + 7] = alphaCutOut(m, base) ? 1.0 : 0.0;
  for (int i = 0; i < 4; ++i) result[r + 8 + i] = base[i];
  outColor = vec4(0.0);
}
)";

struct Case {
  SurfaceMaterial material;
  SurfacePoint point;
  glm::vec4 baseColorTexel{1.0f}, metallicRoughnessTexel{1.0f};
  float occlusionTexel = 1.0f;
  glm::vec3 emissiveTexel{1.0f}, normalTexel{0.5f, 0.5f, 1.0f};
  float ambient = 0.0f;
  bool environment = false;
  glm::vec3 environmentDiffuse{0.0f}, environmentSpecular{0.0f};
  std::vector<ShadingLight> lights;
};

// The C++ side's fetches: the case's values, and the same environment functions as the probe's.
class CaseFetch final : public SurfaceFetch {
 public:
  explicit CaseFetch(const Case& c) : c_(c) {}
  glm::vec4 baseColorTexel() const override { return c_.baseColorTexel; }
  glm::vec4 metallicRoughnessTexel() const override { return c_.metallicRoughnessTexel; }
  float occlusionTexel() const override { return c_.occlusionTexel; }
  glm::vec3 emissiveTexel() const override { return c_.emissiveTexel; }
  glm::vec3 normalTexel() const override { return c_.normalTexel; }
  glm::vec3 environmentDiffuse(const glm::vec3& n) const override {
    return c_.environmentDiffuse * (glm::vec3(1.5f) + n);
  }
  glm::vec3 environmentSpecular(const glm::vec3& r, float roughness) const override {
    return c_.environmentSpecular * (glm::vec3(1.5f) + r) * (1.0f + roughness);
  }

 private:
  const Case& c_;
};

std::vector<Case> randomCases(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto in = [&](float lo, float hi) { return lo + (hi - lo) * u(rng); };
  const auto chance = [&](float p) { return u(rng) < p; };
  const auto unit = [&] {
    while (true) {
      const glm::vec3 d(in(-1, 1), in(-1, 1), in(-1, 1));
      const float len = glm::length(d);
      if (len > 0.1f && len <= 1.0f) return d / len;
    }
  };
  const auto colour = [&] { return glm::vec4(u(rng), u(rng), u(rng), u(rng)); };
  std::vector<Case> cases(kWidth * kHeight);
  for (Case& c : cases) {
    SurfaceMaterial& m = c.material;
    // Alpha beyond [0, 1] as a glTF factor may not be, but a blend's clamp must hold either way.
    m.baseColorFactor = glm::vec4(u(rng), u(rng), u(rng), in(-0.2f, 1.3f));
    m.hasBaseColorTexture = chance(0.5f);
    m.alphaMask = chance(0.3f);
    m.alphaCutoff = u(rng);
    m.doubleSided = chance(0.5f);
    m.unlit = chance(0.15f);
    m.metallicFactor = u(rng);
    m.roughnessFactor = u(rng);
    m.hasMetallicRoughnessTexture = chance(0.5f);
    m.hasOcclusionTexture = chance(0.5f);
    m.occlusionStrength = u(rng);
    m.normalMapped = chance(0.5f);
    m.normalScale = in(-2.0f, 2.0f);
    m.emissive = chance(0.4f) ? glm::vec3(in(0, 5), in(0, 5), in(0, 5)) : glm::vec3(0.0f);
    m.hasEmissiveTexture = chance(0.5f);
    SurfacePoint& p = c.point;
    p.vertexColor = chance(0.5f) ? glm::vec4(1.0f) : colour();
    p.normal = unit() * in(0.2f, 3.0f);                                    // interpolated: not unit
    p.tangent = chance(0.1f) ? glm::vec3(0.0f) : unit() * in(0.2f, 3.0f);  // some meshes have none
    p.handedness = chance(0.5f) ? 1.0f : -1.0f;
    p.frontFacing = chance(0.7f);
    p.position = {in(-1, 1), in(-1, 1), in(-1, 1)};
    p.towardViewer = unit();
    // Mostly the side the normal faces (front) or the other (a double-sided back face), some silhouettes.
    const float side = glm::dot(p.normal, p.towardViewer) * (p.frontFacing ? 1.0f : -1.0f);
    if (chance(0.8f) && side < 0.0f) p.towardViewer = -p.towardViewer;
    c.baseColorTexel = colour();
    c.metallicRoughnessTexel = colour();
    c.occlusionTexel = u(rng);
    c.emissiveTexel = glm::vec3(colour());
    c.normalTexel = glm::vec3(colour());
    c.ambient = in(0.0f, 1.0f);
    c.environment = chance(0.5f);
    c.environmentDiffuse = {in(0, 2), in(0, 2), in(0, 2)};
    c.environmentSpecular = {in(0, 2), in(0, 2), in(0, 2)};
    c.lights.resize(static_cast<std::size_t>(std::min(8, static_cast<int>(in(0.0f, 9.0f)))));
    for (ShadingLight& l : c.lights) {
      l.type = std::min(2, static_cast<int>(3.0f * u(rng)));
      l.intensity = {in(0, 30), in(0, 30), in(0, 30)};
      l.position = {in(-3, 3), in(-3, 3), in(-3, 3)};
      l.direction = unit();
      l.range = chance(0.5f) ? 0.0f : in(1, 6);
      const float outer = in(0.05f, 1.5f);
      const glm::vec2 cone = spotScaleOffset(in(0.0f, 0.99f) * outer, outer);
      l.spotScale = cone.x;
      l.spotOffset = cone.y;
    }
  }
  return cases;
}

std::vector<float> packed(const std::vector<Case>& cases) {
  std::vector<float> data(cases.size() * kFloatsPerCase, 0.0f);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    float* d = data.data() + i * kFloatsPerCase;
    const auto put = [&](int at, auto v) {
      for (int j = 0; j < v.length(); ++j) d[at + j] = v[j];
    };
    const auto flag = [](bool b) { return b ? 1.0f : 0.0f; };
    const SurfaceMaterial& m = c.material;
    put(0, m.baseColorFactor);
    d[4] = flag(m.hasBaseColorTexture);
    d[5] = flag(m.alphaMask);
    d[6] = m.alphaCutoff;
    d[7] = flag(m.doubleSided);
    d[8] = flag(m.unlit);
    d[9] = m.metallicFactor;
    d[10] = m.roughnessFactor;
    d[11] = flag(m.hasMetallicRoughnessTexture);
    d[12] = flag(m.hasOcclusionTexture);
    d[13] = m.occlusionStrength;
    d[14] = flag(m.normalMapped);
    d[15] = m.normalScale;
    put(16, m.emissive);
    d[19] = flag(m.hasEmissiveTexture);
    const SurfacePoint& p = c.point;
    put(20, p.vertexColor);
    put(24, p.normal);
    put(27, p.tangent);
    d[30] = p.handedness;
    d[31] = flag(p.frontFacing);
    put(32, p.position);
    put(35, p.towardViewer);
    put(38, c.baseColorTexel);
    put(42, c.metallicRoughnessTexel);
    d[46] = c.occlusionTexel;
    put(47, c.emissiveTexel);
    put(50, c.normalTexel);
    d[53] = c.ambient;
    d[54] = flag(c.environment);
    put(55, c.environmentDiffuse);
    put(58, c.environmentSpecular);
    d[61] = static_cast<float>(c.lights.size());
    for (std::size_t k = 0; k < c.lights.size(); ++k) {
      const ShadingLight& l = c.lights[k];
      const int at = kFirstLight + kFloatsPerLight * static_cast<int>(k);
      d[at] = static_cast<float>(l.type);
      put(at + 1, l.intensity);
      put(at + 4, l.position);
      put(at + 7, l.direction);
      d[at + 10] = l.range;
      d[at + 11] = l.spotScale;
      d[at + 12] = l.spotOffset;
    }
  }
  return data;
}

gl::Program buildProbe() {
  const fs::path source = fs::path(LENSLAB_TEST_ASSET_DIR).parent_path() / "shaders";
  const fs::path dir = fs::temp_directory_path() / ("lenslab-shade-surface-probe-" + std::to_string(getpid()));
  fs::create_directories(dir / "common");
  fs::create_directories(dir / "probe");
  for (const char* file :
       {"brdf.glsl", "dfg_filtered.glsl", "material_maps.glsl", "shade_surface.glsl", "fullscreen.vert"})
    fs::copy_file(source / "common" / file, dir / "common" / file, fs::copy_options::overwrite_existing);
  std::ofstream(dir / "probe/shade_surface_probe.frag") << kProbe;
  gl::Program program;
  {
    const ShaderDirOverride override(dir);
    program = gl::buildProgram("common/fullscreen.vert", "probe/shade_surface_probe.frag");
  }
  fs::remove_all(dir);
  return program;
}

// The DFG table on unit 9, as ScenePass binds it (bilinear, clamped: dfg_filtered.glsl).
gl::Texture uploadDfgTable() {
  gl::Texture table = gl::Texture::create();
  glTextureStorage2D(table.id(), 1, GL_RGB32F, kDfgTableSize, kDfgTableSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(table.id(), 0, 0, 0, kDfgTableSize, kDfgTableSize, GL_RGB, GL_FLOAT, dfgTable().data());
  glTextureParameteri(table.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(table.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(table.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(table.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTextureUnit(9, table.id());
  glBindSampler(9, 0);
  return table;
}

// The GLSL's results, kResultsPerCase floats per case.
std::vector<float> evaluateGlsl(const std::vector<Case>& cases) {
  const gl::Program program = buildProbe();
  const std::vector<float> data = packed(cases);
  gl::Buffer input = gl::Buffer::create();
  glNamedBufferStorage(input.id(), static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
  std::vector<float> results(cases.size() * kResultsPerCase, -1.0f);
  gl::Buffer output = gl::Buffer::create();
  glNamedBufferStorage(output.id(), static_cast<GLsizeiptr>(results.size() * sizeof(float)), results.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
  const gl::Texture table = uploadDfgTable();
  const gl::FullScreenPass pass;
  gl::RenderTarget target(kWidth, kHeight);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  target.bind();
  pass.draw(program);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(results.size() * sizeof(float)), results.data());
  return results;
}

TEST(ShadeSurfaceGlsl, AgreesWithItsCppCompilationOnRandomInputs) {
  LENSLAB_REQUIRE_GL();
  const std::vector<Case> cases = randomCases(33);
  const std::vector<float> glsl = evaluateGlsl(cases);
  double worst = 0.0;
  int lit = 0, cut = 0, environment = 0, backFaces = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const CaseFetch fetch(c);
    const SurfaceLighting lighting{c.lights, c.ambient, c.environment};
    const glm::vec4 base = surfaceBaseColor(c.material, c.point.vertexColor, fetch);
    const ShadedSurface shaded = shadeSurface(c.material, base, c.point, lighting, fetch);
    const bool cutOut = alphaCutOut(c.material, base);
    const float* got = glsl.data() + i * kResultsPerCase;
    lit += !c.material.unlit;
    cut += cutOut;
    environment += c.environment && !c.material.unlit;
    backFaces += c.material.doubleSided && !c.point.frontFacing;
    // Each quantity relative to its largest component (a channel near 0 beside a bright one is
    // judged on the case's scale, not its own), absolute below 1.
    const auto compare = [&](const char* what, const float* glslValues, const float* cppValues, int n) {
      float scale = 1.0f;
      for (int j = 0; j < n; ++j) scale = std::max(scale, std::abs(cppValues[j]));
      for (int j = 0; j < n; ++j) {
        ASSERT_TRUE(std::isfinite(glslValues[j])) << what << " of case " << i;
        const double error = std::abs(glslValues[j] - cppValues[j]) / scale;
        worst = std::max(worst, error);
        EXPECT_LE(error, 1e-5) << what << "[" << j << "] of case " << i << ": GLSL " << glslValues[j] << ", C++ "
                               << cppValues[j];
      }
    };
    compare("radiance", got, &shaded.radiance.x, 3);
    compare("alpha", got + 3, &shaded.alpha, 1);
    compare("normal", got + 4, &shaded.normal.x, 3);
    const float cutFlag = cutOut ? 1.0f : 0.0f;
    compare("cut out", got + 7, &cutFlag, 1);
    compare("base colour", got + 8, &base.x, 4);
  }
  std::cout << "[ measure  ] shade_surface.glsl GLSL vs C++: " << cases.size() << " random cases (" << lit << " lit, "
            << environment << " by an environment, " << cut << " cut out, " << backFaces
            << " double-sided back faces), worst relative difference " << worst << "\n";
  // Every part of the assembly is exercised by many cases.
  EXPECT_GE(lit, 3000);
  EXPECT_GE(environment, 1000);
  EXPECT_GE(cut, 200);
  EXPECT_GE(backFaces, 300);
}

}  // namespace
}  // namespace lenslab
