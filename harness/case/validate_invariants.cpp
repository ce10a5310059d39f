#include "case/validate_invariants.h"

#include <algorithm>

#include "invariants/invariant.h"

namespace taa::cases {

using spec::InvariantKind;

std::vector<std::pair<std::string, std::string>> invariantProblems(
    const spec::CaseSpec& spec, const std::set<std::string>& present) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto& listed = spec.checks.invariants;
  for (size_t i = 0; i < listed.size(); ++i) {
    const std::string key = "checks.invariants[" + std::to_string(i) + "]";
    const auto before = listed.begin() + long(i);
    if (std::find(listed.begin(), before, listed[i]) != before) {
      out.emplace_back(key, std::string("'") + spec::enumToString(listed[i]) +
                                "' is listed twice; remove one");
      continue;
    }
    if (auto why = invariants::inapplicable(listed[i], spec); !why.empty())
      out.emplace_back(key, why);
  }
  // Parameters of an invariant that does not run would silently do nothing.
  const std::pair<const char*, InvariantKind> params[] = {
      {"no_ghosting", InvariantKind::NoGhosting},
      {"converges", InvariantKind::Converges},
      {"temporal_stability", InvariantKind::TemporalStability},
      {"energy", InvariantKind::Energy},
      {"bit_stable", InvariantKind::BitStable}};
  for (const auto& [name, kind] : params) {
    const std::string key = std::string("checks.") + name;
    if (present.count(key) && std::find(listed.begin(), listed.end(), kind) == listed.end())
      out.emplace_back(key, std::string("parameters of ") + name +
                                " are set but checks.invariants does not list it; add \"" + name +
                                "\" to checks.invariants or remove " + key);
  }
  return out;
}

}  // namespace taa::cases
