// Bad input: every problem names the file, the key path and the fix. The CLI turns
// a CaseError into exit code 2.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace taa::cases {

class CaseError : public std::runtime_error {
 public:
  explicit CaseError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Levenshtein distance, for "did you mean" suggestions.
int editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `key`, or "" when none is plausibly a typo of it.
std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates);

}  // namespace taa::cases
