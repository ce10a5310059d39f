// The run engine: a batch of loaded cases rendered several at once, each worker on its own
// Vulkan device, their results handed on in case order; shared by `run` and `bless`. Frames
// go to the run's folder (run/run_folder.h) through its staging folder.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "case/case_loader.h"
#include "core/image.h"
#include "golden/environment.h"
#include "run/case_runner.h"
#include "run/results.h"

namespace taa::run {

struct CaseBatch {
  std::vector<cases::LoadedCase> cases;
  SuiteInfo suite;  // every case given, before --shard kept this share
};

struct BatchOptions {
  RunOptions run;
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

// What the batch's cases say, worst first: a case whose input is bad (an InputError while it
// rendered), else one that failed. Errors of the environment are not verdicts: they end the
// batch as the exception they are.
enum class BatchVerdict { Pass, Regression, BadInput };

struct BatchOutcome {
  RunResults results;
  golden::Environment environment;  // of the device the batch ran on
  BatchVerdict verdict = BatchVerdict::Pass;
  size_t notRun = 0;  // cases skipped by failFast after the first failure
  size_t workers = 1;
  size_t pipelinesCreated = 0, pipelinesReused = 0;  // over every worker's device
  size_t referencesRendered = 0, referencesFromDisk = 0, referencesReused = 0;
  std::map<std::string, std::map<int, Image>> outputs;  // when keepOutputs
};

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
                      const std::function<void(const CaseResult&)>& onCase,
                      bool keepOutputs = false);

}  // namespace taa::run
