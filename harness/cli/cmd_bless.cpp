#include <iostream>
#include <optional>
#include <sstream>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/run_cases.h"
#include "compare/metric_table.h"
#include "core/output_file.h"
#include "golden/bless.h"
#include "golden/golden_store.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kBlessUsage =
    "taa-harness bless CASE... --reason \"why the image changed\" [--force] [--goldens DIR] [--out DIR] [-j N]\n"
    "taa-harness bless --failed-from out/results.json --reason \"...\"   (re-bless what failed last run)\n"
    "  renders each case, runs its invariants (a failing invariant refuses the bless unless --force),\n"
    "  prints what changed against the old goldens, then replaces goldens/NAME/ atomically.";

std::vector<std::string> failedCases(const fs::path& results) {
  std::vector<std::string> files;
  for (const auto& c : readResultsFile(results, "pass the results.json of a previous run").cases)
    if (c.status != run::CaseStatus::Pass && c.status != run::CaseStatus::Error)
      files.push_back(c.file);
  return files;
}

void printChanges(const run::CaseResult& r) {
  if (r.firstDifference.frame >= 0)
    std::cout << "  " << r.name << " sequence: " << r.firstDifference.detail << "\n";
  if (r.frames.empty()) return;
  for (const auto& f : r.frames) {
    std::cout << "  " << r.name << " frame " << f.frame << ": ";
    if (f.status == run::FrameStatus::MissingGolden)
      std::cout << "new golden\n";
    else if (f.status == run::FrameStatus::Exact)
      std::cout << "unchanged\n";
    else {
      std::cout << "changed:";
      const char* sep = " ";
      for (const auto* m : compare::goldenMetrics()) {
        std::cout << sep << m->name << " " << f.metrics.*m->golden;
        sep = ", ";
      }
      std::cout << " (old " << f.goldenSha256.substr(0, 12) << ", new "
                << f.actualSha256.substr(0, 12) << ")\n";
    }
  }
}
}  // namespace

int cmdBless(const Args& args) {
  const auto a = parseArgs(args, {"--force"}, {"--reason", "--goldens", "--out", "--failed-from", "--device", "--jobs"}, kBlessUsage);
  const std::string reason = a.value("--reason");
  if (reason.find_first_not_of(" \t") == std::string::npos)
    throw UsageError("--reason is required: say why the images changed (it is stored in the manifest)\nusage: " +
                     std::string(kBlessUsage));
  std::vector<std::string> paths = a.positional;
  if (a.values.count("--failed-from")) {
    const auto failed = failedCases(a.value("--failed-from"));
    if (failed.empty()) {
      std::cout << "nothing to bless: no case failed in " << a.value("--failed-from") << "\n";
      return kPass;
    }
    paths.insert(paths.end(), failed.begin(), failed.end());
  }
  if (paths.empty()) throw UsageError(std::string("no case given\nusage: ") + kBlessUsage);
  const CaseBatch batch = loadBatch(paths, "");
  BatchOptions options;
  options.run.outDir = a.value("--out", "out/bless");
  options.run.goldensRoot = a.value("--goldens");
  options.device = a.value("--device");
  options.jobs = parseJobs(a.value("--jobs"));
  for (const auto& c : batch.cases)
    refuseOutputInGoldens(options.run.outDir, options.run.goldensRoot.empty()
                                                  ? run::defaultGoldensRoot(c.spec.file)
                                                  : options.run.goldensRoot);
  createOutputDirectory(options.run.outDir);
  const auto outcome = runBatch(batch, options, nullptr, /*keepOutputs=*/true);
  if (outcome.exitCode == kBadInput || outcome.exitCode == kEnvironment) {
    // A scene that does not load (or a broken environment): say which case and why.
    for (const auto& r : outcome.results.cases)
      if (r.status == run::CaseStatus::Error)
        std::cerr << "error: " << r.name << ": " << r.message << "\n";
    return outcome.exitCode;
  }

  int exit = kPass;
  for (size_t k = 0; k < batch.cases.size(); ++k) {
    const auto& loaded = batch.cases[k];
    const auto& r = outcome.results.cases[k];
    if (r.status == run::CaseStatus::Error) {
      std::cout << "REFUSED " << r.name << ": " << r.message << "\n";
      exit = kRegression;
      continue;
    }
    bool invariantsFailed = false;
    for (const auto& inv : r.invariants)
      if (!inv.passed) {
        std::cout << "FAIL " << r.name << " invariant " << inv.name << ": " << inv.detail << "\n";
        invariantsFailed = true;
      }
    if (invariantsFailed && !a.has("--force")) {
      std::cout << "REFUSED " << r.name << ": invariants fail; fix the case or pass --force to bless anyway\n";
      exit = kRegression;
      continue;
    }
    if (!r.message.empty()) std::cout << "NOTE " << r.name << ": " << r.message << "\n";
    printChanges(r);
    const fs::path root = options.run.goldensRoot.empty() ? run::defaultGoldensRoot(loaded.spec.file)
                                                          : options.run.goldensRoot;
    const golden::GoldensLock lock(root);  // the old manifest stays current until the swap
    // The previous record only (its history continues); a bless replaces the images anyway,
    // so a set whose EXRs fail verification can be re-blessed, but not one whose manifest is lost.
    std::optional<golden::Manifest> previous;
    if (fs::exists(root / loaded.spec.name / "manifest.json"))
      previous = golden::readManifest(root / loaded.spec.name / "manifest.json");
    const auto& frames = outcome.outputs.at(loaded.spec.name);
    const auto manifest = golden::makeManifest(loaded, outcome.environment, frames,
                                               {r.frameSha256, r.frameSignatures}, reason,
                                               previous ? &*previous : nullptr);
    std::vector<std::pair<golden::GoldenFrame, Image>> files;
    for (const auto& gf : manifest.frames) files.emplace_back(gf, frames.at(gf.frame));
    golden::replaceGoldens(root, manifest, files);
    std::cout << "BLESSED " << r.name << ": " << manifest.frames.size() << " frame(s) in " << (root / r.name).string()
              << " (" << reason << ")\n";
  }
  return exit;
}

}  // namespace taa::cli
