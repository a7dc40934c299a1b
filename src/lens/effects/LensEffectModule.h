#pragma once
// A lens effect is a module (../shared/ARCHITECTURE.md, "A lens effect is a module"; Mitsuba 3's
// one sensor, one file): each effect — distortion, lateral and axial colour, field curvature,
// vignetting, the barrel, the aperture shape — says in one place, for its part of a Lens (lens/Lens.h),
//   - its camera-file key and what the object under it holds (read and written through the small
//     KeyReader / KeyWriter below, which io/ implements on JSON: lens/ stays free of the JSON
//     library, and the effect's keys stay beside its model);
//   - how it is interpolated between two keys of a camera path;
//   - what a frame needs for it (plan/FramePlan asks every module; none adds anything at zero
//     strength): views per aperture sample, shader variants, the lens remap, a gain at the end;
//   - where its shader code lives.
// kLensEffectModules (LensEffectRegistry.h) lists them once; the camera reader and writer, the
// path's interpolation and the frame plan iterate it instead of naming effects.
#include "lens/Lens.h"

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lenslab {

// What some keys need of the camera they belong to: the axial colour's and the field curvature's
// keys are focus distances, held as shifts of the camera's own 1/z_f.
struct LensFrame {
  std::string where;          // the file (reading) or the camera's source (writing), for messages
  double inverseFocus = 0.0;  // the camera's 1/z_f (green's; 0 at infinity)
  double cornerRadius = 1.0;  // normalised radius of the window's farthest corner
  bool perspective = true;
  std::optional<double> focalLength;  // world units, when the camera came in the physical form
};

// One object of a camera file, as a module reads it. Every method that finds something wrong
// throws InputError naming the file and the key ("<file>: \"vignetting.a1\" must be a number ...").
class KeyReader {
 public:
  virtual ~KeyReader() = default;
  virtual bool has(const std::string& key) const = 0;
  virtual bool isArray(const std::string& key) const = 0;
  virtual double number(const std::string& key) const = 0;    // finite
  virtual double distance(const std::string& key) const = 0;  // a number or "infinity"
  virtual int integer(const std::string& key) const = 0;
  virtual std::size_t arraySize(const std::string& key) const = 0;
  // The array's i-th element when it is a finite number.
  virtual std::optional<double> element(const std::string& key, std::size_t i) const = 0;
  virtual std::string text(const std::string& key) const = 0;    // the value as the file wrote it
  virtual std::string string(const std::string& key) const = 0;  // a JSON string's value
  [[noreturn]] virtual void fail(const std::string& key, const std::string& message) const = 0;
  // "<file>: \"key\" is missing; the <form> form needs it" when absent.
  virtual void require(const std::string& key, const std::string& form) const = 0;
  // The object under `key`, with keys named "key.sub" in messages; a key outside `allowed` is refused.
  virtual std::unique_ptr<KeyReader> object(const std::string& key, const std::set<std::string>& allowed) const = 0;
};

// One object of a camera file, as a module writes it.
class KeyWriter {
 public:
  virtual ~KeyWriter() = default;
  virtual void number(const std::string& key, double value) = 0;
  virtual void integer(const std::string& key, int value) = 0;
  virtual void distance(const std::string& key, double value) = 0;  // +infinity as "infinity"
  virtual void string(const std::string& key, const std::string& value) = 0;
  virtual KeyWriter& object(const std::string& key) = 0;  // a new object under `key`
};

// What the frame plan knows of the view when it asks a module (the aperture is the lens's).
struct PlanView {
  double inverseFocus = 0.0;         // 1/z_f
  double farthestCornerSlope = 0.0;  // normalised radius of the rendered window's farthest corner
};

// What a frame needs for its effects: the renderer's mechanisms, each module asking for those it
// uses. Effects on one mechanism share it (distortion and lateral colour: one remap pass).
struct EffectNeeds {
  int viewsPerSample = 1;                  // 3: one view per colour channel at each aperture point
  std::vector<std::string> sceneVariants;  // variants of each view's scene pass ("field-curvature")
  bool fieldCurvatureWarp = false;         // the views are summed through the curved focal surface's warp
  std::vector<std::string> lensVariants;   // the lens remap pass runs when any ("distortion")
  int remapTables = 0;                     // its inverse lookup tables: 1 (one image) or 3 (per channel)
  std::string finalGain;                   // a gain on the finished image, in words for --stats
  bool idleThroughPinhole = false;         // an effect here changes nothing without an aperture
  int minApertureSamples = 0;              // views the frame takes at least, and why
  std::string minSamplesWhy;
};

struct LensEffectModule {
  const char* key;            // its camera-file key: "vignetting"
  const char* shaderSnippet;  // its shader code under shaders/, "" for none
  // Reads the module's key from the camera's object when present, onto `lens`.
  void (*read)(const KeyReader& camera, const LensFrame& frame, Lens& lens);
  // Writes the module's key into the camera's object when the effect is present.
  void (*write)(const Lens& lens, const LensFrame& frame, KeyWriter& camera);
  // Sets the module's part of `out` between keys `a` (u = 0) and `b` (u = 1).
  void (*interpolate)(const Lens& a, const Lens& b, double u, Lens& out);
  // Adds what a frame needs for the effect; nothing at zero strength.
  void (*plan)(const Lens& lens, const PlanView& view, EffectNeeds& needs);
};

// Helpers the modules share.
inline double lerpValue(double a, double b, double u) { return a + (b - a) * u; }
// A focus distance for an inverse distance (0 → +infinity); refused below 0, where "beyond infinity"
// has no distance to write: "<where>: <key> lies beyond infinity ...".
double distanceForInverse(double inverse, const LensFrame& frame, const std::string& key);
// 1/distance for a focus distance read from `reader` ("infinity" → 0); refused at ≤ 0.
double inverseOfDistance(const KeyReader& reader, const std::string& key);

}  // namespace lenslab
