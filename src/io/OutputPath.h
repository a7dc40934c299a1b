#pragma once
// Every file a command will write is checked before any work starts, so that a typo or a
// read-only folder fails in a second, not after a long render, and never after another output
// has already been written. A check cannot reserve space: a disk that fills up during the run is
// caught by AtomicFile's checked writes instead.
#include <filesystem>
#include <string_view>

namespace lenslab {

enum class OutputKind {
  Image,      // .png or .exr (io/ImageFile.h)
  Json,       // .json
  JsonLines,  // .jsonl or .json (capture's manifest, appended line by line)
  Any,        // any name (the sweep's fixed report names)
};

// Throws InputError, one line naming the option and the file, unless: the extension suits `kind`;
// the path is not a folder; its name fits the file system (NAME_MAX); its folder exists, is a folder, and takes a new file (a probe file is
// created, written, and removed there — this also finds a read-only file system, a full disk and
// missing permissions, whoever runs it). `option` is the flag the path came from ("--stats").
void checkOutputPath(const std::filesystem::path& path, OutputKind kind, std::string_view option);

// Throws InputError unless `output` (from `option`) is a file other than `input` (read as
// `inputOption`): writing a report over the camera file it came from loses the user's camera.
// Compared as the files they are (links and ./ spellings included) when both exist.
void checkNotInput(const std::filesystem::path& output, std::string_view option, const std::filesystem::path& input,
                   std::string_view inputOption);

}  // namespace lenslab
