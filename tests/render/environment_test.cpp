// The environment on the GPU: the GLSL lookups against their C++ (one source, two compilers), and
// the background through the lens in the rasterizer against the ray caster.
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"
#include "../common/gl_test_context.h"
#include "io/CameraJson.h"
#include "io/ImageCompare.h"
#include "plan/FramePlan.h"
#include "raycast/RayCaster.h"
#include "render/GpuEnvironment.h"
#include "render/Renderer.h"
#include "scene/Environment.h"
#include "scene/EnvironmentPrefilter.h"
#include "scene/GltfLoader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// A smooth sky with a bright disc (a soft box) and a seam-crossing band: detail for every lookup,
// in [0, 1] outside the disc.
EnvironmentImage testSky(int width) {
  EnvironmentImage image{width, width / 2, std::vector<glm::vec3>(static_cast<std::size_t>(width) * (width / 2))};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < width; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(image.height);
      glm::vec3 c(0.2f + 0.6f * (1.0f - v), 0.3f + 0.2f * std::sin(6.2831853f * u),
                  0.5f + 0.4f * std::cos(12.566f * u) * v);
      const float du = std::min(std::abs(u - 0.4f), 1.0f - std::abs(u - 0.4f)), dv = v - 0.35f;
      if (du * du + dv * dv < 0.003f) c += glm::vec3(0.3f);
      image.at(x, y) = c;
    }
  return image;
}

std::shared_ptr<const EnvironmentLookup> testEnvironment(int width, double rotationDegrees, float intensity) {
  PrefilterSettings s;
  s.diffuseWidth = 32;
  s.specularWidth = 64;
  s.specularLevels = 5;
  s.samplesPerTexel = 64;
  auto maps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(testSky(width), s));
  return std::make_shared<const EnvironmentLookup>(maps, EnvironmentPlacement{rotationDegrees, intensity});
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

GLuint compileStage(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    ADD_FAILURE() << log;
  }
  return shader;
}

// Each pixel of a 32 × 32 target evaluates one lookup for its own (direction, roughness) from
// an input texture: 1024 random inputs. `which`: 0 background, 1 diffuse, 2 specular.
TEST(EnvironmentGlsl, LookupsMatchTheCpp) {
  LENSLAB_REQUIRE_GL();
  const fs::path shaders = fs::path(LENSLAB_TEST_ASSET_DIR).parent_path() / "shaders" / "common";
  std::string textures = readText(shaders / "environment_textures.glsl");
  const std::string include = "#include \"environment.glsl\"";
  textures.replace(textures.find(include), include.size(), readText(shaders / "environment.glsl"));
  const std::string locations = "#include \"locations.glsl\"";
  textures.replace(textures.find(locations), locations.size(), readText(shaders / "locations.glsl"));
  const std::string fragment = "#version 450 core\n" + textures + R"(
layout(binding = 0) uniform sampler2D inputs;
layout(location = 10) uniform int which;
layout(location = 0) out vec4 outColor;
void main() {
  vec4 in4 = texelFetch(inputs, ivec2(gl_FragCoord.xy), 0);
  vec3 d = vec3(in4.x, in4.y, in4.z);
  EnvironmentParams p = environmentParams();
  vec3 c = which == 0 ? environmentBackground(p, d) : which == 1 ? environmentDiffuse(p, d) : environmentSpecular(p, d, in4.w);
  outColor = vec4(c, 1.0);
})";
  const std::string vertex = readText(shaders / "fullscreen.vert");
  gl::Program program = gl::Program::create();
  const GLuint vs = compileStage(GL_VERTEX_SHADER, vertex), fs_ = compileStage(GL_FRAGMENT_SHADER, fragment);
  glAttachShader(program.id(), vs);
  glAttachShader(program.id(), fs_);
  glLinkProgram(program.id());
  glDeleteShader(vs);
  glDeleteShader(fs_);
  GLint linked = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
  ASSERT_TRUE(linked);

  for (const double rotation : {0.0, 127.5}) {
    const auto lookup = testEnvironment(128, rotation, 1.7f);
    const GpuEnvironment gpu(*lookup);
    gpu.bind(program.id());
    constexpr int kSide = 32;
    std::mt19937 rng(17);
    std::normal_distribution<float> g;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec4> inputs(kSide * kSide);
    for (glm::vec4& in : inputs) in = glm::vec4(g(rng), g(rng), g(rng), unit(rng));
    inputs[0] = {0.0f, 0.0f, 1.0f, 0.5f};   // the seam
    inputs[1] = {0.0f, 1.0f, 0.0f, 0.0f};   // a pole
    inputs[2] = {0.0f, -1.0f, 0.0f, 1.0f};  // the other
    gl::Texture input = gl::Texture::create();
    glTextureStorage2D(input.id(), 1, GL_RGBA32F, kSide, kSide);
    glTextureSubImage2D(input.id(), 0, 0, 0, kSide, kSide, GL_RGBA, GL_FLOAT, inputs.data());
    glTextureParameteri(input.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTextureUnit(0, input.id());
    glBindSampler(0, 0);
    const gl::RenderTarget target(kSide, kSide);
    gl::FullScreenPass pass;
    for (int which = 0; which < 3; ++which) {
      target.bind();
      glDisable(GL_DEPTH_TEST);
      glDisable(GL_BLEND);
      glProgramUniform1i(program.id(), 10, which);
      pass.draw(program);
      std::vector<glm::vec4> out(kSide * kSide);
      glReadPixels(0, 0, kSide, kSide, GL_RGBA, GL_FLOAT, out.data());
      double worst = 0.0;
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        const glm::vec3 d(inputs[i]);
        const glm::vec3 want = which == 0   ? lookup->background(d)
                               : which == 1 ? lookup->diffuse(d)
                                            : lookup->specular(d, inputs[i].w);
        for (int k = 0; k < 3; ++k) {
          const double relative = std::abs(out[i][k] - want[k]) / std::max(std::abs(want[k]), 1e-3f);
          worst = std::max(worst, relative);
          EXPECT_LE(relative, 1e-4) << "lookup " << which << " input " << i << " channel " << k << ": " << out[i][k]
                                    << " vs " << want[k];
        }
      }
      std::cout << "[ measure  ] lookup " << which << " rotation " << rotation
                << ": worst relative difference GLSL vs C++ " << worst << "\n";
    }
  }
}

TEST(EnvironmentGlsl, DirectionFromNdcFollowsTheProjection) {
  // A symmetric reverse-Z perspective looking down −Z: NDC (1, 0) is at the right edge of a 90° field.
  const glm::dmat4 clipFromView(1.0, 0.0, 0.0, 0.0,   //
                                0.0, 1.0, 0.0, 0.0,   //
                                0.0, 0.0, 0.0, -1.0,  //
                                0.0, 0.0, 0.1, 0.0);  // infinite reverse-Z, near 0.1
  const glm::dmat3 m = worldDirectionFromNdc(clipFromView);
  const glm::dvec3 centre = glm::normalize(m * glm::dvec3(0, 0, 1));
  const glm::dvec3 right = glm::normalize(m * glm::dvec3(1, 0, 1));
  EXPECT_NEAR(centre.z, -1.0, 1e-12);
  EXPECT_NEAR(right.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(right.z, -std::sqrt(0.5), 1e-12);
  // The same view 1e15 from the origin, turned: the directions only turn (no eye position in them).
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(0.3, 1.0, 0.2));
  const glm::dmat4 far =
      clipFromView * glm::inverse(glm::translate(glm::dmat4(1.0), glm::dvec3(1e15, -3e14, 7e14)) * turn);
  const glm::dmat3 mFar = worldDirectionFromNdc(far);
  for (const glm::dvec3 ndc : {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 1), glm::dvec3(-0.3, 0.8, 1)}) {
    const glm::dvec3 want = glm::dmat3(turn) * glm::normalize(m * ndc);
    const glm::dvec3 got = glm::normalize(mFar * ndc);
    EXPECT_NEAR(glm::length(got - want), 0.0, 1e-12);
  }
}

// An empty view of the environment: every pixel the background, through the lens.
double environmentPsnr(const std::string& cameraFile, bool pinhole, std::optional<double> targetPsnrDb = std::nullopt) {
  const fs::path assets = LENSLAB_TEST_ASSET_DIR;
  Scene scene = loadGltf(assets / "rows/rows.gltf");
  Camera camera = loadCameraJson(assets / cameraFile).camera;
  // Keep one instance, moved far behind the camera: nothing in view but the environment.
  scene.instances.resize(1);
  const glm::dvec3 behind = camera.view.vrp + 1e3 * glm::normalize(camera.view.vpn) * glm::length(scene.bounds.size());
  scene.instances[0].worldFromModel = glm::translate(glm::dmat4(1.0), behind);
  scene.bounds = computeBounds(scene);
  scene.environment = testEnvironment(256, 40.0, 1.0f);
  const ImageSize size{120, 80};
  Camera lensCamera = camera;
  if (lensCamera.lens.isPinhole()) lensCamera.lens.apertureRadius = 1e-3;
  PlanOptions options{targetPsnrDb ? AperturePattern::Sobol : AperturePattern::Concentric, targetPsnrDb ? 0 : 256, 256,
                      3};
  options.targetPsnrDb = targetPsnrDb;
  const FramePlan plan = makeFramePlan(scene, lensCamera, size, options);
  if (pinhole) camera.lens.apertureRadius = 0.0;
  Renderer renderer(scene);
  const Image raster = renderer.render(camera, plan, size);
  const RayCaster caster(scene);
  const Image reference = caster.render(camera, size, RaycastOptions{256, 11});
  // The picture is the environment, not a constant: its green spans the sky's gradient.
  float lo = 1e9f, hi = -1e9f;
  for (int y = 0; y < size.heightPx; ++y)
    for (int x = 0; x < size.widthPx; ++x) {
      lo = std::min(lo, reference.at(x, y).g);
      hi = std::max(hi, reference.at(x, y).g);
    }
  EXPECT_GT(hi - lo, 0.05f);
  const double psnr = compareImages(raster, reference, 0.0).psnrDb;
  std::cout << "[ measure  ] environment only, " << cameraFile << (pinhole ? " pinhole" : " thin lens")
            << (targetPsnrDb ? " per-tile budgets" : "") << ": raster 256 views vs ray cast 256 spp: PSNR " << psnr
            << " dB\n";
  return psnr;
}

TEST(EnvironmentRaster, BackgroundMatchesTheRayCaster) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(environmentPsnr("rows/camera.json", true), 40.0);
  EXPECT_GE(environmentPsnr("rows/camera-dof.json", false), 40.0);
}

// The paths that draw views differently: lens effects (each view overscanned and summed through
// distortion, lateral colour and the field-curvature warp), and per-tile budgets (views drawn into
// scissored tiles, two streams).
TEST(EnvironmentRaster, LensEffectsAndTileBudgetsMatchTheRayCaster) {
  LENSLAB_REQUIRE_GL();
  EXPECT_GE(environmentPsnr("rows/camera-lens.json", false), 40.0);
  EXPECT_GE(environmentPsnr("rows/camera-dof.json", false, 45.0), 40.0);
}

}  // namespace
}  // namespace lenslab
