#pragma once
// "Did you mean ...?" for a mistyped command or option name.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab {

// Edits that turn `a` into `b`: insertions, deletions, substitutions, and swaps of two
// neighbouring characters (the commonest typo, "lenght"), each counting one.
int editDistance(std::string_view a, std::string_view b);

// The candidate `word` most likely stands for: the nearest by editDistance when it is within a
// third of the longer name's length (at least 1, at most 3 edits), else the one candidate that
// `word` begins (an abbreviation); nothing when none is near enough, two are equally near, or
// `word` begins more than one.
std::optional<std::string> nearestName(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace lenslab
