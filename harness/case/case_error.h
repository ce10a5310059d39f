// Bad input: every problem names the file, the key path and the fix. An InputError
// (exit code 2) that prints one "error:" line per problem.
#pragma once

#include <string>
#include <vector>

#include "core/errors.h"

namespace taa::cases {

class CaseError : public InputError {
 public:
  explicit CaseError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }
  std::string report(const std::string& command) const override;

 private:
  std::vector<std::string> problems_;
};

// Levenshtein distance, for "did you mean" suggestions.
int editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `key`, or "" when none is plausibly a typo of it.
std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates);

}  // namespace taa::cases
