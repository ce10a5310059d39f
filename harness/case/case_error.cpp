#include "case/case_error.h"

namespace taa::cases {

namespace {
std::string joinLines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}
}  // namespace

CaseError::CaseError(std::vector<std::string> problems)
    : InputError(joinLines(problems)), problems_(std::move(problems)) {}

std::string CaseError::report(const std::string&) const {
  std::vector<std::string> lines;
  for (const auto& p : problems_) lines.push_back("error: " + p);
  return joinLines(lines);
}

}  // namespace taa::cases
