#pragma once
// Image files through OpenImageIO. By extension: .png is 8-bit sRGB (the transfer function
// applied here, values clamped to [0, 1]; an exposure and a view transform, when a command asks
// for them, are applied before: applyDisplayForFile); .exr is linear 32-bit float, unclamped.
// Writing is atomic (see AtomicFile.h): a failed run leaves no partial file.
#include "core/Image.h"
#include "io/AtomicFile.h"
#include "io/ToneMap.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Throws InputError naming the path when its extension is neither .png nor .exr. Call it before
// long work, so that a typo fails at once.
void checkImageExtension(const std::filesystem::path& path);

// The file's bytes, encoded in memory. OIIO's PNG writer reports a failed write(2) only through
// has_error() and still returns true from write_image() and close(), without errno's reason: so
// OIIO never touches the disk here, and AtomicFile's checked writes do.
// `depthZ`, when given (width × height values, rows from the top), becomes the EXR's Z channel
// (OpenEXR's name for depth; spec.z_channel); only .exr holds it.
std::string encodeImage(const std::filesystem::path& path, const Image& linear,
                        const std::vector<float>* depthZ = nullptr);

// A float channel an EXR holds beside R, G, B, A: its name (OpenEXR's, e.g. "Z", "N.X") and one
// value a pixel, rows from the top.
struct ImageChannel {
  std::string name;
  std::vector<float> values;
};
// As above with any number of extra channels, written in this order after R, G, B, A (readers
// find them by name: OpenEXR itself stores channels sorted by name). A channel named "Z" is the
// depth (spec.z_channel). Only .exr holds them; a .png with channels is refused naming them.
std::string encodeImage(const std::filesystem::path& path, const Image& linear,
                        const std::vector<ImageChannel>& channels);

// Where an image holds radiance past a float's range (a pixel of ∞ or NaN: lights or emission
// brighter than 3.4e38), the one-line warning that says how many pixels and what to
// do; nullopt where every value is finite.
std::optional<std::string> radianceOverflowWarning(const Image& linear);

// One file, whole or not at all.
void writeImage(const std::filesystem::path& path, const Image& linear);
// Into `outputs`: the target appears when the set is committed, with the run's other files.
void writeImage(OutputSet& outputs, const std::filesystem::path& path, const Image& linear,
                const std::vector<float>* depthZ = nullptr);
void writeImage(OutputSet& outputs, const std::filesystem::path& path, const Image& linear,
                const std::vector<ImageChannel>& channels);

// Reads PNG/EXR (or anything OIIO reads) into linear RGBA; 8-bit files are decoded from sRGB.
Image readImage(const std::filesystem::path& path);
// The Z channel of an EXR (rows from the top). Throws InputError when the file has none.
std::vector<float> readDepthChannel(const std::filesystem::path& path);
// The channel called `name` of an image file (rows from the top). Throws InputError when it has none.
std::vector<float> readChannel(const std::filesystem::path& path, const std::string& name);
// The names of an image file's channels, as its reader lists them.
std::vector<std::string> channelNames(const std::filesystem::path& path);

// What a PNG of the image holds before its sRGB encoding: `display`'s exposure and view transform
// (io/ToneMap.h) applied to the RGB of `image` in place, leaving display-referred linear values
// in [0, 1]; alpha is kept. An EXR is left as it is: it holds the linear radiance, never exposed
// or tone-mapped. Nothing changes for the identity encoding (the default), so that default PNGs
// cost and hold what they always did.
void applyDisplayForFile(const std::filesystem::path& path, Image& image, const DisplayEncoding& display);
// Whether a file of this name is exposed and shown through a view transform (a PNG), not linear.
bool isDisplayReferred(const std::filesystem::path& path);

float linearFromSrgb(float encoded);
float srgbFromLinear(float linear);

}  // namespace lenslab
