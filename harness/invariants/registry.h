// Every invariant's description in one place: its name in case files, what the runner must
// read back for it, which frames it judges, its parameter object and how to build it. The
// rows come from invariants/invariant_list.h; validation, the runner, the schema and the
// tests all look invariants up here by name.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "invariants/invariant.h"
#include "spec/checked_case.h"

namespace taa::invariants {

// Which frames the runner hands to observe().
enum class Frames {
  FromFrame,  // checks.from_frame on: warm-up frames are not judged
  All,        // every frame, warm-up included (a defect counts whenever it appears)
};

struct InvariantInfo {
  const char* name;  // as listed in checks.invariants and reported in results
  Needs needs;
  Frames frames;
  // Key of its parameter object under checks ("no_ghosting"), or nullptr when it has none.
  const char* params;
  // Why the case cannot use it (a fix-it sentence), or "" when it can; nullptr: any case.
  std::string (*inapplicable)(const spec::CheckedCase& spec);
  std::unique_ptr<Invariant> (*make)(const spec::CheckedCase& spec);
};

// Declarations of the rows, one per line of invariant_list.h.
#define TAA_INVARIANT(id) extern const InvariantInfo id##_invariant;
#include "invariants/invariant_list.h"
#undef TAA_INVARIANT

// Every row, in table order.
std::span<const InvariantInfo* const> invariantTable();
std::vector<std::string> invariantNames();

// The row of `name`, or nullptr when no invariant has that name.
const InvariantInfo* findInvariant(std::string_view name);
// The row of `name`; throws std::invalid_argument naming the known ones otherwise.
const InvariantInfo& invariantInfo(std::string_view name);

// By name, for callers and tests that hold one.
Needs needsOf(std::string_view name);
std::string inapplicable(std::string_view name, const spec::CheckedCase& spec);
std::unique_ptr<Invariant> makeInvariant(std::string_view name, const spec::CheckedCase& spec);

}  // namespace taa::invariants
