#include <unistd.h>

#include <chrono>
#include <iostream>

#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/run_cases.h"
#include "compare/metric_table.h"
#include "compare/tolerance.h"
#include "core/output_file.h"
#include "report/html_report.h"
#include "report/junit.h"
#include "run/console.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
std::string runUsage() {
  return "taa-harness run CASE... [--out DIR] [--goldens DIR] [--shard I/N] [--device NAME] "
         "[--validate]\n"
         "                        [--metric NAME --above X] [--fail-fast]\n"
         "  renders each case, compares its checked frames with goldens/NAME/, runs its invariants "
         "and\n"
         "  writes DIR/results.json, DIR/junit.xml and DIR/report.html (default DIR: out).\n"
         "  --shard I/N runs every N-th case starting at the I-th (1-based), for CI matrices.\n"
         "  --fail-fast stops at the first case that fails (exit 1; 2 for bad input); the outputs\n"
         "  cover the cases run so far.\n"
         "  --metric NAME --above X: exit 1 when a checked frame's NAME (" +
         compare::metricList(compare::goldenMetrics()) +
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
}  // namespace

int cmdRun(const Args& args) {
  const auto a =
      parseArgs(args, {"--validate", "--fail-fast"},
                {"--out", "--goldens", "--shard", "--device", "--metric", "--above"}, runUsage());
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
  CaseBatch batch = loadBatch(a.positional, a.value("--shard"));
  const fs::path out = a.value("--out", "out");
  for (const auto& c : batch.cases)
    refuseOutputInGoldens(out, a.has("--goldens") ? fs::path(a.value("--goldens"))
                                                  : run::defaultGoldensRoot(c.spec.file));
  createOutputDirectory(out);
  const auto start = std::chrono::steady_clock::now();
  BatchOptions options;
  options.run.outDir = out;
  options.run.goldensRoot = a.value("--goldens");
  options.device = a.value("--device");
  options.validate = a.has("--validate");
  options.failFast = a.has("--fail-fast");
  options.run.missingGoldenFails = runningInCi();
  const auto outcome = runBatch(batch, options, [](const run::CaseResult& c) { run::printCase(std::cout, c); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  writeFileAtomically(out / "results.json", run::toJson(outcome.results).dump(1) + "\n");
  report::writeJUnit(out / "junit.xml", outcome.results);
  report::writeHtmlReport(out / "report.html", outcome.results);
  run::printSummary(std::cout, outcome.results, seconds);
  if (outcome.notRun > 0)
    std::cout << "--fail-fast: stopped at the first failing case, " << outcome.notRun << " of "
              << batch.cases.size() << " cases not run\n";
  std::cout << "report: " << (out / "report.html").string() << "\n";
  if (outcome.exitCode == kBadInput || outcome.exitCode == kEnvironment) return outcome.exitCode;
  if (a.values.count("--metric")) return metricVerdict(outcome.results, a.value("--metric"), above);
  return outcome.exitCode;
}

}  // namespace taa::cli
