// The environment: its direction map, prefiltering against closed forms, files and the cache.
#include "core/Error.h"
#include "io/CameraJson.h"
#include "io/EnvironmentFile.h"
#include "plan/FramePlan.h"
#include "plan/VisibleBlur.h"
#include "scene/GltfLoader.h"
#include "scene/Environment.h"
#include "scene/EnvironmentPrefilter.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include <sys/stat.h>
#include <unistd.h>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

EnvironmentImage constantImage(int width, glm::vec3 value) {
  return {width, width / 2, std::vector<glm::vec3>(static_cast<std::size_t>(width) * (width / 2), value)};
}

// Small maps: the tests check the method, not the default sizes.
PrefilterSettings smallSettings() {
  PrefilterSettings s;
  s.diffuseWidth = 16;
  s.diffuseSourceWidth = 64;
  s.specularWidth = 32;
  s.specularLevels = 4;
  s.samplesPerTexel = 64;
  return s;
}

TEST(Environment, DirectionAndUvRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec2 uv(unit(rng), 0.01f + 0.98f * unit(rng));
    const glm::vec3 d = directionFromUv(uv);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    const glm::vec2 back = uvFromDirection(3.0f * d);  // any length
    EXPECT_NEAR(std::remainder(back.x - uv.x, 1.0f), 0.0f, 1e-5f) << uv.x << " " << uv.y;
    EXPECT_NEAR(back.y, uv.y, 1e-5f);
  }
  // The stated convention: −Z the centre, +X at u = 0.75, +Y the top row, +Z the seam.
  EXPECT_NEAR(uvFromDirection({0, 0, -1}).x, 0.5f, 1e-6f);
  EXPECT_NEAR(uvFromDirection({0, 0, -1}).y, 0.5f, 1e-6f);
  EXPECT_NEAR(uvFromDirection({1, 0, 0}).x, 0.75f, 1e-6f);
  EXPECT_NEAR(uvFromDirection({0, 1, 0}).y, 0.0f, 1e-6f);
  EXPECT_NEAR(uvFromDirection({0, -1, 0}).y, 1.0f, 1e-6f);
  EXPECT_NEAR(std::abs(uvFromDirection({0, 0, 1}).x - 0.5f), 0.5f, 1e-6f);
}

TEST(Environment, BilinearWrapsAcrossTheSeam) {
  EnvironmentImage image = constantImage(8, glm::vec3(0.0f));
  for (int y = 0; y < 4; ++y) {
    image.at(0, y) = glm::vec3(1.0f);
    image.at(7, y) = glm::vec3(3.0f);
  }
  // u = 0 and u = 1 are the same place: halfway between the last column and the first.
  EXPECT_NEAR(sampleBilinear(image, {0.0f, 0.5f}).r, 2.0f, 1e-6f);
  EXPECT_NEAR(sampleBilinear(image, {1.0f, 0.5f}).r, 2.0f, 1e-6f);
  // Directions just either side of +Z agree.
  const glm::vec3 left = sampleBilinear(image, uvFromDirection({-1e-4f, 0.0f, 1.0f}));
  const glm::vec3 right = sampleBilinear(image, uvFromDirection({1e-4f, 0.0f, 1.0f}));
  EXPECT_NEAR(left.r, right.r, 1e-3f);
  // Rows clamp at the poles.
  EXPECT_NEAR(sampleBilinear(image, {0.5f / 8.0f, 0.0f}).r, 1.0f, 1e-6f);
}

TEST(Environment, ConstantPrefiltersToTheSameConstant) {
  const glm::vec3 c(0.5f, 2.0f, 7.0f);
  const auto maps =
      std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(constantImage(64, c), smallSettings()));
  ASSERT_EQ(maps->specularLevels(), 4);
  const auto near = [&](glm::vec3 v, glm::vec3 want) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[k], want[k], 1e-5f * want[k]);
  };
  for (const glm::vec3& v : maps->diffuse.rgb) near(v, c);
  for (const EnvironmentImage& level : maps->specular)
    for (const glm::vec3& v : level.rgb) near(v, c);
  const EnvironmentLookup lookup(maps, {33.0, 2.0f});
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 d(g(rng), g(rng), g(rng));
    near(lookup.background(d), 2.0f * c);
    near(lookup.diffuse(d), 2.0f * c);
    near(lookup.specular(d, static_cast<float>(i) / 199.0f), 2.0f * c);
  }
}

TEST(Environment, SingleBrightTexelFollowsTheCosineLaw) {
  // One texel of radiance L and solid angle Ω: irradiance E(n) = L·Ω·max(0, n·ω), and the diffuse
  // map holds E / π.
  EnvironmentImage image = constantImage(128, glm::vec3(0.0f));
  const int tx = 80, ty = 20;
  const float radiance = 1e4f;
  image.at(tx, ty) = glm::vec3(radiance);
  const double omega = texelSolidAngle(ty, 128, 64);
  const glm::dvec3 light(directionFromUv({(tx + 0.5f) / 128.0f, (ty + 0.5f) / 64.0f}));
  PrefilterSettings s = smallSettings();
  s.diffuseWidth = 64;
  s.diffuseSourceWidth = 128;
  const auto maps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(image, s));
  const EnvironmentLookup lookup(maps, {});
  const double peak = radiance * omega / std::numbers::pi;
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const double cosine = glm::dot(n, light);
    const double got = lookup.diffuse(glm::vec3(n)).g;
    if (cosine > 0.2) {
      EXPECT_NEAR(got, peak * cosine, 0.02 * peak) << "cos " << cosine;
      ++checked;
    } else if (cosine < -0.2) {
      EXPECT_NEAR(got, 0.0, 1e-6 * peak);
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Environment, RoughnessSpreadsABrightTexelWithoutLosingIt) {
  // A small bright source: the mirror level shows it sharp; each rougher level spreads it wider,
  // so its peak falls, but never beyond the source nor below zero (no fireflies, no ringing).
  EnvironmentImage image = constantImage(128, glm::vec3(0.1f));
  image.at(64, 32) = glm::vec3(1000.0f);
  const auto maps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(image, smallSettings()));
  const EnvironmentLookup lookup(maps, {});
  const glm::vec3 toSource = directionFromUv({64.5f / 128.0f, 32.5f / 64.0f});
  float previous = 1e30f;
  for (int level = 1; level < maps->specularLevels(); ++level) {
    const float peak = lookup.specular(toSource, static_cast<float>(maps->levelRoughness(level))).r;
    EXPECT_LT(peak, previous);
    EXPECT_GT(peak, 0.1f);
    previous = peak;
    for (const glm::vec3& v : maps->specular[static_cast<std::size_t>(level - 1)].rgb) {
      EXPECT_GE(v.r, 0.1f * (1.0f - 1e-5f));
      EXPECT_LE(v.r, 1000.0f);
    }
  }
}

// The levels are spaced from the smallest roughness the shading uses: a near-mirror (roughness
// ≤ 0.045, the floor) reads the source alone, with nothing of a rough level blended in; each
// level's own roughness reads that level alone; the levels end at roughness 1.
TEST(Environment, NearMirrorsReadTheSourceAloneAndEachLevelItsOwnRoughness) {
  EnvironmentImage image = constantImage(128, glm::vec3(0.1f));
  image.at(64, 32) = glm::vec3(1000.0f);
  const auto maps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(image, smallSettings()));
  const EnvironmentLookup lookup(maps, {});
  EXPECT_DOUBLE_EQ(maps->levelRoughness(0), 0.045);
  EXPECT_DOUBLE_EQ(maps->levelRoughness(maps->specularLevels() - 1), 1.0);
  for (const glm::vec3 d : {directionFromUv({64.5f / 128.0f, 32.5f / 64.0f}), directionFromUv({0.3f, 0.6f})}) {
    for (const float roughness : {0.0f, 0.03f, 0.045f})
      EXPECT_EQ(lookup.specular(d, roughness), lookup.background(d)) << "roughness " << roughness;
    for (int level = 1; level < maps->specularLevels(); ++level) {
      const glm::vec2 uv = uvFromDirection(d);
      const glm::vec3 own = sampleBilinear(maps->specular[static_cast<std::size_t>(level - 1)], uv);
      const glm::vec3 looked = lookup.specular(d, static_cast<float>(maps->levelRoughness(level)));
      EXPECT_NEAR(looked.r, own.r, 1e-4f * own.r) << "level " << level;
    }
  }
}

TEST(Environment, FilteredImportanceSamplingLeavesNoFireflies) {
  // A bright texel seen through a rough level: with a fixed set of samples read at full
  // resolution it would show as scattered dots (the texels whose samples happen to hit it);
  // read at the pyramid level each sample stands for, it is one smooth lobe. Along the row
  // through it, the level rises to one peak and falls, with no second bump.
  EnvironmentImage image = constantImage(256, glm::vec3(0.1f));
  image.at(128, 64) = glm::vec3(1e4f);
  PrefilterSettings s = smallSettings();
  s.specularWidth = 64;
  const PrefilteredEnvironment maps = prefilterEnvironment(image, s);
  for (const EnvironmentImage& level : maps.specular) {
    const int y = level.height / 2;
    int peak = 0;
    for (int x = 0; x < level.width; ++x)
      if (level.at(x, y).r > level.at(peak, y).r) peak = x;
    // (At roughness 1 the lobe's top is flat over tens of degrees: its maximum wanders with the samples.)
    const double roughness = maps.levelRoughness(static_cast<int>(&level - &maps.specular[0]) + 1);
    if (roughness < 1.0) {
      EXPECT_NEAR(peak, level.width / 2, 2) << "level of roughness " << roughness;
    }
    // Where the source shows (above 5 % of its peak over the background), within 2 % of it.
    const float excess = level.at(peak, y).r - 0.1f;
    for (int x = 1; x < level.width; ++x) {
      const float before = level.at(x - 1, y).r, here = level.at(x, y).r;
      if (std::max(before, here) - 0.1f < 0.05f * excess) continue;
      if (x <= peak)
        EXPECT_GE(here, before - 0.02f * excess) << "x " << x;
      else
        EXPECT_LE(here, before + 0.02f * excess) << "x " << x;
    }
  }
}

TEST(Environment, RotationTurnsAboutY) {
  EnvironmentImage image = constantImage(64, glm::vec3(0.0f));
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) image.at(x, y) = glm::vec3(static_cast<float>(x), static_cast<float>(y), 1.0f);
  const auto maps = std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(image, smallSettings()));
  const EnvironmentLookup plain(maps, {});
  const EnvironmentLookup turned(maps, {90.0, 1.0f});
  // At 90° the image centre (−Z unturned) is seen towards −X.
  const glm::vec3 a = plain.background({0.2f, 0.3f, -1.0f});
  const glm::vec3 b = turned.background({-1.0f, 0.3f, -0.2f});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-3f);
}

TEST(EnvironmentCache, EncodesAndDecodesExactly) {
  const auto maps = prefilterEnvironment(constantImage(32, glm::vec3(1.0f, 2.0f, 3.0f)), smallSettings());
  const std::string bytes = encodeEnvironmentCache("key", maps);
  const auto back = decodeEnvironmentCache("key", bytes);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->background.rgb, maps.background.rgb);
  EXPECT_EQ(back->diffuse.rgb, maps.diffuse.rgb);
  ASSERT_EQ(back->specular.size(), maps.specular.size());
  for (std::size_t l = 0; l < maps.specular.size(); ++l) EXPECT_EQ(back->specular[l].rgb, maps.specular[l].rgb);
  EXPECT_FALSE(decodeEnvironmentCache("other key", bytes));  // stale
  std::string corrupt = bytes;
  corrupt[corrupt.size() / 2] ^= 1;
  EXPECT_FALSE(decodeEnvironmentCache("key", corrupt));
  EXPECT_FALSE(decodeEnvironmentCache("key", bytes.substr(0, bytes.size() - 3)));
}

// A file in this process's scratch folder, removed when the tests end.
fs::path scratch(const std::string& name) {
  static const struct Folder {
    fs::path path = fs::temp_directory_path() / ("lenslab-environment-test-" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } folder;
  fs::create_directories(folder.path);
  return folder.path / name;
}

void writeExr(const fs::path& path, int width, int height, int channels, float value) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  ASSERT_TRUE(out->open(path.string(), spec));
  std::vector<float> pixels(static_cast<std::size_t>(width) * height * channels, value);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] += 0.001f * static_cast<float>(i % 97);
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  out->close();
}

TEST(EnvironmentCache, SecondLoadIsAHitWithIdenticalData) {
  const fs::path file = scratch("sky.exr");
  writeExr(file, 32, 16, 3, 0.5f);
  const fs::path cache = scratch("cache");
  fs::remove_all(cache);
  const LoadedEnvironment first = loadEnvironment(file, smallSettings(), cache);
  EXPECT_FALSE(first.fromCache);
  EXPECT_EQ(first.warning, "");
  const LoadedEnvironment second = loadEnvironment(file, smallSettings(), cache);
  EXPECT_TRUE(second.fromCache);
  EXPECT_EQ(second.maps->background.rgb, first.maps->background.rgb);
  EXPECT_EQ(second.maps->diffuse.rgb, first.maps->diffuse.rgb);
  for (std::size_t l = 0; l < first.maps->specular.size(); ++l)
    EXPECT_EQ(second.maps->specular[l].rgb, first.maps->specular[l].rgb);
  // Other settings: another entry.
  PrefilterSettings other = smallSettings();
  other.samplesPerTexel = 32;
  EXPECT_FALSE(loadEnvironment(file, other, cache).fromCache);
  // A corrupt entry is computed again (and replaced).
  for (const auto& entry : fs::directory_iterator(cache)) {
    std::fstream f(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    f.put('x');
  }
  const LoadedEnvironment third = loadEnvironment(file, smallSettings(), cache);
  EXPECT_FALSE(third.fromCache);
  EXPECT_EQ(third.maps->diffuse.rgb, first.maps->diffuse.rgb);
  EXPECT_TRUE(loadEnvironment(file, smallSettings(), cache).fromCache);
}

TEST(EnvironmentCache, UnwritableFolderIsOnlyAWarning) {
  const fs::path file = scratch("plain.exr");
  writeExr(file, 16, 8, 4, 1.0f);
  const fs::path blocker = scratch("not-a-folder");
  std::ofstream(blocker) << "x";
  const LoadedEnvironment loaded = loadEnvironment(file, smallSettings(), blocker / "lenslab");
  EXPECT_FALSE(loaded.fromCache);
  EXPECT_NE(loaded.warning, "");
  ASSERT_TRUE(loaded.maps);
}

TEST(EnvironmentFile, RefusesBadFilesInOneLine) {
  const auto message = [](const fs::path& path) {
    try {
      readEnvironmentImage(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const fs::path twoChannels = scratch("two.exr");
  writeExr(twoChannels, 16, 8, 2, 1.0f);
  EXPECT_NE(message(twoChannels).find("3 (RGB) or 4 (RGBA)"), std::string::npos);
  const fs::path square = scratch("square.exr");
  writeExr(square, 16, 16, 3, 1.0f);
  EXPECT_NE(message(square).find("twice as wide as high"), std::string::npos);
  const fs::path negative = scratch("negative.exr");
  writeExr(negative, 16, 8, 3, -1.0f);
  EXPECT_NE(message(negative).find("finite and ≥ 0"), std::string::npos);
  EXPECT_NE(message(scratch("sky.png")).find(".hdr or .exr"), std::string::npos);
  for (const fs::path& p : {twoChannels, square, negative}) {
    const std::string m = message(p);
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_NE(m.find(p.string()), std::string::npos);
  }
}

TEST(EnvironmentFile, ReadsOnlyRegularFilesOfABoundedSizeWhoseHeaderTheBytesCanHold) {
  // Through the bounded reader (core/TextFile.h), both ways in: the image alone and the cached load.
  const auto messages = [](const fs::path& path) {
    std::vector<std::string> out;
    for (int way = 0; way < 2; ++way) {
      try {
        if (way == 0)
          readEnvironmentImage(path);
        else
          loadEnvironment(path, smallSettings(), std::nullopt);
        out.push_back("");
      } catch (const InputError& e) {
        out.push_back(e.what());
      }
    }
    return out;
  };
  const fs::path fifo = scratch("fifo.hdr");
  for (const char* name : {"fifo.hdr", "folder.hdr", "zero.exr"}) fs::remove(scratch(name));
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);  // opened for reading, it would block forever
  const fs::path folder = scratch("folder.hdr");
  fs::create_directories(folder);
  const fs::path zero = scratch("zero.exr");
  fs::create_symlink("/dev/zero", zero);  // read to its end, it would fill memory
  // A 150-byte Radiance header claiming 65536 × 32768, and one claiming 4096 × 2048 in 60 bytes.
  const fs::path huge = scratch("huge.hdr"), short_ = scratch("short.hdr");
  std::ofstream(huge, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32768 +X 65536\n"
                                        << std::string(100, '\x02');
  std::ofstream(short_, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2048 +X 4096\n"
                                          << std::string(10, '\x02');
  // Files that are not what their names say: a PNG (8-bit sRGB, taken for radiance it would be
  // silently wrong), text, a Radiance image named .exr.
  const fs::path png = scratch("png.hdr"), text = scratch("text.hdr"), radiance = scratch("radiance.exr");
  std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\n" << std::string(100, '\0');
  std::ofstream(text, std::ios::binary) << "sky, 4 by 2\n";
  std::ofstream(radiance, std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n"
                                            << std::string(32, '\x02');
  const std::pair<fs::path, std::string> cases[] = {
      {fifo, "not a regular file"},
      {folder, "is a folder"},
      {zero, "not a regular file"},
      {huge, "at most 16384 × 8192"},
      {short_, "cannot hold them"},
      {png, "the file is a PNG image, not the Radiance HDR image its name says"},
      {text, "the file is not the Radiance HDR image its name says"},
      {radiance, "the file is a Radiance HDR image, not the OpenEXR image its name says"},
  };
  for (const auto& [path, expected] : cases)
    for (const std::string& m : messages(path)) {
      EXPECT_NE(m.find(expected), std::string::npos) << path << ": " << m;
      EXPECT_NE(m.find(path.string()), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

// The frame plan counts the environment's blur: at infinity, beyond the scene's bounds. A small
// scene near the plane of focus alone would ask for few samples, and the sky behind it is blurred
// by the whole aperture.
TEST(EnvironmentPlan, SamplesCoverTheBlurAtInfinity) {
  const fs::path assets = LENSLAB_UNIT_ASSET_DIR;
  Scene scene = loadGltf(assets / "rows/rows.gltf");
  const Camera camera = loadCameraJson(assets / "rows/camera-dof.json").camera;  // focused at 2 m
  // Only the instance nearest the plane of focus (the floor, which runs under the camera, would
  // have the largest circle on its own).
  const auto distance = [&](const Instance& i) {
    Scene one = scene;
    one.instances = {i};
    const glm::dvec3 eye = camera.view.vrp + camera.view.prp.z * glm::normalize(camera.view.vpn);
    return std::abs(glm::length(computeBounds(one).center() - eye) - 1.0 / camera.inverseFocusDistance()) +
           (glm::length(computeBounds(one).size()) > 10.0 ? 1e9 : 0.0);
  };
  const Instance nearest =
      *std::min_element(scene.instances.begin(), scene.instances.end(),
                        [&](const Instance& a, const Instance& b) { return distance(a) < distance(b); });
  scene.instances = {nearest};
  scene.bounds = computeBounds(scene);
  const ImageSize size{480, 320};
  const FramePlan plain = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 0, 4096, 1});
  scene.environment =
      std::make_shared<const EnvironmentLookup>(std::make_shared<const PrefilteredEnvironment>(prefilterEnvironment(
                                                    constantImage(16, glm::vec3(1.0f)), smallSettings())),
                                                EnvironmentPlacement{});
  const FramePlan lit = makeFramePlan(scene, camera, size, PlanOptions{AperturePattern::Sobol, 0, 4096, 1});
  EXPECT_TRUE(std::isinf(lit.depthMax));
  const double atInfinity = cocDiameterOnWindow(camera, std::numeric_limits<double>::infinity(), 0.0) * size.widthPx /
                            camera.view.window.width();
  EXPECT_GE(lit.cocMaxPx, atInfinity * (1.0 - 1e-9));
  EXPECT_GT(lit.cocMaxPx, plain.cocMaxPx);
  EXPECT_GE(lit.apertureSamples, plain.apertureSamples);
  // The visible blur: a view of nothing but the environment has infinity's circle everywhere.
  const std::vector<double> nothing(static_cast<std::size_t>(60 * 40), std::numeric_limits<double>::infinity());
  EXPECT_EQ(visibleBlur(camera, size, {60, 40}, nothing).maxPx, 0.0);
  EXPECT_NEAR(visibleBlur(camera, size, {60, 40}, nothing, true).maxPx, atInfinity, 1e-6 * atInfinity);
}

}  // namespace
}  // namespace lenslab
