// JUnit XML for CI dashboards: one <testsuite> with one <testcase> per case.
#pragma once

#include <filesystem>
#include <string>

#include "run/results.h"

namespace taa::report {

// classname "taa", name = the case name, time = the case's wall seconds. A failing or stale case
// gets <failure> listing the failed golden-frame thresholds and failed invariants (one per line);
// an error gets <error>; a case without golden gets <skipped>. The message and bless command go
// to <system-out>. Deterministic for identical input.
std::string renderJUnit(const run::RunResults& results);

// Writes renderJUnit atomically. Throws std::runtime_error when the file cannot be written.
void writeJUnit(const std::filesystem::path& file, const run::RunResults& results);

}  // namespace taa::report
