#pragma once
// A JSON-lines file that several processes append to at once (capture's manifest.jsonl, one line
// per frame from every shard). Each line goes out in one write(2) on a descriptor opened with
// O_APPEND, under an exclusive flock(2) that every lenslab writer takes: lines from different
// processes never interleave, and a writer that finds the file ending in part of a line (a full
// disk, a kill mid-write) cuts that part off before appending, with nobody appending meanwhile.
// A write that fails partway is cut back to the size before it, so the file stays valid JSON
// lines. (NFS keeps neither O_APPEND's nor flock's promise across machines: there give each shard
// its own file.)
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

// Appends `line` and a newline (one write, fsync'ed). Throws InputError naming the file; the file
// then holds no part of the line.
void appendLine(const std::filesystem::path& file, const std::string& line);

// Throws InputError naming `option` and the file when an existing `file` cannot be appended to (a
// read-only file, a folder): checked before any work, like io/OutputPath.h's checks.
void checkAppendable(const std::filesystem::path& file, std::string_view option);

// The complete lines of `file` (each ended by a newline; a last line without one is not yet
// written, or cut short, and is left out). No file: none. Throws InputError naming the file.
std::vector<std::string> readCompleteLines(const std::filesystem::path& file);

}  // namespace lenslab
