#include "invariants/registry.h"

#include <stdexcept>

namespace taa::invariants {

namespace {
const InvariantInfo* const kInvariantRows[] = {
#define TAA_INVARIANT(id) &id##_invariant,
#include "invariants/invariant_list.h"
#undef TAA_INVARIANT
};
}  // namespace

std::span<const InvariantInfo* const> invariantTable() {
  return kInvariantRows;
}

std::vector<std::string> invariantNames() {
  std::vector<std::string> out;
  for (const auto* row : kInvariantRows) out.emplace_back(row->name);
  return out;
}

const InvariantInfo* findInvariant(std::string_view name) {
  for (const auto* row : kInvariantRows)
    if (name == row->name) return row;
  return nullptr;
}

const InvariantInfo& invariantInfo(std::string_view name) {
  if (const auto* row = findInvariant(name)) return *row;
  std::string known;
  for (const auto* row : kInvariantRows)
    known += std::string(known.empty() ? "" : ", ") + row->name;
  throw std::invalid_argument("unknown invariant '" + std::string(name) + "'; known: " + known);
}

Needs needsOf(std::string_view name) {
  return invariantInfo(name).needs;
}

std::string inapplicable(std::string_view name, const spec::CheckedCase& spec) {
  const auto& row = invariantInfo(name);
  return row.inapplicable ? row.inapplicable(spec) : "";
}

std::unique_ptr<Invariant> makeInvariant(std::string_view name, const spec::CheckedCase& spec) {
  return invariantInfo(name).make(spec);
}

}  // namespace taa::invariants
