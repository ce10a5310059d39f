// What the case reader refuses in a case file's text, for tests of validation messages.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace taa::test {

// The problems of the cases::CaseError `load` throws; empty when it throws none.
std::vector<std::string> caseRefusal(const std::function<void()>& load);

// The problems the case reader lists for `json` (read as if it were cases/t.json); empty when
// the case is accepted.
std::vector<std::string> caseProblems(const std::string& json);

}  // namespace taa::test
