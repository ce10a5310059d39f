// What the case reader refuses in a case file's text, for tests of validation messages.
#pragma once

#include <string>
#include <vector>

namespace taa::test {

// The problems the case reader lists for `json` (read as if it were cases/t.json); empty when
// the case is accepted.
std::vector<std::string> caseProblems(const std::string& json);

}  // namespace taa::test
