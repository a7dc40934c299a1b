#pragma once
// Progress on long work, for a person at a terminal: a bar on stderr, redrawn in place.
#include <cstdio>

namespace lenslab {

bool isTerminal(std::FILE* stream);
void printProgress(int done, int total, double seconds);

}  // namespace lenslab
