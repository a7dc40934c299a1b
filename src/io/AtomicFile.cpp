#include "io/AtomicFile.h"

#include "core/Error.h"
#include "core/Text.h"

#include <atomic>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace lenslab {
namespace fs = std::filesystem;

namespace {
std::atomic<unsigned> counter{0};
}

AtomicOutput::AtomicOutput(fs::path target) : target_(std::move(target)) {
  const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  if (!fs::is_directory(folder))
    throw InputError(cat(target_.string(), ": the folder ", folder.string(), " does not exist"));
  temporary_ = folder / cat(".", target_.stem().string(), ".tmp-", ::getpid(), "-", counter++,
                            target_.extension().string());
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove(temporary_, ignored);
  }
}

void AtomicOutput::commit() {
  std::error_code error;
  fs::rename(temporary_, target_, error);
  if (error) throw InputError(cat(target_.string(), ": cannot write it: ", error.message()));
  committed_ = true;
}

void writeTextFileAtomically(const fs::path& target, std::string_view text) {
  AtomicOutput output(target);
  {
    std::ofstream out(output.temporaryPath(), std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw InputError(cat(target.string(), ": cannot write it"));
  }
  output.commit();
}

}  // namespace lenslab
