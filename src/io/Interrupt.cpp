#include "io/Interrupt.h"

#include <csignal>
#include <map>
#include <string>
#include <thread>

#include <pthread.h>
#include <unistd.h>

namespace lenslab {
namespace fs = std::filesystem;

namespace {

struct Removal {
  fs::path path;
  RemovalKind kind;
};

// Recursive: OutputSet::commit() adds and forgets entries while holding a deferral.
std::recursive_mutex& registryMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}
std::map<std::uint64_t, Removal>& registry() {  // ordered by handle: the order added
  static std::map<std::uint64_t, Removal> entries;
  return entries;
}
std::uint64_t nextHandle = 1;

const char* signalName(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

[[noreturn]] void removeAndExit(int sig) {
  // Never unlocked: the process ends here, and no step holding a deferral starts after this.
  registryMutex().lock();
  int files = 0, folders = 0;
  for (const auto& [handle, r] : registry())
    if (r.kind == RemovalKind::File && ::unlink(r.path.c_str()) == 0) ++files;
  for (auto it = registry().rbegin(); it != registry().rend(); ++it)
    if (it->second.kind == RemovalKind::Folder && ::rmdir(it->second.path.c_str()) == 0) ++folders;
  std::string line = std::string("\nlenslab: interrupted (") + signalName(sig) + ")";
  if (!isatty(STDERR_FILENO)) line.erase(0, 1);  // the newline ends a progress bar's line
  if (files > 0 || folders > 0) {
    line += "; removed ";
    if (files > 0) line += plural(files, "unfinished file", "unfinished files");
    if (files > 0 && folders > 0) line += " and ";
    if (folders > 0) line += plural(folders, "empty folder it made", "empty folders it made");
  }
  line += "\n";
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + sig);
}

}  // namespace

void installInterruptHandling() {
  std::signal(SIGXFSZ, SIG_IGN);
  // A signal ignored at start (nohup's SIGHUP, a background job's SIGINT) stays ignored.
  sigset_t wanted;
  sigemptyset(&wanted);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (::sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    sigaddset(&wanted, sig);
  }
  ::pthread_sigmask(SIG_BLOCK, &wanted, nullptr);
  std::thread([wanted] {
    int sig = 0;
    while (::sigwait(&wanted, &sig) != 0) {}
    removeAndExit(sig);
  }).detach();
}

std::uint64_t removeOnInterrupt(const fs::path& path, RemovalKind kind) {
  const std::lock_guard lock(registryMutex());
  const std::uint64_t handle = nextHandle++;
  registry().emplace(handle, Removal{path, kind});
  return handle;
}

void forgetRemoveOnInterrupt(std::uint64_t handle) {
  const std::lock_guard lock(registryMutex());
  registry().erase(handle);
}

InterruptDeferral::InterruptDeferral() : lock_(registryMutex()) {}
InterruptDeferral::~InterruptDeferral() = default;

}  // namespace lenslab
