#include "core/NearestName.h"

#include <algorithm>

namespace lenslab {

int editDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance: Levenshtein plus adjacent transpositions, by rows.
  const std::size_t n = a.size(), m = b.size();
  std::vector<int> before(m + 1), previous(m + 1), current(m + 1);
  for (std::size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i) {
    current[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= m; ++j) {
      const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[m];
}

std::optional<std::string> nearestName(std::string_view word, const std::vector<std::string>& candidates) {
  // An abbreviation: "ray" for raycast; one that begins several names ("--focus") is no guess.
  std::optional<std::string> prefixed;
  int prefixes = 0;
  for (const std::string& c : candidates)
    if (word.size() >= 2 && c.size() > word.size() && c.compare(0, word.size(), word) == 0) {
      prefixed = c;
      ++prefixes;
    }
  if (prefixes > 1) return std::nullopt;
  std::optional<std::string> best;
  int bestDistance = 0;
  bool tie = false;
  for (const std::string& c : candidates) {
    const int d = editDistance(word, c);
    const int allowed = std::clamp(static_cast<int>(std::max(word.size(), c.size()) / 3), 1, 3);
    if (d > allowed) continue;
    if (!best || d < bestDistance) {
      best = c;
      bestDistance = d;
      tie = false;
    } else if (d == bestDistance) {
      tie = true;
    }
  }
  if (best && !tie) return best;
  if (best) return std::nullopt;  // two names equally near: guessing would mislead
  return prefixed;
}

}  // namespace lenslab
