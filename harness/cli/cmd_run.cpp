#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/batch_args.h"
#include "compare/metric_table.h"
#include "compare/tolerance.h"
#include "core/output_file.h"
#include "golden/bless.h"
#include "golden/environment.h"
#include "report/html_report.h"
#include "report/junit.h"
#include "run/build_identity.h"
#include "run/case_runner.h"
#include "run/console.h"
#include "run/results_seal.h"
#include "run/run_folder.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
std::string runUsage() {
  return "taa-harness run CASE... [--out DIR] [--goldens DIR] [-j N] [--shard I/N] [--device NAME] "
         "[--validate]\n"
         "                        [--metric NAME --above X] [--fail-fast] [--no-reference-cache]\n"
         "                        [--verdict-from RESULTS] [--require-exact]\n"
         "  renders each case, compares its checked frames with goldens/NAME/, runs its invariants "
         "and\n"
         "  writes DIR/results.json, DIR/junit.xml and DIR/report.html (default DIR: out).\n"
         "  -j N (--jobs N) renders N cases at once, each worker on its own device (default: one per\n"
         "  core); the console lines and every output stay in case order, the same for any N.\n"
         "  A reference frame several cases (or the frames of a still scene) share is rendered once;\n"
         "  it is kept on disk for later runs ($TAA_REFERENCE_CACHE_DIR, else\n"
         "  ~/.cache/taa-harness/references; $TAA_REFERENCE_CACHE_MAX_MB MiB, default 1024).\n"
         "  --no-reference-cache renders every one, reading no disk (the results are the same).\n"
         "  --verdict-from RESULTS takes the cases' lines and verdict from RESULTS (and writes them to\n"
         "  DIR/results.json) instead of rendering, when RESULTS is an earlier run of this build (the\n"
         "  same executable, SPIR-V, CPU level, device and CI setting) that holds every one of them\n"
         "  with the same inputs and goldens, as ctest's shards and case tests use; else they run.\n"
         "  --shard I/N runs every N-th case starting at the I-th (1-based), for CI matrices;\n"
         "  `taa-harness merge` joins the shards' outputs.\n"
         "  --fail-fast stops at the first case that fails (exit 1; 2 for bad input); the outputs\n"
         "  cover the cases run so far.\n"
         "  --metric NAME --above X: exit 1 when a checked frame's NAME (" +
         compare::metricList(compare::goldenMetrics()) +
         "  --require-exact (or TAA_REQUIRE_EXACT=1) fails a case whose goldens hold no positive "
         "for\n"
         "  this environment instead of comparing it within tolerances (the positive's command is\n"
         "  printed: bless --add-environment, or bless --from a run's folder).\n"
         ")\n  against its golden is past X (below X for psnr), else 0 (bit-exactness is not "
         "required).\n"
         "exit: 0 pass, 1 regression, 2 bad input, 3 environment";
}

// Applies --metric/--above: quality drift past a bound, ignoring bit-exactness.
int metricVerdict(const run::RunResults& results, const std::string& metric, double above) {
  bool bad = false;
  for (const auto& c : results.cases)
    for (const auto& f : c.frames) {
      if (f.status == run::FrameStatus::MissingGolden) {
        std::cout << "MISSING " << c.name << " frame " << f.frame << ": no golden to measure against\n";
        bad = true;
        continue;
      }
      const double v = compare::metricByName(f.metrics, metric);
      const bool higherIsBetter = compare::findMetric(metric)->better == compare::Better::Higher;
      const bool over = compare::violates(*compare::findMetric(metric), v, above);
      std::cout << (over ? "ABOVE " : "OK ") << c.name << " frame " << f.frame << " " << metric
                << " " << v << (higherIsBetter ? " (bound: at least " : " (bound: at most ")
                << above << ")\n";
      bad |= over;
    }
  return bad ? kRegression : kPass;
}
// results.json, sealed for a later --verdict-from; a note when it cannot be.
void writeResults(const fs::path& file, const std::string& text) {
  if (const std::string why = run::writeSealedResults(file, text); !why.empty())
    std::cerr << "note: " << file.string() << " is not sealed (" << why
              << "); a later run --verdict-from renders its cases instead of reusing them\n";
}

// --verdict-from RESULTS: when RESULTS (ctest's shard of this session, or the main job of this
// build) carries this user's seal (run/results_seal.h: no byte edited since a run wrote it)
// and holds every case of the batch, rendered by the same build (run::buildIdentity) in the
// same environment (driver, device, CPU level: golden::Environment's fingerprint) from the same
// inputs (LoadedCase::sha256: every file a case reads) against the same goldens,
// their lines and verdict come from it instead of a render, and OUT/results.json holds them
// (so a case test can take its verdict from a shard that took its own from the main job).
// Empty when it does not: then the cases render (with a note when the seal is why).
std::optional<int> earlierVerdict(const run::CaseBatch& batch, const fs::path& from,
                                  const run::RunFolder& out,
                                  const std::string& build, const std::string& device,
                                  const fs::path& goldensRoot) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(from, ec))) return std::nullopt;
  const std::string fix = "pass the results.json of an earlier run";
  const run::RunFolder earlierFolder = run::RunFolder::ofResultsFile(from);
  const std::string text = earlierFolder.readResultsText(fix);
  // A file that is no results at all is bad input (exit 2), sealed or not.
  run::RunResults earlier = earlierFolder.parseResults(text, fix);
  // Said, not silent: a run that renders what the user expected to reuse (a rebuild or an
  // edited tree since the main job) is otherwise a mystery of a slow ctest.
  auto notReused = [&](const std::string& why) {
    std::cerr << "note: --verdict-from " << from.string() << ": not reused (" << why
              << "); the cases render\n";
    return std::nullopt;
  };
  if (const std::string why = run::sealProblem(from, text); !why.empty()) return notReused(why);
  if (earlier.build != build)
    return notReused(
        "made by another build: its executable, SPIR-V, CPU level, CI setting or "
        "device differs from this run's");
  if (const std::string commit = golden::rendererCommit(); earlier.commit != commit)
    return notReused("made at commit " + earlier.commit + ", this tree is " + commit);
  // The same build on another driver or Mesa version renders other bytes.
  DeviceOptions probe;
  probe.device = device;
  const std::string fingerprint =
      golden::currentEnvironment(Device(probe).identity()).fingerprint();
  if (earlier.fingerprint != fingerprint)
    return notReused("made on another driver or environment: " + earlier.fingerprint);
  std::vector<run::CaseResult> found;
  for (const auto& c : batch.cases) {
    const auto it = std::find_if(earlier.cases.begin(), earlier.cases.end(), [&](const auto& r) {
      // Not the path: `run cases` and ctest name one file differently, and its bytes (and
      // those of every file it references) are in caseSha256.
      return r.name == c.spec.name && r.caseSha256 == c.sha256 &&
             (r.fingerprint.empty() || r.fingerprint == fingerprint) &&
             r.goldensSha256 == run::goldensDigest(c.spec, goldensRoot);
    });
    if (it == earlier.cases.end()) return std::nullopt;
    found.push_back(*it);
  }
  bool failed = false;
  for (const auto& c : found) {
    run::printCase(std::cout, c);
    failed |= run::caseFailed(c);
  }
  if (!fs::equivalent(from, out.resultsFile(), ec)) {
    earlier.cases = std::move(found);
    earlier.suite = batch.suite;
    earlier.notRun = 0;
    writeResults(out.resultsFile(), run::toJson(earlier).dump(1) + "\n");
  }
  // A shard that took its own verdicts from the main job has no report; the main job's is it.
  const fs::path report = earlierFolder.reportFile();
  std::cout << "verdict: from " << from.string() << " (a run of this build"
            << (fs::exists(report, ec) ? "; its report: " + report.string() : std::string()) << ")\n";
  return failed ? kRegression : kPass;
}
}  // namespace

int cmdRun(const Args& args) {
  const auto a =
      parseArgs(args, {"--validate", "--fail-fast", "--no-reference-cache", "--require-exact"},
                {"--out", "--goldens", "--shard", "--device", "--metric", "--above", "--jobs",
                 "--verdict-from"}, runUsage());
  if (a.positional.empty()) throw UsageError(std::string("no case given\nusage: ") + runUsage());
  if (a.values.count("--metric") != a.values.count("--above"))
    throw UsageError(std::string("--metric and --above go together\nusage: ") + runUsage());
  double above = 0.0;
  if (a.values.count("--metric")) {
    try {
      run::ImageMetrics probe;
      compare::metricByName(probe, a.value("--metric"));  // rejects an unknown name before rendering
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--metric/--above: ") + e.what());
    }
    above = numberOption(a, "--above", -1e300, 1e300);
  }
  run::CaseBatch batch = loadBatch(a.positional, a.value("--shard"));
  const run::RunFolder folder(a.value("--out", "out"));
  const fs::path& out = folder.root();
  for (const auto& c : batch.cases)
    refuseOutputInGoldens(out, a.values.count("--goldens") ? fs::path(a.value("--goldens"))
                                                  : run::defaultGoldensRoot(c.spec.file));
  createOutputDirectory(out);
  const bool requireExact = a.has("--require-exact") || requireExactFromEnvironment();
  if (a.values.count("--verdict-from"))
    if (const auto verdict =
            earlierVerdict(batch, a.value("--verdict-from"), folder,
                           run::buildIdentity(a.value("--device"), runningInCi(), requireExact),
                           a.value("--device"), a.value("--goldens")))
      return *verdict;
  const auto start = std::chrono::steady_clock::now();
  const run::CpuTimes cpuBefore = run::cpuTimes();
  run::BatchOptions options;
  options.jobs = parseJobs(a.value("--jobs"));
  options.shareReferences = !a.has("--no-reference-cache");
  options.run.outDir = out;
  options.run.goldensRoot = a.value("--goldens");
  options.device = a.value("--device");
  options.validate = a.has("--validate");
  options.failFast = a.has("--fail-fast");
  options.run.missingGoldenFails = runningInCi();
  options.run.requireExact = requireExact;
  const auto outcome =
      run::runBatch(batch, options, [](const run::CaseResult& c) { run::printCase(std::cout, c); });

  writeResults(folder.resultsFile(), run::toJson(outcome.results).dump(1) + "\n");
  report::writeJUnit(folder.junitFile(), outcome.results);
  report::writeHtmlReport(folder.reportFile(), outcome.results);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run::printSummary(std::cout, outcome.results, seconds);
  std::cout << run::throughputLine(outcome, seconds, cpuBefore) << "\n";
  if (outcome.notRun > 0)
    std::cout << "--fail-fast: stopped at the first failing case, " << outcome.notRun << " of "
              << batch.cases.size() << " cases not run\n";
  std::cout << "report: " << folder.reportFile().string() << "\n";
  if (outcome.verdict == run::BatchVerdict::BadInput) return exitCodeOf(outcome.verdict);
  if (a.values.count("--metric")) return metricVerdict(outcome.results, a.value("--metric"), above);
  return exitCodeOf(outcome.verdict);
}

}  // namespace taa::cli
