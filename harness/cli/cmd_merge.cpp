#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "cli/run_cases.h"
#include "core/output_file.h"
#include "report/html_report.h"
#include "report/junit.h"
#include "run/console.h"
#include "run/merge.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kMergeUsage =
    "taa-harness merge OUT1 OUT2 ... --out DIR\n"
    "  joins the outputs of `run --shard I/N` (each shard's --out folder) into DIR: one\n"
    "  results.json, junit.xml and report.html with every case in case order, as one unsharded\n"
    "  run writes them, and the cases' images. Refuses (exit 2) shards of different commits,\n"
    "  drivers or case sets, a shard given twice or stopped by --fail-fast, and names a missing one.\n"
    "exit: 0 every case passed, 1 a case failed or erred, 2 the shards do not merge";

bool sameFolder(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}
}  // namespace

int cmdMerge(const Args& args) {
  const auto a = parseArgs(args, {}, {"--out"}, kMergeUsage);
  if (a.positional.empty()) throw UsageError(std::string("no shard output given\nusage: ") + kMergeUsage);
  if (!a.values.count("--out"))
    throw UsageError(std::string("--out DIR is required\nusage: ") + kMergeUsage);
  const fs::path out = a.value("--out");
  std::vector<run::ShardOutput> shards;
  for (const auto& dir : a.positional) {
    if (sameFolder(dir, out))
      throw UsageError("--out " + out.string() + " is the shard output " + dir +
                       ": merge into a new folder, e.g. --out out/merged");
    shards.push_back({dir, readResultsFile(fs::path(dir) / "results.json",
                                           "pass the --out folder of a `taa-harness run --shard`")});
  }
  run::RunResults merged;
  try {
    merged = run::mergeShards(shards);
  } catch (const run::MergeError& e) {
    throw UsageError(e.what());
  }
  createOutputDirectory(out);
  // Each case's images, at the paths its results give relative to the output folder.
  for (const auto& s : shards)
    for (const auto& c : s.results.cases) {
      const fs::path from = fs::path(s.dir) / c.name;
      if (fs::is_directory(from))
        fs::copy(from, out / c.name, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    }
  writeFileAtomically(out / "results.json", run::toJson(merged).dump(1) + "\n");
  report::writeJUnit(out / "junit.xml", merged);
  report::writeHtmlReport(out / "report.html", merged);
  bool failed = false;
  double seconds = 0.0;
  for (const auto& c : merged.cases) {
    run::printCase(std::cout, c);
    failed |= run::caseFailed(c);
    seconds += c.seconds;
  }
  run::printSummary(std::cout, merged, seconds);
  std::cout << "merge: " << shards.size() << " shard(s) of " << merged.suite.cases.size()
            << " cases; the summary's time is the cases' own, added up\n";
  std::cout << "report: " << (out / "report.html").string() << "\n";
  return failed ? kRegression : kPass;
}

}  // namespace taa::cli
