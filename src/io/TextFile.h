#pragma once
// A whole text file read for a parser, with the one-line error a user gets when it cannot be.
#include <filesystem>
#include <string>

namespace lenslab {

// Throws InputError "<file>: cannot read the <what> (does it exist?)".
std::string readTextFile(const std::filesystem::path& file, const std::string& what);

}  // namespace lenslab
