#include "io/JsonLines.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lenslab {

namespace {

InputError cannotAppend(const std::filesystem::path& file, int error) {
  return InputError(cat(file.string(), ": cannot append to it: ", std::strerror(error)));
}

// Closes the descriptor (and so drops the flock) on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// The size the file has once a trailing part of a line (no newline after it) is cut off: the
// offset after the last newline, or 0. Reads backwards in blocks. Returns -1 (errno set) on error.
off_t endOfLastLine(int fd, off_t size) {
  char block[4096];
  for (off_t end = size; end > 0;) {
    const off_t begin = end > static_cast<off_t>(sizeof block) ? end - static_cast<off_t>(sizeof block) : 0;
    const ssize_t n = ::pread(fd, block, static_cast<std::size_t>(end - begin), begin);
    if (n < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    if (n != end - begin) {
      errno = EIO;
      return -1;
    }
    for (ssize_t i = n; i > 0; --i)
      if (block[i - 1] == '\n') return begin + i;
    end = begin;
  }
  return 0;
}

}  // namespace

void appendLine(const std::filesystem::path& file, const std::string& line) {
  if (line.find('\n') != std::string::npos) throw std::logic_error("appendLine: a JSON line holds no newline");
  const std::string bytes = line + "\n";
  // O_RDWR, not O_WRONLY: a part of a line at the end is found by reading it.
  const Descriptor d{::open(file.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644)};
  if (d.fd < 0) throw cannotAppend(file, errno);
  while (::flock(d.fd, LOCK_EX) != 0)
    if (errno != EINTR) throw cannotAppend(file, errno);
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) throw cannotAppend(file, errno);
  off_t size = st.st_size;
  if (size > 0) {
    const off_t whole = endOfLastLine(d.fd, size);
    if (whole < 0) throw cannotAppend(file, errno);
    // A part of a line from a write that failed without cutting it back (a kill, an older
    // lenslab): not a line, and the next line would be glued to it.
    if (whole != size) {
      if (::ftruncate(d.fd, whole) != 0) throw cannotAppend(file, errno);
      size = whole;
    }
  }
  // Under the flock nobody else appends, so the line may go out in several writes: a short
  // write is followed by one that returns the reason (ENOSPC, EFBIG) or goes on.
  int error = 0;
  for (std::string_view rest = bytes; !rest.empty() && error == 0;) {
    const ssize_t n = ::write(d.fd, rest.data(), rest.size());
    if (n < 0 && errno != EINTR)
      error = errno;
    else if (n == 0)
      error = ENOSPC;  // no progress and no reason: do not spin
    else if (n > 0)
      rest.remove_prefix(static_cast<std::size_t>(n));
  }
  if (error == 0 && ::fsync(d.fd) != 0) error = errno;
  if (error != 0) {
    // No part of the line stays: cut back to the size before it.
    if (::ftruncate(d.fd, size) == 0) (void)::fsync(d.fd);
    throw cannotAppend(file, error);
  }
}

void checkAppendable(const std::filesystem::path& file, std::string_view option) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return;  // made by the first line: its folder is checked
  if (S_ISDIR(st.st_mode)) throw InputError(cat(option, " ", file.string(), ": is a folder; give a file name"));
  const int fd = ::open(file.c_str(), O_RDWR | O_APPEND | O_CLOEXEC);
  if (fd < 0)
    throw InputError(cat(option, " ", file.string(), ": cannot append to it: ", std::strerror(errno),
                         " (give a file this user may write, or another --manifest)"));
  ::close(fd);
}

std::vector<std::string> readCompleteLines(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error) && !error) return {};
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(cat(file.string(), ": cannot read it: ", error ? error.message() : std::strerror(errno)));
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  std::vector<std::string> lines;
  std::size_t begin = 0;
  for (std::size_t nl = all.find('\n'); nl != std::string::npos; nl = all.find('\n', begin)) {
    lines.push_back(all.substr(begin, nl - begin));
    begin = nl + 1;
  }
  return lines;
}

}  // namespace lenslab
