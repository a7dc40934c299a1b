#pragma once
// Where lenslab finds its data: the bundled scenes (assets/) and the GLSL shaders. An installed
// lenslab finds them relative to its own executable, so the install prefix can be moved; a
// developer's build reads the source tree, so an edited shader or scene needs no rebuild.
//
// Shaders, first that applies:
//   1. LENSLAB_SHADER_DIR in the environment (a folder laid out as shaders/);
//   2. the source tree's shaders/, when the running executable lies inside the build tree it was
//      built in (build/lenslab, build/tests/...);
//   3. the copies compiled into the library at build time (gl/EmbeddedShaders.h).
// Assets, first that applies:
//   1. LENSLAB_ASSET_DIR in the environment;
//   2. <executable's folder>/../share/lenslab/assets, when that folder exists (the installed layout;
//      the relative part follows the install's bin and data folders);
//   3. the source tree's assets/, when the executable lies inside its build tree;
//   otherwise an InputError saying where it looked and how to point at the assets.
// The source and build trees' paths are compiled in, but used only by step 2 (shaders) and 3
// (assets): an executable anywhere else never opens them.
#include <filesystem>
#include <optional>

namespace lenslab {

// The running executable (/proc/self/exe, symbolic links resolved, read once); empty when it cannot
// be read.
std::filesystem::path executablePath();

// For a library loaded into another program (the Python module, loaded by python): its own file,
// which then stands for the executable in the rules above, with the installed data in
// <its folder>/share/lenslab (a wheel's layout) instead of <executable's folder>/../share/lenslab.
// Called once, before any other thread asks for data.
void setEmbeddingLibrary(const std::filesystem::path& library);

// Whether the running executable (or the embedding library) lies inside the build tree this
// library was built in.
bool runningFromBuildTree();

// The folder to read shaders from, or nullopt for the ones compiled into the library.
std::optional<std::filesystem::path> shaderDirectory();

// The bundled scenes' folder (rows/, grid/, ...). Throws InputError when there is none.
std::filesystem::path assetDirectory();

}  // namespace lenslab
