// lenslab: the lecture's camera models, rendered. See README.md.
#include "app/Commands.h"
#include "core/Error.h"

#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"lenslab — a renderer of the lecture's camera models: pinhole, thin lens, lens effects", "lenslab"};
  app.set_version_flag("--version", LENSLAB_VERSION);
  app.require_subcommand(1);
  // Usage errors in one line, like every other error lenslab reports.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("lenslab: error: ") + e.what() + " (see --help)\n";
  });
  std::vector<std::function<int()>> commands = {lenslab::addRenderCommand(app), lenslab::addRaycastCommand(app),
                                                lenslab::addCaptureCommand(app),
                                                lenslab::addSweepCommand(app), lenslab::addInfoCommand(app),
                                                lenslab::addViewCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a usage error prints CLI11's message and exits 2, as Unix
    // tools do for bad usage.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& command : commands) {
      const int result = command();
      if (result >= 0) return result;
    }
    return 0;
  } catch (const lenslab::InputError& e) {
    std::cerr << "lenslab: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lenslab: error: " << e.what() << "\n";
    return 1;
  }
}
