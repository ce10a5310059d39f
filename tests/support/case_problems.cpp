#include "support/case_problems.h"

#include "case/case_error.h"
#include "case/case_loader.h"

namespace taa::test {

std::vector<std::string> caseRefusal(const std::function<void()>& load) {
  try {
    load();
  } catch (const cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

std::vector<std::string> caseProblems(const std::string& json) {
  return caseRefusal([&] { cases::parseCase(json, "cases/t.json"); });
}

}  // namespace taa::test
