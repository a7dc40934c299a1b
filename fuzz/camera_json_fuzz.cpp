// libFuzzer target: the camera JSON reader (parseCameraJson, what `--camera FILE.json` reads),
// then, for a camera it accepts, the way back: toCameraJson (what `view` saves) parsed again.
//
// The reader's contract: any text gives a camera or is refused with an InputError. Any other
// exception, a crash, an abort, a hang (-timeout), a sanitizer report or a large allocation is a
// finding. Built with LENSLAB_FUZZ (the fuzz preset); run by tools/fuzz.sh.
#include "core/Error.h"
#include "io/CameraJson.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

// LENSLAB_FUZZ_VERBOSE=1 prints each refusal (to see why a seed or a finding is refused).
const bool verbose = std::getenv("LENSLAB_FUZZ_VERBOSE") != nullptr;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const lenslab::CameraFile file = lenslab::parseCameraJson(text, "fuzz.json");
    const std::string saved = lenslab::toCameraJson(file.camera);
    (void)lenslab::parseCameraJson(saved, "saved.json");
  } catch (const lenslab::InputError& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    // refused with one line: what the reader must do with bad input
  }
  return 0;
}
