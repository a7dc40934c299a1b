#pragma once
// The AOVs (arbitrary output variables) lenslab writes beside an image (`--aov` of render, raycast
// and capture): per pixel, what the first surface seen through the pixel centre is. They are
// ground truth for vision work, so each is one exact value per pixel, not an average: the ray from
// the lens centre through the pixel centre (through the inverse lens model, green's, when the lens
// distorts), whatever the aperture, focus or pixel filter of the image beside them.
#include <string>
#include <vector>

namespace lenslab {

// Which AOVs a run writes.
struct AovSelection {
  bool depth = false;     // distance along the optical axis from the lens centre, world units
  bool normal = false;    // the shading normal, camera space (u right, v up, n toward the viewer)
  bool albedo = false;    // the base colour the renderers shade: factor × texture × vertex colour
  bool instance = false;  // the glTF node index of the instance hit
  bool flow = false;      // capture: each pixel's motion to the next frame, pixels (camera/OpticalFlow.h)

  bool any() const { return depth || normal || albedo || instance || flow; }
  // The selected names, in the order above (as the manifest lists them).
  std::vector<std::string> names() const;
};

// The names --aov takes, in the order AovSelection lists them.
const std::vector<std::string>& aovNames();

// The selection `names` ask for (each one of aovNames(), repeats allowed). Throws InputError
// naming `option`, the unknown name and the valid ones.
AovSelection parseAovs(const std::vector<std::string>& names, const std::string& option = "--aov");

// "depth,normal": the selection as --aov writes it.
std::string aovList(const AovSelection& selection);

// The instance AOV where no surface is seen (glTF node indices are ≥ 0).
constexpr float kNoSurfaceInstance = -1.0f;
// The largest node index the instance AOV holds (a float holds every integer up to 2^24); a scene
// with a larger one is refused when the instance AOV is asked for.
constexpr int kMaxExactInstance = 1 << 24;

// The AOV images of one frame, rows from the top; only the selected ones are filled.
struct AovImages {
  int widthPx = 0;
  int heightPx = 0;
  std::vector<float> depth;   // 1 a pixel; +infinity where nothing is hit (OpenEXR's Z)
  std::vector<float> normal;  // 3 a pixel (x, y, z in camera space), unit; 0, 0, 0 where nothing is hit
  std::vector<float> albedo;  // 3 a pixel, linear RGB; 0, 0, 0 where nothing is hit
  std::vector<float>
      instance;  // 1 a pixel, an exact integer (float holds them to 2^24); kNoSurfaceInstance where nothing is hit
  std::vector<float> flow;  // 2 a pixel (x right, y down, pixels); NaN where unknown
};

}  // namespace lenslab
