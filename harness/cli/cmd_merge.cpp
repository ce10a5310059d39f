#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "report/html_report.h"
#include "report/junit.h"
#include "run/console.h"
#include "run/merge.h"
#include "run/results_seal.h"
#include "run/run_folder.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kMergeUsage =
    "taa-harness merge OUT1 OUT2 ... --out DIR\n"
    "  joins the outputs of `run --shard I/N` (each shard's --out folder) into DIR: one\n"
    "  results.json, junit.xml and report.html with every case in case order, as one unsharded\n"
    "  run writes them, and the cases' images. Refuses (exit 2) shards of different commits,\n"
    "  builds, devices, drivers or case sets, a shard given twice or stopped by --fail-fast, and "
    "names a missing one.\n"
    "exit: 0 every case passed, 1 a case failed or erred, 2 the shards do not merge";

// Where `p` leads, links resolved as far as it exists.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

// --out must be a folder of its own: the shard itself or a folder inside one would have the
// shard's files overwritten while they are copied (and a later merge read the merged files).
void refuseOutInShard(const fs::path& out, const fs::path& shard) {
  const fs::path o = resolved(out), s = resolved(shard);
  if (o == s || isInsideFolder(s, o))
    throw UsageError("--out " + out.string() + " is inside the shard output " + shard.string() +
                     ": merge into a folder of its own, e.g. --out out/merged");
}

// Copies the case folder `rel` of a shard into OUT: only regular files and folders, each read
// under the run folder's input-path rule; a link, FIFO or device there is no output of `run`,
// so the shard is refused (exit 2) rather than read through.
void copyCaseFolder(const run::RunFolder& shard, const fs::path& rel, const fs::path& out) {
  std::error_code ec;
  const fs::path from = shard.root() / rel;
  const auto st = fs::symlink_status(from, ec);
  if (fs::is_symlink(st))
    throw UsageError(from.string() +
                     " is a symbolic link; a shard's case folders are "
                     "folders `run` wrote: rerun that shard");
  if (!fs::is_directory(st)) return;
  createOutputDirectory(out / rel);
  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(from)) entries.push_back(e.path().filename());
  std::sort(entries.begin(), entries.end());
  for (const auto& name : entries) {
    const fs::path child = rel / name;
    if (fs::is_directory(fs::symlink_status(shard.root() / child, ec))) {
      copyCaseFolder(shard, child, out);
      continue;
    }
    writeFileAtomically(out / child, shard.readFile(child, "a file of the shard's case folder",
                                                    "rerun that shard"));
  }
}

// Every image the shard's results name lies in the shard's folder, as a regular file: a forged
// path ("../../etc/passwd") would otherwise go into the merged report as a link.
void checkImagePaths(const run::ShardOutput& s) {
  for (const auto& c : s.results.cases)
    for (const auto& image : run::imagePathsOf(c)) {
      const fs::path p(image);
      if (p.is_absolute() || std::find(p.begin(), p.end(), "..") != p.end() ||
          p.begin() == p.end() || *p.begin() != c.name)
        throw UsageError(run::RunFolder(s.dir).resultsFile().string() + ": case " + c.name + ": image path '" +
                         image.substr(0, 200) + "' is not inside the case's folder " + c.name +
                         "/: the file was edited, or not written by `run`; rerun that shard");
      run::RunFolder(s.dir).checkFile(p, "case " + c.name + "'s image", "rerun that shard");
    }
}
}  // namespace

int cmdMerge(const Args& args) {
  const auto a = parseArgs(args, {}, {"--out"}, kMergeUsage);
  if (a.positional.empty())
    throw UsageError(std::string("no shard output given\nusage: ") + kMergeUsage);
  if (!a.values.count("--out"))
    throw UsageError(std::string("--out DIR is required\nusage: ") + kMergeUsage);
  const run::RunFolder merged(a.value("--out"));
  const fs::path& out = merged.root();
  std::vector<run::ShardOutput> shards;
  std::string unsealed;  // why the merged results cannot be sealed, "" when they can
  for (const auto& dir : a.positional) refuseOutInShard(out, dir);
  for (const auto& dir : a.positional) {
    const run::RunFolder shard(dir);
    const std::string fix = "pass the --out folder of a `taa-harness run --shard`";
    const std::string text = shard.readResultsText(fix);
    // The merged file is sealed only when every shard's is: merging must not launder an
    // edited shard into a file a later --verdict-from trusts.
    if (const std::string why = run::sealProblem(shard.resultsFile(), text);
        !why.empty() && unsealed.empty())
      unsealed = why;
    shards.push_back({dir, shard.parseResults(text, fix)});
  }
  const run::RunResults results = run::mergeShards(shards);  // MergeError: bad input, exit 2
  for (const auto& s : shards) checkImagePaths(s);
  createOutputDirectory(out);
  // Each case's images, at the paths its results give relative to the output folder.
  for (const auto& s : shards)
    for (const auto& c : s.results.cases) copyCaseFolder(run::RunFolder(s.dir), c.name, out);
  const std::string text = run::toJson(results).dump(1) + "\n";
  if (unsealed.empty())
    unsealed = run::writeSealedResults(merged.resultsFile(), text);
  else
    run::writeUnsealedResults(merged.resultsFile(), text);
  if (!unsealed.empty())
    std::cerr << "note: " << merged.resultsFile().string() << " is not sealed (" << unsealed
              << "); a later run --verdict-from renders its cases instead of reusing them\n";
  report::writeJUnit(merged.junitFile(), results);
  report::writeHtmlReport(merged.reportFile(), results);
  bool failed = false;
  double seconds = 0.0;
  for (const auto& c : results.cases) {
    run::printCase(std::cout, c);
    failed |= run::caseFailed(c);
    seconds += c.seconds;
  }
  run::printSummary(std::cout, results, seconds);
  std::cout << "merge: " << shards.size() << " shard(s) of " << results.suite.cases.size()
            << " cases; the summary's time is the cases' own, added up\n";
  std::cout << "report: " << merged.reportFile().string() << "\n";
  return failed ? kRegression : kPass;
}

}  // namespace taa::cli
