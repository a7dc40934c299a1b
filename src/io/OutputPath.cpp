#include "io/OutputPath.h"

#include "core/Error.h"
#include "core/Text.h"
#include "io/ImageFile.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

std::atomic<unsigned> probeCounter{0};

// Creates, writes one byte to, and removes a file in `folder`: what the real write will need,
// asked of the kernel rather than guessed from permission bits (root passes those, a read-only
// mount does not). Returns 0 or the errno that stopped it.
int probeFolder(const fs::path& folder) {
  const fs::path probe = folder / cat(".lenslab-probe-", ::getpid(), "-", probeCounter++);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return errno;
  int error = 0;
  while (::write(fd, "x", 1) != 1)
    if (errno != EINTR) {
      error = errno;
      break;
    }
  if (::close(fd) != 0 && error == 0) error = errno;
  ::unlink(probe.c_str());
  return error;
}

}  // namespace

void checkOutputPath(const fs::path& path, OutputKind kind, std::string_view option) {
  if (path.empty()) throw InputError(cat(option, ": the file name is empty; give one"));
  const std::string name = cat(option, " ", path.string());
  if (kind == OutputKind::Image) checkImageExtension(path);
  if (kind == OutputKind::Json && lowerExtension(path) != ".json")
    throw InputError(cat(name, ": give a .json file name"));
  if (kind == OutputKind::JsonLines && lowerExtension(path) != ".jsonl" && lowerExtension(path) != ".json")
    throw InputError(cat(name, ": give a .jsonl (or .json) file name for its JSON lines"));

  std::error_code error;
  if (!path.has_filename() || fs::is_directory(fs::status(path, error)))
    throw InputError(cat(name, ": is a folder; give a file name"));
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const fs::file_status folderStatus = fs::status(folder, error);
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
    throw InputError(cat(name, ": cannot reach the folder ", folder.string(), ": ", error.message()));
  if (!fs::exists(folderStatus)) throw InputError(cat(name, ": the folder ", folder.string(), " does not exist"));
  if (!fs::is_directory(folderStatus)) throw InputError(cat(name, ": ", folder.string(), " is not a folder"));
  // The probe's name is short; the target's may not fit (NAME_MAX, 255 bytes on most).
  const std::size_t nameBytes = path.filename().string().size();
  if (const long nameMax = ::pathconf(folder.c_str(), _PC_NAME_MAX);
      nameMax > 0 && nameBytes > static_cast<std::size_t>(nameMax))
    throw InputError(cat(name, ": the file name is ", nameBytes, " bytes; the file system in ", folder.string(),
                         " allows ", nameMax, ": give a shorter name"));
  if (const int e = probeFolder(folder); e != 0)
    throw InputError(
        cat(name, ": cannot write in the folder ", folder.string(), ": ", std::system_category().message(e)));
}

void checkNotInput(const fs::path& output, std::string_view option, const fs::path& input,
                   std::string_view inputOption) {
  if (output.empty() || input.empty()) return;
  std::error_code error;
  const bool same = fs::equivalent(output, input, error);
  if (!error && same)
    throw InputError(
        cat(option, " ", output.string(), ": is the ", inputOption, " file this run reads; give another name"));
}

}  // namespace lenslab
