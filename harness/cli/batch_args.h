// What `run`, `bless` and `coverage` take from their arguments and environment before the run
// engine (run/batch_runner.h) renders: the case files as a batch and its shard, -j, CI=true,
// TAA_REQUIRE_EXACT, and the rule that no output goes into the goldens.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "run/batch_runner.h"

namespace taa::cli {

// Loads every file (directories expand to their *.json), reports every problem of
// every file together (CaseError, exit 2), then keeps shard I of N ("I/N", 1-based).
// Two cases of one name are refused: both would write OUT/NAME/.
run::CaseBatch loadBatch(const std::vector<std::string>& paths, const std::string& shard);

// Whether CI=true (or 1, yes) is set: a case without goldens then fails instead of skipping.
bool runningInCi();

// TAA_REQUIRE_EXACT=1: as `run --require-exact`, for CI jobs that must compare bit for bit.
// UsageError for a value other than 0 or 1.
bool requireExactFromEnvironment();

// Throws UsageError (exit 2) when `out` is the goldens folder or lies inside it: `render`,
// `run`, `sweep` and `bless` write frames there and would overwrite goldens.
void refuseOutputInGoldens(const std::filesystem::path& out,
                           const std::filesystem::path& goldensRoot);

// The exit code of a batch's verdict (cli/exit_codes.h): 2 bad input, 1 regression, 0 pass.
int exitCodeOf(run::BatchVerdict verdict);

// --jobs N (also -j N): at least 1; absent: 0, one worker per core.
size_t parseJobs(const std::string& value);

}  // namespace taa::cli
