#pragma once
// Errors a user can act on: bad files, bad JSON, bad cameras, bad options. Thrown at the boundary
// where the input is read; `main` prints what() as one line on stderr and exits non-zero.
// The message names the file (or option), the field, and what would be valid.
#include <stdexcept>
#include <string>

namespace lenslab {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lenslab
