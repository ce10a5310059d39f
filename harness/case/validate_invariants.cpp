#include "case/validate_invariants.h"

#include <algorithm>

#include "case/json_reader.h"
#include "invariants/registry.h"

namespace taa::cases {

std::vector<std::pair<std::string, std::string>> invariantProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto& listed = spec.checks.invariants;
  const auto names = invariants::invariantNames();
  for (size_t i = 0; i < listed.size(); ++i) {
    const std::string key = "checks.invariants[" + std::to_string(i) + "]";
    const auto* row = invariants::findInvariant(listed[i]);
    if (row == nullptr) {
      std::string msg = "'" + listed[i] + "' is not one of " + joinNames(names);
      if (const std::string guess = closestMatch(listed[i], names); !guess.empty())
        msg += "; did you mean '" + guess + "'?";
      out.emplace_back(key, msg);
      continue;
    }
    const auto before = listed.begin() + long(i);
    if (std::find(listed.begin(), before, listed[i]) != before) {
      out.emplace_back(key, "'" + listed[i] + "' is listed twice; remove one");
      continue;
    }
    if (row->inapplicable)
      if (auto why = row->inapplicable(spec); !why.empty()) out.emplace_back(key, why);
  }
  // Parameters of an invariant that does not run would silently do nothing.
  for (const auto* row : invariants::invariantTable()) {
    if (row->params == nullptr) continue;
    const std::string key = std::string("checks.") + row->params;
    if (present.count(key) && std::find(listed.begin(), listed.end(), row->name) == listed.end())
      out.emplace_back(key, std::string("parameters of ") + row->name +
                                " are set but checks.invariants does not list it; add \"" +
                                row->name + "\" to checks.invariants or remove " + key);
  }
  return out;
}

}  // namespace taa::cases
