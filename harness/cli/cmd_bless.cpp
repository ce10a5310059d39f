#include <stdlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>
#include <variant>

#include "cli/bless_source.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/batch_args.h"
#include "run/run_folder.h"
#include "compare/metric_table.h"
#include "core/output_file.h"
#include "golden/bless.h"
#include "golden/case_owner.h"
#include "golden/golden_store.h"
#include "run/add_environment.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kBlessUsage =
    "taa-harness bless CASE... --reason \"why the image changed\" [--force] [--goldens DIR] [--out "
    "DIR] [-j N]\n"
    "taa-harness bless --failed-from out/results.json --reason \"...\"   (re-bless what failed "
    "last run)\n"
    "taa-harness bless --from OUT [CASE...] [--failed-from OUT/results.json] --reason \"...\"\n"
    "taa-harness bless --add-environment CASE... --reason \"which machine\"   (also with --from "
    "OUT)\n"
    "  renders each case, runs its invariants (a failing invariant refuses the bless unless "
    "--force),\n"
    "  prints what changed against the old goldens, then replaces goldens/NAME/ atomically.\n"
    "  --from OUT takes the frames and hashes a run wrote to OUT (another machine's CI artifact)\n"
    "  instead of rendering: no Vulkan device needed; refused (exit 2) when OUT was made from "
    "other\n"
    "  case, scene, track or shader bytes, lacks a case or frame, or was altered.\n"
    "  --add-environment adds the positive of the environment that rendered the frames (this\n"
    "  machine, or OUT's) beside the others, keeping every image; refused when the case changed\n"
    "  since its bless or a frame lies outside its tolerances of the primary positive.\n"
    "  Without --out, a render's frames go to a new folder under $TMPDIR (printed).";

std::vector<std::string> failedCases(const fs::path& results) {
  std::vector<std::string> files;
  const auto earlier =
      run::RunFolder::ofResultsFile(results).readResults("pass the results.json of a previous run");
  for (const auto& c : earlier.cases)
    if (c.status != run::CaseStatus::Pass && c.status != run::CaseStatus::Error)
      files.push_back(c.file);
  return files;
}

void printChanges(const run::CaseResult& r) {
  if (r.firstDifference.frame >= 0)
    std::cout << "  " << r.name << " sequence: " << r.firstDifference.detail << "\n";
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

// A new folder for a render's frames: a bless run from a user's shader folder leaves nothing
// there.
fs::path temporaryOutput() {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern =
      (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/taa-bless-XXXXXX";
  if (!mkdtemp(pattern.data()))
    throw OutputError(pattern, std::string(std::strerror(errno)) +
                                   " (a folder for the bless's frames; pass --out DIR)");
  return pattern;
}

struct BlessPlan {
  std::string reason;
  bool force = false;
  bool addEnvironment = false;
  fs::path goldensRoot;  // empty: each case's default
};

// Blesses one case from `source`; returns its exit code (0, 1 for a refusal).
int blessOne(const cases::LoadedCase& loaded, const BlessSource& source, const BlessPlan& plan) {
  const auto& r = source.result;
  bool invariantsFailed = false;
  for (const auto& inv : r.invariants)
    if (!inv.passed) {
      std::cout << "FAIL " << r.name << " invariant " << inv.name << ": " << inv.detail << "\n";
      invariantsFailed = true;
    }
  if (invariantsFailed && !plan.force) {
    std::cout << "REFUSED " << r.name
              << ": invariants fail; fix the case or pass --force to bless anyway\n";
    return kRegression;
  }
  const fs::path root =
      plan.goldensRoot.empty() ? run::defaultGoldensRoot(loaded.spec.file) : plan.goldensRoot;
  const golden::GoldensLock lock(root);  // the old manifest stays current until the swap
  // The set's record, read once: a bless continues its history and keeps the positives that
  // render these frames, so an unreadable one is refused (GoldenError, naming how to restore it
  // or start over), as for --add-environment. Images that fail verification are replaced.
  std::optional<golden::Manifest> previous;
  if (const fs::path m = root / loaded.spec.name / "manifest.json"; fs::exists(m)) {
    previous = golden::readManifest(m);
    if (const std::string other = golden::otherCaseProblem(*previous, root, loaded.spec.file);
        !other.empty()) {
      std::cout << "REFUSED " << r.name << ": " << other << "\n";
      return kBadInput;
    }
  }
  if (plan.addEnvironment) {
    const auto set = golden::loadGoldens(root, loaded.spec.name);
    if (!set) {
      std::cout << "REFUSED " << r.name << ": no goldens in " << (root / loaded.spec.name).string()
                << " to add an environment to; bless it with a reason first\n";
      return kRegression;
    }
    run::PositiveCandidate candidate{{source.environment,
                                      {golden::todayUtc(), source.commit, plan.reason},
                                      source.digests.sha256,
                                      source.digests.signatures},
                                     &source.stored};
    const auto outcome = run::addEnvironment(loaded.spec, *set, loaded.sha256, candidate);
    const std::string fingerprint = source.environment.fingerprint();
    switch (outcome.kind) {
      case run::AddEnvironmentOutcome::Kind::Refused:
        std::cout << "REFUSED " << r.name << " environment " << fingerprint << ": "
                  << outcome.detail << "\n";
        return kRegression;
      case run::AddEnvironmentOutcome::Kind::AlreadyThere:
        std::cout << "UNCHANGED " << r.name << ": " << outcome.detail << "\n";
        return kPass;
      case run::AddEnvironmentOutcome::Kind::Added:
        break;
    }
    golden::replaceManifest(root, outcome.manifest);  // every image stays as it is
    std::cout << "ADDED " << r.name << " environment " << fingerprint << ": " << outcome.detail
              << " (" << plan.reason << ")\n";
    return kPass;
  }
  if (!r.message.empty()) std::cout << "NOTE " << r.name << ": " << r.message << "\n";
  printChanges(r);
  auto manifest = golden::makeManifest(loaded, source.environment, source.stored, source.digests,
                                       plan.reason, previous ? &*previous : nullptr);
  manifest.bless.commit = source.commit;
  // An earlier environment whose every frame hashes as this render's stays a positive (a bless
  // that changed no frame here, such as an input hash that now covers more files, keeps the
  // machines that render these same bytes); one of other frames goes with the old images.
  size_t dropped = 0;
  if (previous)
    for (const auto& p : previous->positives()) {
      if (p.environment.fingerprint() == manifest.environment.fingerprint()) continue;
      if (p.sequence == manifest.sequence && p.signatures.size() == manifest.sequence.size())
        manifest.others.push_back(p);
      else
        ++dropped;
    }
  std::vector<std::pair<golden::GoldenFrame, Image>> files;
  for (const auto& gf : manifest.frames) files.emplace_back(gf, source.stored.at(gf.frame));
  golden::replaceGoldens(root, manifest, files);
  std::cout << "BLESSED " << r.name << ": " << manifest.frames.size() << " frame(s) in "
            << (root / r.name).string() << " (" << plan.reason << ")\n";
  if (!manifest.others.empty())
    std::cout << "NOTE " << r.name << ": kept the positives of " << manifest.others.size()
              << " other environment(s) whose frames hash as this render's\n";
  if (dropped)
    std::cout << "NOTE " << r.name << ": the positives of " << dropped
              << " other environment(s) were dropped with the old frames; add them again "
                 "(bless --add-environment there, or bless --from a run there)\n";
  return kPass;
}

// Renders the batch here: its sources, or an exit code when the batch could not run.
std::variant<std::vector<BlessSource>, int> renderSources(const run::CaseBatch& batch,
                                                          const ParsedArgs& a,
                                                          const fs::path& goldensRoot) {
  run::BatchOptions options;
  options.run.outDir = a.values.count("--out") ? fs::path(a.value("--out")) : temporaryOutput();
  options.run.goldensRoot = goldensRoot;
  options.device = a.value("--device");
  options.jobs = parseJobs(a.value("--jobs"));
  for (const auto& c : batch.cases)
    refuseOutputInGoldens(options.run.outDir,
                          goldensRoot.empty() ? run::defaultGoldensRoot(c.spec.file) : goldensRoot);
  createOutputDirectory(options.run.outDir);
  if (!a.values.count("--out"))
    std::cout << "bless: this render's frames are in " << options.run.outDir.string() << "\n";
  auto outcome = run::runBatch(batch, options, nullptr, /*keepOutputs=*/true);
  if (outcome.verdict == run::BatchVerdict::BadInput) {
    // A scene that does not load (or a broken environment): say which case and why.
    for (const auto& r : outcome.results.cases)
      if (r.status == run::CaseStatus::Error)
        std::cerr << "error: " << r.name << ": " << r.message << "\n";
    return exitCodeOf(outcome.verdict);
  }
  std::vector<BlessSource> sources;
  for (auto& r : outcome.results.cases) {
    BlessSource s;
    s.environment = outcome.environment;
    s.commit = golden::rendererCommit();
    s.digests = {r.frameSha256, r.frameSignatures};
    s.stored = std::move(outcome.outputs[r.name]);
    s.result = std::move(r);
    sources.push_back(std::move(s));
  }
  return sources;
}
}  // namespace

int cmdBless(const Args& args) {
  const auto a =
      parseArgs(args, {"--force", "--add-environment"},
                {"--reason", "--goldens", "--out", "--failed-from", "--device", "--jobs", "--from"},
                kBlessUsage);
  BlessPlan plan;
  plan.reason = a.value("--reason");
  if (plan.reason.find_first_not_of(" \t") == std::string::npos)
    throw UsageError(
        "--reason is required: say why the images changed (it is stored in the manifest)\nusage: " +
        std::string(kBlessUsage));
  plan.force = a.has("--force");
  plan.addEnvironment = a.has("--add-environment");
  plan.goldensRoot = a.value("--goldens");
  const bool fromRun = a.values.count("--from") > 0;
  if (fromRun)
    for (const char* renderOnly : {"--out", "--device", "--jobs"})
      if (a.values.count(renderOnly))
        throw UsageError(std::string(renderOnly) +
                         " has no use with --from, which renders nothing; leave it out");
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
  const run::CaseBatch batch = loadBatch(paths, "");
  std::vector<BlessSource> sources;
  if (fromRun) {
    // Every case is checked before any golden is written: a refused folder changes nothing.
    const RunFolderSource folder(a.value("--from"));
    for (const auto& c : batch.cases) sources.push_back(folder.source(c));
  } else {
    auto rendered = renderSources(batch, a, plan.goldensRoot);
    if (const int* code = std::get_if<int>(&rendered)) return *code;
    sources = std::move(std::get<std::vector<BlessSource>>(rendered));
  }
  int exit = kPass;
  for (size_t k = 0; k < batch.cases.size(); ++k) {
    if (sources[k].result.status == run::CaseStatus::Error) {
      std::cout << "REFUSED " << sources[k].result.name << ": " << sources[k].result.message
                << "\n";
      exit = kRegression;
      continue;
    }
    exit = std::max(exit, blessOne(batch.cases[k], sources[k], plan));
  }
  return exit;
}

}  // namespace taa::cli
