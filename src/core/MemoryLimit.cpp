#include "core/MemoryLimit.h"

#include "core/Error.h"
#include "core/Text.h"

#include <sys/resource.h>

namespace lenslab {

std::optional<std::uint64_t> addressSpaceLimitBytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

std::string addressSpaceNote() {
  const std::optional<std::uint64_t> limit = addressSpaceLimitBytes();
  if (!limit) return {};
  return cat("; the process may use ", *limit >> 20, " MiB of address space (ulimit -v): raise it");
}

std::uint64_t addressSpaceForLlvmpipeBytes(unsigned threads) {
  return (std::uint64_t{1280} + std::uint64_t{64} * threads) << 20;
}

void requireAddressSpace(std::uint64_t needed, const std::string& what) {
  const std::optional<std::uint64_t> limit = addressSpaceLimitBytes();
  if (limit && *limit < needed)
    throw InputError(cat(what, " needs about ", needed >> 20, " MiB of address space, and ulimit -v allows ",
                         *limit >> 20, " MiB: raise it (ulimit -v unlimited)"));
}

}  // namespace lenslab
