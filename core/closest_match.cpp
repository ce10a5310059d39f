#include "core/closest_match.h"

#include <algorithm>
#include <numeric>

namespace taa {

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  int bestDistance = 1 << 30;
  for (const auto& c : candidates) {
    const int d = editDistance(key, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  // A third of the key's length (at least 2 edits) separates typos from other words.
  const int allowed = std::max(2, static_cast<int>(key.size()) / 3);
  return bestDistance <= allowed ? best : std::string();
}

}  // namespace taa
