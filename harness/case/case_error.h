// Bad input: every problem names the file, the key path and the fix. An InputError
// (exit code 2) that prints one "error:" line per problem.
#pragma once

#include <string>
#include <vector>

#include "core/closest_match.h"
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

// "Did you mean" suggestions (core/closest_match.h).
using taa::closestMatch;
using taa::editDistance;

}  // namespace taa::cases
