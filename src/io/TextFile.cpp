#include "io/TextFile.h"

#include "core/Error.h"
#include "core/Text.h"

#include <fstream>
#include <sstream>

namespace lenslab {

std::string readTextFile(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(cat(file.string(), ": cannot read the ", what, " (does it exist?)"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace lenslab
