// lenslab: the lecture's camera models, rendered. See README.md.
#include "app/Commands.h"
#include "core/Error.h"
#include "core/MemoryLimit.h"
#include "core/NearestName.h"
#include "io/Interrupt.h"

#include <algorithm>
#include <iostream>
#include <new>
#include <string>
#include <system_error>
#include <vector>

namespace {

std::vector<std::string> commandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// Every spelling of every option of `command`: --width, -o, ...
std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& n : option->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : option->get_snames()) names.push_back("-" + n);
  }
  return names;
}

// The first word that is not an option must be a command. CLI11 would say only "A subcommand is
// required" for `lenslab rendr`; this names the word and the command it is nearest to.
std::string unknownCommandMessage(const CLI::App& app, int argc, char** argv) {
  const std::vector<std::string> names = commandNames(app);
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') continue;  // --help, --version
    if (std::find(names.begin(), names.end(), word) != names.end()) return {};
    std::string message = "unknown command \"" + word + "\"";
    if (const auto near = lenslab::nearestName(word, names)) {
      message += "; did you mean \"" + *near + "\"?";
    } else {
      message += "; the commands are";
      for (const std::string& n : names) message += (n == names.front() ? " " : ", ") + n;
    }
    return message;
  }
  return {};
}

// An option the command does not know, with the nearest it does know, or the commands that take
// it (`raycast --pattern`: patterns are the rasterizer's); empty when CLI11's message is better.
std::string unknownOptionMessage(const CLI::App& app) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty()) return {};
  const CLI::App& command = *chosen.front();
  for (std::string word : command.remaining(false)) {
    if (word.size() < 2 || word[0] != '-') continue;
    word = word.substr(0, word.find('='));  // --widht=5
    const std::string head = command.get_name() + ": unknown option " + word;
    if (const auto near = lenslab::nearestName(word, optionNames(command)))
      return head + "; did you mean " + *near + "? (see lenslab " + command.get_name() + " --help)";
    std::vector<std::string> others;
    for (const std::string& name : commandNames(app)) {
      const std::vector<std::string> options = optionNames(*app.get_subcommand(name));
      if (std::find(options.begin(), options.end(), word) != options.end()) others.push_back(name);
    }
    if (others.empty()) return head + " (see lenslab " + command.get_name() + " --help)";
    std::string takers;
    for (std::size_t i = 0; i < others.size(); ++i)
      takers += (i == 0 ? "" : i + 1 == others.size() ? " and " : ", ") + others[i];
    return head + ": " + takers + (others.size() == 1 ? " takes" : " take") + " it, " + command.get_name() +
           " does not (see lenslab " + command.get_name() + " --help)";
  }
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  // First, before any thread starts: Ctrl-C and SIGTERM remove the run's unfinished files.
  try {
    lenslab::installInterruptHandling();
  } catch (const std::system_error& e) {  // its thread cannot start: too little address space
    std::cerr << "lenslab: error: cannot start a thread (" << e.what() << ")" << lenslab::addressSpaceNote() << "\n";
    return 1;
  }
  CLI::App app{"lenslab — a renderer of the lecture's camera models: pinhole, thin lens, lens effects", "lenslab"};
  app.set_version_flag("--version", LENSLAB_VERSION);
  app.require_subcommand(1);
  // Usage errors in one line, like every other error lenslab reports.
  app.failure_message([](const CLI::App* failed, const CLI::Error& e) {
    if (dynamic_cast<const CLI::ExtrasError*>(&e))
      if (const std::string message = unknownOptionMessage(*failed); !message.empty())
        return "lenslab: error: " + message + "\n";
    return std::string("lenslab: error: ") + e.what() + " (see --help)\n";
  });
  std::vector<std::function<int()>> commands = {lenslab::addRenderCommand(app),  lenslab::addRaycastCommand(app),
                                                lenslab::addCaptureCommand(app), lenslab::addSweepCommand(app),
                                                lenslab::addInfoCommand(app),    lenslab::addLensCommand(app),
                                                lenslab::addViewCommand(app),    lenslab::addDiagramCommand(app)};
  if (const std::string message = unknownCommandMessage(app, argc, argv); !message.empty()) {
    std::cerr << "lenslab: error: " << message << " (see --help)\n";
    return 2;
  }
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
  } catch (const std::bad_alloc&) {
    // Nothing was written: every output is committed only when whole (io/AtomicFile.h).
    std::cerr << "lenslab: error: out of memory: this run needs more than the process may use (the machine's memory, "
                 "ulimit -v); give a smaller --width, or render in tiles (render --tile-size)\n";
    return 1;
  } catch (const std::system_error& e) {  // a thread (TBB's, Embree's, llvmpipe's) that cannot start
    std::cerr << "lenslab: error: " << e.what() << lenslab::addressSpaceNote() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lenslab: error: " << e.what() << "\n";
    return 1;
  }
}
