#include "support/case_problems.h"

#include "case/case_error.h"
#include "case/case_loader.h"

namespace taa::test {

std::vector<std::string> caseProblems(const std::string& json) {
  try {
    cases::parseCase(json, "cases/t.json");
  } catch (const cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

}  // namespace taa::test
