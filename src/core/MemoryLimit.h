#pragma once
// The address space a process may use (ulimit -v, RLIMIT_AS), for messages and for refusing work
// that cannot fit before it starts: under a low limit, libraries fail in ways that say nothing
// of it (a dlopen that "cannot open" an installed library, a thread that cannot start, a crash in
// Mesa's shader compiler).
#include <cstdint>
#include <optional>
#include <string>

namespace lenslab {

// The soft limit in bytes; nullopt when there is none.
std::optional<std::uint64_t> addressSpaceLimitBytes();

// "; the process may use 600 MiB of address space (ulimit -v): raise it" when a limit is set, else
// empty: appended to a message about memory, it names the likely cause.
std::string addressSpaceNote();

// The address space OSMesa (llvmpipe) needs before a context is made, for `threads` rendering
// threads (LP_NUM_THREADS, else one per core). Measured with `render --width 66` under ulimit -v:
// with 2 threads the context failed, or Mesa's shader compiler crashed, below 1.1 GiB; with 16 it
// failed at 1.6 GiB (and once hung at 1.7) and worked at 2.0; with 32 it failed at 2.0. Taken as
// 1280 MiB + 64 MiB per thread. Below it, a GL command is refused in one line.
std::uint64_t addressSpaceForLlvmpipeBytes(unsigned threads);

// Throws InputError naming the limit when it is below `needed` for `what` ("OpenGL through OSMesa").
void requireAddressSpace(std::uint64_t needed, const std::string& what);

}  // namespace lenslab
