#include "io/AtomicFile.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/Interrupt.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <random>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

std::atomic<unsigned> counter{0};

fs::path folderOf(const fs::path& file) { return file.has_parent_path() ? file.parent_path() : fs::path("."); }

// The temporary file's name: ".lenslab-PID-TOKEN-N.EXT", short whatever the target's name, so
// that a target named with all of NAME_MAX (255 bytes) still has a temporary file beside it; the
// extension is kept because OpenImageIO picks the format from it. The process id alone is not
// unique where processes on several machines write into one shared folder (shards of a cluster
// job, each container's process often with the same small pid) and may write the same target
// (capture --colmap-out): a random token drawn once per process keeps their temporary files apart.
fs::path temporaryFor(const fs::path& target) {
  static const unsigned token = std::random_device{}();
  std::string extension = target.extension().string();
  if (extension.size() > 16) extension.clear();  // not an image's: the name stays short
  return folderOf(target) /
         cat(".lenslab-", ::getpid(), "-", std::hex, token, std::dec, "-", counter++, ".tmp", extension);
}

InputError cannotWrite(const fs::path& target, int error) {
  return InputError(cat(target.string(), ": cannot write it: ", std::system_category().message(error)));
}

// write(2) until every byte is out: a short write is not an error by itself (a signal, a pipe),
// so go on; the call after it returns the reason (ENOSPC, EFBIG, EIO). Returns 0 or an errno.
int writeAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return ENOSPC;  // no progress and no reason: do not spin
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

// fsync(2) of a folder makes the renames in it durable. Some file systems cannot sync a folder
// (EINVAL): the rename is then as durable as that file system makes it, which is not an error.
int syncFolder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno;
  int error = ::fsync(fd) == 0 || errno == EINVAL ? 0 : errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  return error;
}

}  // namespace

OutputSet::~OutputSet() {
  if (committed_) return;
  std::error_code ignored;
  for (const Entry& e : entries_) {
    if (!e.temporary.empty()) fs::remove(e.temporary, ignored);
    forgetRemoveOnInterrupt(e.interruptHandle);
  }
  for (auto folder = createdFolders_.rbegin(); folder != createdFolders_.rend(); ++folder)
    fs::remove(*folder, ignored);  // only if empty: never what someone else put there
  for (const std::uint64_t handle : folderHandles_) forgetRemoveOnInterrupt(handle);
}

void OutputSet::createFolders(const fs::path& folder) {
  fs::path f = folder.lexically_normal();
  if (!f.has_filename()) f = f.parent_path();  // "out/" names the folder "out"
  std::vector<fs::path> missing;
  std::error_code error;
  for (fs::path p = f; !p.empty() && !fs::exists(fs::symlink_status(p, error)); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
    const bool made = fs::create_directory(*p, error);
    if (error) throw InputError(cat(p->string(), ": cannot create the folder: ", error.message()));
    if (made) {
      createdFolders_.push_back(*p);
      folderHandles_.push_back(removeOnInterrupt(*p, RemovalKind::Folder));
    }
  }
}

namespace {

constexpr std::size_t kStreamBufferBytes = std::size_t{1} << 20;

}  // namespace

StreamedFile::StreamedFile(OutputSet& set, const fs::path& target) : target_(target) {
  const fs::path temporary = set.addStreamed(target);
  fd_ = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    const int error = errno;
    if (error == ENOENT)
      throw InputError(cat(target.string(), ": the folder ", folderOf(target).string(), " does not exist"));
    throw cannotWrite(target, error);
  }
  buffer_.reserve(kStreamBufferBytes);
}

StreamedFile::~StreamedFile() {
  if (fd_ >= 0) ::close(fd_);
}

void StreamedFile::write(std::string_view bytes) {
  if (fd_ < 0) throw std::logic_error("StreamedFile::write after close");
  buffer_.append(bytes);
  if (buffer_.size() >= kStreamBufferBytes) flush();
}

void StreamedFile::flush() {
  if (const int error = writeAll(fd_, buffer_); error != 0) throw cannotWrite(target_, error);
  buffer_.clear();
}

void StreamedFile::overwrite(std::uint64_t offset, std::string_view bytes) {
  if (fd_ < 0) throw std::logic_error("StreamedFile::overwrite after close");
  flush();
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw cannotWrite(target_, n < 0 ? errno : EIO);
    done += static_cast<std::size_t>(n);
  }
}

void StreamedFile::close() {
  flush();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw cannotWrite(target_, errno);
}

void OutputSet::add(const fs::path& target, std::string_view bytes) {
  // In the interruption's list before it exists: no moment when it is there and not listed.
  const fs::path temp = temporaryFor(target);
  entries_.push_back({target, temp, false, removeOnInterrupt(temp, RemovalKind::File)});
  const fs::path& temporary = entries_.back().temporary;
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    forgetRemoveOnInterrupt(entries_.back().interruptHandle);
    entries_.pop_back();  // not ours to remove: O_EXCL found it there, or nothing was made
    if (error == ENOENT)
      throw InputError(cat(target.string(), ": the folder ", folderOf(target).string(), " does not exist"));
    throw cannotWrite(target, error);
  }
  int error = writeAll(fd, bytes);
  // The data reaches the disk before the rename can make the name point at it.
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    std::error_code ignored;
    fs::remove(temporary, ignored);  // at once: on a full disk its pages are what the next file needs
    forgetRemoveOnInterrupt(entries_.back().interruptHandle);
    entries_.pop_back();
    throw cannotWrite(target, error);
  }
}

fs::path OutputSet::addStreamed(const fs::path& target) {
  const fs::path temp = temporaryFor(target);
  entries_.push_back({target, temp, true, removeOnInterrupt(temp, RemovalKind::File)});
  return entries_.back().temporary;
}

void OutputSet::commit() {
  // Files written by others: their data reaches the disk before any rename (a failed sync, e.g.
  // EIO or a quota, is found before a name points at the file).
  for (const Entry& e : entries_) {
    if (!e.streamed) continue;
    const int fd = ::open(e.temporary.c_str(), O_RDONLY | O_CLOEXEC);
    int error = fd < 0 ? errno : 0;
    if (fd >= 0 && ::fsync(fd) != 0) error = errno;
    if (fd >= 0 && ::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) throw cannotWrite(e.target, error);
  }
  // An interruption waits until the renames are done (or undone): the set appears whole.
  const InterruptDeferral deferral;
  std::vector<fs::path> created;  // targets that did not exist before this call
  auto undo = [&] {
    std::error_code ignored;
    for (const fs::path& t : created) fs::remove(t, ignored);
  };
  std::vector<fs::path> folders;
  for (Entry& e : entries_) {
    std::error_code error;
    const bool existed = fs::exists(fs::symlink_status(e.target, error));
    if (::rename(e.temporary.c_str(), e.target.c_str()) != 0) {
      const int reason = errno;
      undo();
      throw cannotWrite(e.target, reason);
    }
    e.temporary.clear();  // it is the target now: not the destructor's to remove
    if (!existed) created.push_back(e.target);
    folders.push_back(folderOf(e.target));
  }
  for (const fs::path& f : createdFolders_) folders.push_back(folderOf(f));
  std::sort(folders.begin(), folders.end());
  folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
  for (const fs::path& f : folders)
    if (const int error = syncFolder(f); error != 0) {
      undo();
      throw InputError(
          cat(f.string(), ": cannot sync the folder after writing into it: ", std::system_category().message(error)));
    }
  committed_ = true;
  for (const Entry& e : entries_) forgetRemoveOnInterrupt(e.interruptHandle);
  for (const std::uint64_t handle : folderHandles_) forgetRemoveOnInterrupt(handle);
}

void writeFileAtomically(const fs::path& target, std::string_view bytes) {
  OutputSet output;
  output.add(target, bytes);
  output.commit();
}

void writeTextFileAtomically(const fs::path& target, std::string_view text) { writeFileAtomically(target, text); }

}  // namespace lenslab
