#pragma once
// The subcommands of the `lenslab` executable. Each registers its options on the CLI11 app and
// runs when chosen; errors a user can act on are thrown as InputError.
#include <CLI/CLI.hpp>

#include <functional>

namespace lenslab {

// Adds `render` to `app`; the returned function runs it after parsing.
std::function<int()> addRenderCommand(CLI::App& app);
std::function<int()> addRaycastCommand(CLI::App& app);
std::function<int()> addSweepCommand(CLI::App& app);
std::function<int()> addInfoCommand(CLI::App& app);
std::function<int()> addLensCommand(CLI::App& app);     // src/app/LensCommand.cpp
std::function<int()> addViewCommand(CLI::App& app);     // src/app/ViewCommand.cpp
std::function<int()> addCaptureCommand(CLI::App& app);  // src/app/CaptureCommand.cpp
std::function<int()> addDiagramCommand(CLI::App& app);  // src/app/DiagramCommand.cpp

}  // namespace lenslab
