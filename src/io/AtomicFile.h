#pragma once
// Output files appear whole or not at all, and the files of one run appear together or not at all.
//
// Each file is first written to a temporary file beside its target (same folder, so that rename is
// atomic; a short dot name, ".lenslab-PID-TOKEN-N.EXT", so that it does not look like a result and
// fits wherever the target's name fits, up to NAME_MAX). Every write(2), the fsync(2) of the
// data and the close(2) are checked: a full disk shows as an error here, not as a short file later.
// commit() then renames every temporary file onto its target and fsyncs the folders, so that after
// a crash a name points either at the old file or at the whole new one.
//
// Until commit() no target is touched. If the set is destroyed uncommitted — a write failed, the
// disk filled up, any exception on the way — the temporary files are removed, and so are the
// folders createFolders() made (when empty): nothing new is left. An interruption (Ctrl-C, SIGTERM;
// io/Interrupt.h) removes the same, and waits for a commit() under way to finish.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Creates `folder` and its missing parents now; those this call made are removed again (if
  // still empty) when the set is not committed. Throws InputError naming the folder.
  void createFolders(const std::filesystem::path& folder);

  // Writes `bytes` to a new temporary file beside `target`, fsync'ed. Throws InputError naming the
  // target and the reason ("No space left on device"); the temporary file is then already gone.
  void add(const std::filesystem::path& target, std::string_view bytes);

  // For a file another library writes in pieces (a tiled image, strip by strip through
  // OpenImageIO): the temporary path beside `target` for it to write to and close. It is part of
  // the set from now on: removed if the set is not committed; its data fsync'ed by commit()
  // before the rename. The writer must check its own writes (and close) as add() does.
  std::filesystem::path addStreamed(const std::filesystem::path& target);

  // Renames each temporary file onto its target (in the order added), then fsyncs their folders.
  // Should one fail, the targets this call had already created are removed before it throws;
  // a target that replaced an older file cannot be given its old content back.
  void commit();

 private:
  struct Entry {
    std::filesystem::path target;
    std::filesystem::path temporary;
    bool streamed = false;              // written by someone else: fsync'ed at commit()
    std::uint64_t interruptHandle = 0;  // the temporary file in io/Interrupt.h's list
  };
  std::vector<Entry> entries_;
  std::vector<std::filesystem::path> createdFolders_;  // outermost first
  std::vector<std::uint64_t> folderHandles_;           // the same in io/Interrupt.h's list
  bool committed_ = false;
};

// A file of an OutputSet that lenslab writes a piece at a time (a COLMAP model of millions of
// frames): memory holds a buffer of it, never the whole. Opened as add() opens its file; every
// write(2) and the close(2) checked as add()'s are; its data fsync'ed by the set's commit().
class StreamedFile {
 public:
  StreamedFile(OutputSet& set, const std::filesystem::path& target);
  ~StreamedFile();  // closes the descriptor: the set removes the file unless it is committed
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;
  // Appends `bytes` (buffered). Throws InputError naming the target and the reason.
  void write(std::string_view bytes);
  // Replaces bytes already written at `offset` (a count in a file's header, known at the end),
  // checked as write() is. The file's length does not change where the bytes were written.
  void overwrite(std::uint64_t offset, std::string_view bytes);
  // Writes what is buffered and closes; call before the set's commit(). Throws as write().
  void close();

 private:
  void flush();
  std::filesystem::path target_;
  int fd_ = -1;
  std::string buffer_;
};

// The set of one file: writes `bytes` to `target` atomically (checked, fsync'ed, renamed).
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);
void writeTextFileAtomically(const std::filesystem::path& target, std::string_view text);

}  // namespace lenslab
