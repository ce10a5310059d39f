// Loading a batch of case files and running them in one Vulkan context; shared by
// `run` and `bless`.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "case/case_loader.h"
#include "golden/environment.h"
#include "run/case_runner.h"
#include "run/results.h"

namespace taa::cli {

struct CaseBatch {
  std::vector<cases::LoadedCase> cases;
};

// Loads every file (directories expand to their *.json), reports every problem of
// every file together (CaseError, exit 2), then keeps shard I of N ("I/N", 1-based).
CaseBatch loadBatch(const std::vector<std::string>& paths, const std::string& shard);

// Whether CI=true (or 1, yes) is set: a case without goldens then fails instead of skipping.
bool runningInCi();

// Throws UsageError (exit 2) when `out` is the goldens folder or lies inside it: `render`,
// `run`, `sweep` and `bless` write frames there and would overwrite goldens.
void refuseOutputInGoldens(const std::filesystem::path& out,
                           const std::filesystem::path& goldensRoot);

struct BatchOptions {
  run::RunOptions run;
  std::string device;
  bool validate = false;
  // Stop after the first case that fails or errors (`run --fail-fast`): a broken build is
  // known at its first failure, which makes a caught mutant (ci/mutate.py) cheap.
  bool failFast = false;
};

struct BatchOutcome {
  run::RunResults results;
  golden::Environment environment;  // of the device the batch ran on
  int exitCode = 0;
  size_t notRun = 0;  // cases skipped by failFast after the first failure
  std::map<std::string, std::map<int, Image>> outputs;  // when keepOutputs
};

BatchOutcome runBatch(const CaseBatch& batch, const BatchOptions& options,
                      const std::function<void(const run::CaseResult&)>& onCase, bool keepOutputs = false);

}  // namespace taa::cli
