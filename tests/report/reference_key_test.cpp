// The sweep's cached ray-cast reference is keyed on its inputs' bytes (report/ReferenceCache.h):
// the same inputs give the same key wherever they lie; a changed byte in the scene's glTF, its
// buffer or an image, or in the camera, environment or lens file, gives another; so does a changed
// option. (No GL needed; it lives beside the sweep, in the GL tests' executable.)
#include "io/CameraJson.h"
#include "report/ReferenceCache.h"
#include "scene/GltfLoader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

namespace lenslab {
namespace {
namespace fs = std::filesystem;

// A copy of the bundled `rows` scene (a .gltf with a .bin buffer and PNG textures) in a scratch
// folder, so that its files can be changed byte by byte.
class ReferenceKey : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lenslab-reference-key-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy(fs::path(LENSLAB_TEST_ASSET_DIR) / "rows", dir_ / "rows", fs::copy_options::recursive);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string keyOf(const fs::path& sceneFile, const SweepOptions& options = {}) const {
    const Scene scene = loadGltf(sceneFile);
    return referenceKey(scene, camera_, size_, options);
  }
  // Flips the lowest bit of the byte at `offset` of `file`, in place.
  static void flipBit(const fs::path& file, std::streamoff offset) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(offset);
    const char c = static_cast<char>(f.get());
    f.seekp(offset);
    f.put(static_cast<char>(c ^ 0x01));
  }
  static void appendByte(const fs::path& file, char byte) {
    std::ofstream(file, std::ios::app | std::ios::binary) << byte;
  }

  fs::path dir_;
  Camera camera_ = loadCameraJson(fs::path(LENSLAB_TEST_ASSET_DIR) / "rows/camera-dof.json").camera;
  ImageSize size_{64, 48};
};

TEST_F(ReferenceKey, SameInputsSameKey) {
  const fs::path scene = dir_ / "rows/rows.gltf";
  const std::string base = keyOf(scene);
  EXPECT_EQ(base.size(), 16u);
  EXPECT_EQ(keyOf(scene), base) << "loaded again";
  fs::copy(dir_ / "rows", dir_ / "rows-moved", fs::copy_options::recursive);
  EXPECT_EQ(keyOf(dir_ / "rows-moved/rows.gltf"), base) << "the same bytes in another folder";
  EXPECT_NE(keyOf(fs::path(LENSLAB_TEST_ASSET_DIR) / "occluder/occluder.gltf"), base) << "another scene";
}

TEST_F(ReferenceKey, ChangesWithAByteOfAnyFileTheSceneReads) {
  const fs::path scene = dir_ / "rows/rows.gltf";
  const Scene loaded = loadGltf(scene);
  EXPECT_EQ(loaded.files.size(), 6u) << "the .gltf, its buffer and its four images";
  const std::string base = keyOf(scene);
  std::set<std::string> keys{base};
  // Each change keeps the scene loadable and its pixels all but equal: the lowest bit of the first
  // vertex's y (rows.bin bytes 4–7 are that float, little-endian), a byte after a PNG's end (which
  // decoders ignore), a space at the end of the glTF's JSON.
  const std::pair<const char*, std::function<void()>> changes[] = {
      {"a bit of the buffer", [&] { flipBit(dir_ / "rows/rows.bin", 4); }},
      {"a byte after an image's end", [&] { appendByte(dir_ / "rows/bricks.png", '\0'); }},
      {"a space in the glTF", [&] { appendByte(scene, ' '); }},
  };
  for (const auto& [what, change] : changes) {
    change();
    const std::string after = keyOf(scene);
    EXPECT_NE(after, base) << what;
    keys.insert(after);
  }
  EXPECT_EQ(keys.size(), 4u) << "every change its own key";
}

TEST_F(ReferenceKey, ChangesWithItsOtherFiles) {
  const fs::path scene = dir_ / "rows/rows.gltf";
  const fs::path cameraFile = dir_ / "rows/camera-dof.json";
  SweepOptions options;
  options.inputFiles = {cameraFile};
  const std::string base = keyOf(scene, options);
  EXPECT_NE(base, keyOf(scene)) << "a camera file given";
  std::ofstream(cameraFile, std::ios::app) << "\n";  // a byte more: the same camera, another file
  EXPECT_NE(keyOf(scene, options), base) << "the camera file's bytes";
}

TEST_F(ReferenceKey, ChangesWithEachOption) {
  const Scene scene = loadGltf(dir_ / "rows/rows.gltf");
  const SweepOptions options;
  const std::string base = referenceKey(scene, camera_, size_, options);
  std::set<std::string> keys{base};
  const auto differs = [&](const std::string& key, const char* what) {
    EXPECT_NE(key, base) << what;
    keys.insert(key);
  };
  SweepOptions withOption = options;
  withOption.inputOptions = {"background 0 0 0"};
  differs(referenceKey(scene, camera_, size_, withOption), "an option");
  withOption.inputOptions = {"background 0 0 1e-9"};
  differs(referenceKey(scene, camera_, size_, withOption), "its value");
  withOption.inputOptions = {"background 0 0", "0"};
  differs(referenceKey(scene, camera_, size_, withOption), "the same text cut in two");
  SweepOptions spp = options;
  spp.referenceSpp = options.referenceSpp + 2;
  differs(referenceKey(scene, camera_, size_, spp), "--reference-spp");
  SweepOptions seed = options;
  seed.seed = options.seed + 1;
  differs(referenceKey(scene, camera_, size_, seed), "--seed");
  differs(referenceKey(scene, camera_, ImageSize{64, 49}, options), "the size");
  Camera focus = camera_;
  focus.view.vrp.z += 1e-9;
  differs(referenceKey(scene, focus, size_, options), "the camera, by 1e-9");
  Camera aperture = camera_;
  aperture.lens.apertureRadius *= 1.0 + 1e-12;
  differs(referenceKey(scene, aperture, size_, options), "the aperture, by 1e-12 of it");
  EXPECT_EQ(keys.size(), 9u) << "every change its own key";
}

}  // namespace
}  // namespace lenslab
