#pragma once
// Input files read whole into memory, with the one-line error a user gets when one cannot be.
// Only a regular file is read, and only up to a limit: /dev/zero, a FIFO or a folder given as a
// camera file would otherwise be read until memory runs out (or block forever).
// Compiled into lenslab_core, so that the glTF loader reads through it too.
#include <cstdint>
#include <filesystem>
#include <string>

namespace lenslab {

// Camera JSON, camera paths and COLMAP text models: real ones are kilobytes to a few megabytes.
constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{64} << 20;
// An environment image (.hdr, .exr): 16384 × 8192 RGB floats are 1.5 GiB; files are smaller.
constexpr std::uintmax_t kMaxEnvironmentFileBytes = std::uintmax_t{2} << 30;
// A .gltf/.glb and its .bin buffers: glTF's own limit (lengths are 32-bit), 4 GiB.
constexpr std::uintmax_t kMaxGltfFileBytes = (std::uintmax_t{1} << 32) - 1;

// The bytes of `file`, a regular file of at most `maxBytes`. Throws InputError naming the file and
// `what` it should be: missing, a folder, not a regular file (a device, FIFO or socket), larger
// than the limit (named), or unreadable.
std::string readInputFile(const std::filesystem::path& file, const std::string& what, std::uintmax_t maxBytes);

// readInputFile with kMaxTextFileBytes, as text: a leading UTF-8 byte-order mark is dropped (editors
// write one), UTF-16 is refused by name (save it as UTF-8). LF and CRLF line ends are left to the
// parsers, which read both. (A glTF file is not read through here: the glTF spec forbids a BOM,
// and the loader refuses one by name.)
std::string readTextFile(const std::filesystem::path& file, const std::string& what);

}  // namespace lenslab
