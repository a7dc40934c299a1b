#include "io/JsonLines.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace lenslab {

void appendLine(const std::filesystem::path& file, const std::string& line) {
  if (line.find('\n') != std::string::npos) throw std::logic_error("appendLine: a JSON line holds no newline");
  const std::string bytes = line + "\n";
  const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(cat(file.string(), ": cannot append to it: ", std::strerror(errno)));
  const ssize_t written = ::write(fd, bytes.data(), bytes.size());
  const int writeError = errno;
  const bool synced = written == static_cast<ssize_t>(bytes.size()) && ::fsync(fd) == 0;
  const int syncError = errno;
  const bool closed = ::close(fd) == 0;
  if (written < 0) throw InputError(cat(file.string(), ": cannot append to it: ", std::strerror(writeError)));
  // A short write leaves part of a line; it can only happen when the disk fills up.
  if (written != static_cast<ssize_t>(bytes.size()))
    throw InputError(cat(file.string(), ": wrote ", written, " of ", bytes.size(), " bytes of a line (is the disk full?)"));
  if (!synced || !closed) throw InputError(cat(file.string(), ": cannot append to it: ", std::strerror(synced ? errno : syncError)));
}

}  // namespace lenslab
