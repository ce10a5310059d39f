// Loading a batch of case files and running them, several at once, each worker on its own
// Vulkan device; shared by `run` and `bless`.
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
  run::SuiteInfo suite;  // every case given, before --shard kept this share
};

// Loads every file (directories expand to their *.json), reports every problem of
// every file together (CaseError, exit 2), then keeps shard I of N ("I/N", 1-based).
// Two cases of one name are refused: both would write OUT/NAME/.
CaseBatch loadBatch(const std::vector<std::string>& paths, const std::string& shard);

// Whether CI=true (or 1, yes) is set: a case without goldens then fails instead of skipping.
bool runningInCi();

// TAA_REQUIRE_EXACT=1: as `run --require-exact`, for CI jobs that must compare bit for bit.
// UsageError for a value other than 0 or 1.
bool requireExactFromEnvironment();

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
  // Cases rendered at once (`run -j N`), each worker on its own device; 0: one per core.
  // Every output is in case order and the same for any count.
  size_t jobs = 0;
  // Reference frames rendered once per run and shared (api/reference_cache.h); off: every
  // case renders its own (`run --no-reference-cache`, to rule the cache out).
  bool shareReferences = true;
};

struct BatchOutcome {
  run::RunResults results;
  golden::Environment environment;  // of the device the batch ran on
  int exitCode = 0;
  size_t notRun = 0;  // cases skipped by failFast after the first failure
  size_t workers = 1;
  size_t pipelinesCreated = 0, pipelinesReused = 0;  // over every worker's device
  size_t referencesRendered = 0, referencesFromDisk = 0, referencesReused = 0;
  std::map<std::string, std::map<int, Image>> outputs;  // when keepOutputs
};

// A results.json `run` wrote, read as an input (bounded, checked); UsageError (exit 2) naming
// the file, with `fix` appended, when it cannot be read or is not results JSON.
run::RunResults readResultsFile(const std::filesystem::path& results, const std::string& fix);
// The same in two steps, for a reader that checks the bytes before it parses them (the seal,
// run/results_seal.h): the file's text (readContainedFile: inside its folder after resolving
// links, regular, at most kMaxResultsFileBytes), then its parse.
std::string readResultsText(const std::filesystem::path& results, const std::string& fix);
run::RunResults parseResultsText(const std::string& text, const std::filesystem::path& results,
                                 const std::string& fix);

// --jobs N (also -j N): at least 1; absent: 0, one worker per core.
size_t parseJobs(const std::string& value);

// Where the CPU went, for the end of a run: CPU time of the process so far (user, system).
struct CpuTimes {
  double user = 0.0, system = 0.0;
};
CpuTimes cpuTimes();
// "run: 4210 frames in 41.2 s (102 frames/s); CPU 75.3 s (user 70.1, system 5.2), CPU/wall 1.83
// with 2 workers; pipelines: 95 compiled, 1630 reused; references: 900 rendered, 0 from disk, 2100
// reused". Timing, not a result: it is the one line that differs between two runs of the same
// cases.
std::string throughputLine(const BatchOutcome& outcome, double wallSeconds, const CpuTimes& before);

BatchOutcome runBatch(const CaseBatch& batch, const BatchOptions& options,
                      const std::function<void(const run::CaseResult&)>& onCase,
                      bool keepOutputs = false);

}  // namespace taa::cli
