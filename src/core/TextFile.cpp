#include "core/TextFile.h"

#include "core/Error.h"
#include "core/Text.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

// "64 MiB", "4 GiB": limits as a user would write them.
std::string sizeInWords(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 30) - 1) return cat((bytes + 1) >> 30, " GiB");
  if (bytes >= std::uintmax_t{1} << 20) return cat(bytes >> 20, " MiB");
  return cat(bytes, " bytes");
}

}  // namespace

std::string readInputFile(const fs::path& file, const std::string& what, std::uintmax_t maxBytes) {
  const std::string name = file.string();
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) throw InputError(cat(name, ": cannot read the ", what, " (does it exist?)"));
  if (fs::is_directory(status)) throw InputError(cat(name, ": is a folder; give the ", what, " as a file"));
  if (!fs::is_regular_file(status))
    throw InputError(cat(name, ": is not a regular file (a device, FIFO or socket); give the ", what, " as a file"));
  const std::uintmax_t size = fs::file_size(file, ec);
  if (!ec && size > maxBytes)
    throw InputError(cat(name, ": the ", what, " has ", size, " bytes; lenslab reads at most ", sizeInWords(maxBytes)));
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!f) throw InputError(cat(name, ": cannot read the ", what, ": ", std::strerror(errno)));
  std::string bytes;
  if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  // The limit holds while reading too: a file that grows after the size was taken stops here.
  while (const std::size_t n = std::fread(chunk, 1, sizeof chunk, f.get())) {
    if (n > maxBytes - bytes.size())
      throw InputError(
          cat(name, ": the ", what, " has more than ", sizeInWords(maxBytes), "; lenslab reads at most that"));
    bytes.append(chunk, n);
  }
  if (std::ferror(f.get())) throw InputError(cat(name, ": cannot read the ", what, ": ", std::strerror(errno)));
  return bytes;
}

std::string readTextFile(const fs::path& file, const std::string& what) {
  std::string text = readInputFile(file, what, kMaxTextFileBytes);
  // What editors write: a UTF-8 byte-order mark is no part of the text (Windows' Notepad adds one);
  // UTF-16 (Notepad's "Unicode") is another encoding, named so that the user can save it as UTF-8.
  // Line ends, LF or CRLF, are each parser's: every one reads both.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF"))
    throw InputError(cat(file.string(), ": the ", what,
                         " is UTF-16 text (it starts with a UTF-16 byte-order mark); save it as UTF-8"));
  return text;
}

}  // namespace lenslab
