#include "core/name_suggestion.h"

#include <algorithm>

namespace cosim {

std::size_t editDistance(const std::string& a, const std::string& b) {
  // Optimal string alignment distance: rows i-2, i-1 and i of the dynamic programme.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[n];
}

std::string closestName(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = 3;  // more than 2 edits is a different word, not a slip
  for (const std::string& c : candidates) {
    if (c == name) return "";
    const std::size_t d = editDistance(name, c);
    if (d < best_distance && d <= name.size() / 3 + 1 && d < c.size()) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates) {
  const std::string best = closestName(name, candidates);
  return best.empty() ? "" : "did you mean '" + best + "'?";
}

}  // namespace cosim
