#pragma once
// The lens pass: distortion and lateral chromatic aberration. The tables of the inverse and the
// forward lens model (the frame's ThinLensMap, camera/ImageMap.h) are built here and rebuilt only when the lens, the window
// or the sizes change, not per frame (a tiled render's tiles each have their own window: each tile
// builds the tables for its pixels and its overscan alone). They are filled and uploaded a band of
// rows at a time, so that the CPU holds one band (kTableBandRows), never a whole table. With many
// aperture views the accumulator uses them to carry each view's samples to where the lens puts
// them (Accumulator::LensGather, exact in the limit); a single view is remapped here, bilinearly,
// through the inverse table.
#include "camera/Camera.h"
#include "camera/ImageSize.h"
#include "camera/ImageMap.h"
#include "gl/Framebuffer.h"
#include "gl/FullScreenPass.h"
#include "gl/Object.h"
#include "render/Accumulator.h"

#include <functional>
#include <vector>

namespace lenslab {

class LensPass {
 public:
  LensPass();  // needs a current context

  // Makes the tables for the frame's map (its camera, image size and overscan); a no-op when nothing
  // changed since the last call.
  // The forward tables (for gather()) only when `forGather`: a single view needs the inverse alone.
  // `progress(table, rowsDone, rows)` as each table ("inverse" or "forward") fills: for a large
  // image they take tens of seconds on the CPU.
  using TableProgress = std::function<void(const char* table, int rowsDone, int rows)>;
  static constexpr int kTableBandRows = 32;  // at least, per band of a table (more with more cores)
  void prepare(const ThinLensMap& map, bool forGather = true, const TableProgress& progress = {});
  // Remaps `undistorted` (one overscanned view) into `out` (the image size), bilinearly.
  void apply(const gl::RenderTarget& undistorted, const gl::RenderTarget& out);
  // The tables for the accumulator's per-view gather (after prepare with forGather).
  const Accumulator::LensGather& gather() const { return gather_; }
  int tablesBuilt() const { return tablesBuilt_; }  // how many times prepare rebuilt the tables

 private:
  gl::Program program_;
  gl::Program perChannelProgram_;  // the lateral-colour variant, built on first use
  gl::FullScreenPass fullScreen_;
  std::vector<gl::Texture> tables_;  // RG32F texture coordinates: green, or red, green, blue
  gl::Texture forwardPosition_;      // RGBA32F at the overscan size (ForwardTable)
  gl::Texture forwardJacobian_;
  Accumulator::LensGather gather_;
  std::vector<double> key_;  // what the tables were made for
  int tablesBuilt_ = 0;
};

}  // namespace lenslab
