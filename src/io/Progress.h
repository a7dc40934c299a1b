#pragma once
// Progress on long work, for a person at a terminal: a bar on stderr, redrawn in place.
#include <cstdio>

namespace lenslab {

bool isTerminal(std::FILE* stream);
// "[#####     ] 12/73 frames, 30.1 s, 43.2 s to go": the time to go assumes the rest take as
// long each as those done so far.
void printProgress(int done, int total, double seconds, const char* unit = "samples");

}  // namespace lenslab
