#pragma once
// Which frames a capture process renders and what it names them (`lenslab capture`):
//   --out 'DIR/frame_%04d.exr'   one printf-style integer conversion (%d, %5d, %05d; %% is a %)
//   --frames A:B[:STEP]          frames A to B inclusive (A:, :B and a single N too), every STEP-th
//                                from A with a step (A, A+STEP, … ≤ B); default all
//   --shard I/N                  the I-th of N independent processes (0 ≤ I < N) takes every N-th
//                                frame of the range, starting at its I-th: interleaved rather than
//                                in blocks, so that a path whose cost changes along it (a rack focus
//                                into blur) spreads evenly over the shards. With a step the
//                                shards split the stepped frames the same way.
// A frame's seed depends only on the run's seed and the frame number, so one process and N shards
// render identical frames.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Throws InputError naming `option` unless the pattern holds exactly one integer conversion.
void checkFramePattern(const std::string& pattern, const std::string& option);
std::string formatFramePath(const std::string& pattern, int frame);

// The frame number whose file `pattern` names `path` (both taken as absolute, lexically normal
// paths), or nothing: a check that an output (a folder, a manifest) is not one of the frames' files
// without formatting every frame's name.
std::optional<int> frameNamedBy(const std::string& pattern, const std::filesystem::path& path);

struct FrameRange {
  int first = 0;
  int last = 0;  // inclusive, though with a step it may lie between two frames taken
  int step = 1;  // every step-th frame from `first`
};
// "A:B", "A:", ":B" or "N", within 0 … frameCount − 1, each range form with an optional ":STEP"
// (a whole number ≥ 1): "0:72:12", "::12", ":48:12", "6::12". Throws InputError naming --frames.
FrameRange parseFrameRange(const std::string& text, int frameCount);

struct Shard {
  int index = 0;
  int count = 1;
};
// "I/N" with 0 ≤ I < N. Throws InputError naming --shard.
Shard parseShard(const std::string& text);

// The frames of `range` that `shard` renders, in order: the I-th, (I+N)-th, … of the range's
// frames (first, first + step, … ≤ last).
std::vector<int> shardFrames(FrameRange range, Shard shard);
// Whether `frame` is one of the range's frames (first, first + step, … ≤ last).
bool inRange(FrameRange range, int frame);

// The seed of one frame: a hash of the run's seed and the frame number (never the shard).
std::uint32_t frameSeed(std::uint32_t seed, int frame);

// Beside `image`: frame_0001.exr → frame_0001.camera.json.
std::filesystem::path frameCameraPath(const std::filesystem::path& image);

}  // namespace lenslab
