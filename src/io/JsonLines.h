#pragma once
// A JSON-lines file that several processes append to at once (capture's manifest.jsonl, one line
// per frame from every shard). Each line goes out in one write(2) on a descriptor opened with
// O_APPEND: on a local file system the kernel moves to the end and writes under the inode's lock,
// so lines from different processes never interleave and the file stays valid JSON lines. (NFS
// does not keep that promise across machines: there give each shard its own file.)
#include <filesystem>
#include <string>

namespace lenslab {

// Appends `line` and a newline (one write, fsync'ed). Throws InputError naming the file.
void appendLine(const std::filesystem::path& file, const std::string& line);

}  // namespace lenslab
