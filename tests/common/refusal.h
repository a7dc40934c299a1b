#pragma once
// The message of the InputError a call throws, or "accepted" when it throws none: for tests that
// check both what is refused (and how it is worded) and what is taken.
#include "core/Error.h"

#include <string>

namespace lenslab::test {

template <class F>
std::string refusalOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace lenslab::test
