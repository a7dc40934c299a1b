#pragma once
// Points on the aperture at which the PRP is placed, one scene pass each, and the sub-pixel
// offset that pass uses (box-filtered anti-aliasing comes with the same samples).
//
// The lecture: "every pixel generates many rays toward different points on the lens … arrange
// points in spherical pattern: two radii every 45 degrees + centre = 17 points".
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

enum class AperturePattern {
  Lecture17,   // the lecture's 17: centre + radii 1/2 and 1 every 45°
  Concentric,  // stratified (jittered grid) through Shirley–Chiu's concentric square→disk map
  R2,          // Roberts' R-sequence (here in four dimensions): lens from two, pixel from two
  Random,      // independent uniform points, for comparison
  Sobol,       // Owen-scrambled Sobol' points in two interleaved streams: every prefix well spread
               // (lens/SobolSequence.h); the progressive order that per-tile budgets stop early in
  Rings,       // one point in each of N equal-area cells, rings of sectors (lens/ApertureCells.h):
               // the cells the cell filter gives each view
};

const char* patternName(AperturePattern pattern);
std::optional<AperturePattern> patternFromName(const std::string& name);
std::string patternNames();                  // "lecture17, concentric, r2, random"
std::vector<std::string> patternNameList();  // the same, one name each, in AperturePattern's order

struct LensSample {
  glm::dvec2 lens;   // on the unit disk; scale by the aperture radius
  glm::dvec2 pixel;  // sub-pixel offset in [−0.5, 0.5)², in pixels
};

// `count` samples (Lecture17 always gives 17). The same seed gives the same samples.
std::vector<LensSample> makeApertureSamples(AperturePattern pattern, int count, std::uint32_t seed);

// Shirley and Chiu's concentric map from [0, 1)² onto the unit disk: area-preserving, and it keeps
// strata compact (squares map to wedges of rings).
glm::dvec2 concentricDisk(glm::dvec2 u);
// Its inverse: the point of [0, 1)² that concentricDisk sends to `disk` (outside [0, 1]² for a point
// outside the unit disk). shaders/accumulate/cell_filter.frag has the same in GLSL.
glm::dvec2 concentricSquare(glm::dvec2 disk);

}  // namespace lenslab
