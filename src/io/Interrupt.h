#pragma once
// Ctrl-C, SIGTERM (a cluster's scheduler ending a job) and SIGHUP (a closed terminal) remove what
// the run had not finished: the temporary files of uncommitted OutputSets (io/AtomicFile.h), the
// folders it made that are still empty, and a frame whose manifest line is not yet written. The
// process then exits 128 + the signal's number with one line on stderr:
//   lenslab: interrupted (SIGINT); removed 1 unfinished file
//
// Design: installInterruptHandling() blocks these signals in every thread (llvmpipe's and TBB's
// threads inherit the mask) and waits for them with sigwait(2) on a thread of its own, so the
// removal runs as ordinary code, not in a signal handler, and works at any moment — during one
// long tile render as between frames. What to remove is a list kept in memory; code that must not
// be cut in half (renaming a set of files into place, a frame's image and its manifest line)
// holds InterruptDeferral meanwhile, and the removal waits for it.
//
// SIGXFSZ (a file size limit, `ulimit -f`) is ignored instead: write(2) then fails with EFBIG,
// which the checked writes report like a full disk, naming the file.
#include <cstdint>
#include <filesystem>
#include <mutex>

namespace lenslab {

// Called once by main before any thread starts. Without it (unit tests) the list is kept, unused.
void installInterruptHandling();

// Adds `path` to what an interruption removes: a file (unlinked) or a folder (removed if empty,
// after the files, the last added first). Returns a handle for forgetRemoveOnInterrupt.
enum class RemovalKind { File, Folder };
std::uint64_t removeOnInterrupt(const std::filesystem::path& path, RemovalKind kind);
void forgetRemoveOnInterrupt(std::uint64_t handle);

// While one is alive, an interruption waits (in its own thread) before removing anything: the
// steps in its scope happen all or, on the next start, not at all. Hold one briefly. Nests.
class InterruptDeferral {
 public:
  InterruptDeferral();
  ~InterruptDeferral();
  InterruptDeferral(const InterruptDeferral&) = delete;
  InterruptDeferral& operator=(const InterruptDeferral&) = delete;

 private:
  std::unique_lock<std::recursive_mutex> lock_;
};

}  // namespace lenslab
