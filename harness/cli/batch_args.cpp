#include "cli/batch_args.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "case/case_error.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/input_file.h"
#include "core/sha256.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {

// A folder's *.json files, each inside it after resolving links (a link leading out is
// refused unread); a file named on the command line is the user's choice and read as named.
std::vector<fs::path> expand(const std::vector<std::string>& paths,
                             std::vector<std::string>& problems) {
  std::vector<fs::path> files;
  for (const auto& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      const auto inDir = inputFilesIn(p, ".json", problems);
      files.insert(files.end(), inDir.begin(), inDir.end());
    } else {
      files.emplace_back(p);
    }
  }
  return files;
}

std::pair<int, int> parseShard(const std::string& shard) {
  const auto slash = shard.find('/');
  auto whole = [](const std::string& t) {
    if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos)
      return -1;
    return std::stoi(t);
  };
  if (slash != std::string::npos) {
    const int i = whole(shard.substr(0, slash)), n = whole(shard.substr(slash + 1));
    if (n >= 1 && i >= 1 && i <= n) return {i, n};
  }
  throw UsageError("--shard '" + shard + "': expected I/N with 1 <= I <= N <= 999999, e.g. --shard 2/4");
}

}  // namespace

bool requireExactFromEnvironment() {
  const char* v = std::getenv("TAA_REQUIRE_EXACT");
  if (!v || !*v || std::string(v) == "0") return false;
  if (std::string(v) == "1") return true;
  throw UsageError(std::string("TAA_REQUIRE_EXACT='") + v +
                   "': expected 1 (fail a case whose goldens have no positive for this "
                   "environment) or 0");
}

bool runningInCi() {
  const char* ci = std::getenv("CI");
  if (!ci) return false;
  std::string v = ci;
  for (auto& ch : v) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return v == "true" || v == "1" || v == "yes";
}

void refuseOutputInGoldens(const fs::path& out, const fs::path& goldensRoot) {
  // Symlinks resolved where the path exists, so "./goldens/../goldens/x" or a link is caught too.
  auto resolved = [](const fs::path& p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
    if (ec) r = fs::absolute(p).lexically_normal();
    return r.has_filename() ? r : r.parent_path();
  };
  const fs::path rel =
      resolved(out).lexically_relative(resolved(goldensRoot));  // "." itself, "../x" outside
  if (!rel.empty() && *rel.begin() != "..")
    throw UsageError(
        "--out " + out.string() + " is inside the goldens folder " + goldensRoot.string() +
        ": outputs there would overwrite goldens; pick another folder, e.g. --out out");
}

run::CaseBatch loadBatch(const std::vector<std::string>& paths, const std::string& shard) {
  run::CaseBatch batch;
  std::vector<std::string> problems;
  for (const auto& file : expand(paths, problems)) {
    try {
      batch.cases.push_back(cases::loadCase(file));
    } catch (const cases::CaseError& e) {
      problems.insert(problems.end(), e.problems().begin(), e.problems().end());
    }
  }
  std::map<std::string, std::string> files;  // name -> the first file of that name
  for (const auto& c : batch.cases) {
    const auto [it, fresh] = files.emplace(c.spec.name, c.spec.file.string());
    if (!fresh)
      problems.push_back(c.spec.file.string() + ": case " + c.spec.name + " is also " + it->second +
                         ": both would write their outputs to OUT/" + c.spec.name +
                         "/; rename one file or run them separately");
  }
  if (!problems.empty()) throw cases::CaseError(problems);
  if (batch.cases.empty()) throw UsageError("no case files found in the given paths");
  Sha256 suite;
  for (const auto& c : batch.cases) {
    batch.suite.cases.push_back(c.spec.name);
    for (const std::string* part : {&c.spec.name, &c.sha256}) suite.update(part->c_str(), part->size() + 1);
  }
  const auto digest = suite.finish();
  batch.suite.sha256 = toHex(digest.data(), digest.size());
  if (!shard.empty()) {
    const auto [i, n] = parseShard(shard);
    run::CaseBatch mine;
    mine.suite = batch.suite;
    mine.suite.shardIndex = i;
    mine.suite.shardCount = n;
    for (size_t k = 0; k < batch.cases.size(); ++k)
      if (int(k % size_t(n)) == i - 1) mine.cases.push_back(std::move(batch.cases[k]));
    if (mine.cases.empty())
      throw UsageError("--shard " + shard + ": shard " + std::to_string(i) + " of " + std::to_string(n) +
                       " holds no case (the suite has " + std::to_string(batch.cases.size()) +
                       "); use at most that many shards");
    return mine;
  }
  return batch;
}

int exitCodeOf(run::BatchVerdict verdict) {
  switch (verdict) {
    case run::BatchVerdict::Pass: return kPass;
    case run::BatchVerdict::Regression: return kRegression;
    case run::BatchVerdict::BadInput: return kBadInput;
  }
  return kEnvironment;
}

size_t parseJobs(const std::string& value) {
  if (value.empty()) return 0;
  size_t used = 0;
  long n = 0;
  try {
    n = std::stol(value, &used);
  } catch (const std::exception&) {
  }
  if (used != value.size() || n < 1 || n > 1024)
    throw UsageError("--jobs '" + value + "': expected a number of cases to run at once, 1 to 1024 "
                     "(e.g. -j 2; leave it out for one per core)");
  return size_t(n);
}

}  // namespace taa::cli
