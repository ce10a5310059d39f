#include "run/merge.h"

#include <map>
#include <string>

namespace taa::run {

namespace {

std::string shardName(const SuiteInfo& s) {
  return std::to_string(s.shardIndex) + "/" + std::to_string(s.shardCount);
}

// The cases of shard `index` (1-based) of `count` in a suite: every count-th from index - 1.
std::vector<std::string> casesOfShard(const SuiteInfo& suite, int index, int count) {
  std::vector<std::string> out;
  for (size_t k = size_t(index - 1); k < suite.cases.size(); k += size_t(count))
    out.push_back(suite.cases[k]);
  return out;
}

std::string someNames(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size() && i < 5; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 5) s += ", ... (" + std::to_string(names.size()) + " cases)";
  return s;
}

}  // namespace

std::vector<std::string> imagePathsOf(const CaseResult& c) {
  std::vector<std::string> out;
  auto add = [&out](const std::string& p) {
    if (!p.empty()) out.push_back(p);
  };
  for (const auto& f : c.frames)
    for (const std::string* p :
         {&f.images.golden, &f.images.actual, &f.images.diff, &f.images.zoomGolden,
          &f.images.zoomActual, &f.images.zoomDiff, &f.images.ab, &f.images.zoomAb})
      add(*p);
  add(c.firstDifference.actual);
  for (const auto& n : c.firstDifference.goldenNeighbours) add(n.image);
  return out;
}

RunResults mergeShards(const std::vector<ShardOutput>& shards) {
  if (shards.empty()) throw MergeError("no shard output given");
  for (const auto& s : shards)
    if (s.results.suite.cases.empty() || s.results.suite.sha256.empty())
      throw MergeError(s.dir.string() +
                       "/results.json records no suite (written by a taa-harness "
                       "older than `merge`, or not by `run`): rerun that shard");
  const ShardOutput& first = shards.front();
  const SuiteInfo& suite = first.results.suite;
  std::map<int, const ShardOutput*> byIndex;
  for (const auto& s : shards) {
    const RunResults& r = s.results;
    const std::string where = s.dir.string() + " (shard " + shardName(r.suite) + ")";
    const std::string firstWhere = first.dir.string() + " (shard " + shardName(suite) + ")";
    if (r.commit != first.results.commit)
      throw MergeError(where + " was run at commit " + r.commit + ", " + firstWhere + " at " +
                       first.results.commit + ": merge shards of one build");
    if (r.fingerprint != first.results.fingerprint)
      throw MergeError(where + " ran on '" + r.fingerprint + "', " + firstWhere + " on '" +
                       first.results.fingerprint +
                       "': goldens compare exactly in one environment only, so merge shards of "
                       "one driver and CPU level");
    // One build on one device: a shard of another executable, SPIR-V, CPU level or device
    // (a device asked for, or the one found) is another run, whatever its commit.
    if (r.build != first.results.build || r.build.empty())
      throw MergeError(where + " was made by the build '" + r.build + "', " + firstWhere + " by '" +
                       first.results.build + "': merge shards of one build");
    if (r.device != first.results.device)
      throw MergeError(where + " ran on device '" + r.device + "', " + firstWhere + " on '" +
                       first.results.device + "': merge shards of one device");
    if (r.suite.sha256 != suite.sha256 || r.suite.cases != suite.cases)
      throw MergeError(where + " ran another case set (" + std::to_string(r.suite.cases.size()) +
                       " cases) than " + firstWhere + " (" + std::to_string(suite.cases.size()) +
                       " cases, or the same names with other contents): run every shard on the "
                       "same case files");
    if (r.suite.shardCount != suite.shardCount)
      throw MergeError(where + " and " + firstWhere +
                       " split the suite differently: run every shard with the same --shard I/" +
                       std::to_string(suite.shardCount));
    if (const auto [it, fresh] = byIndex.emplace(r.suite.shardIndex, &s); !fresh)
      throw MergeError(where + " and " + it->second->dir.string() + " are both shard " +
                       shardName(r.suite) + ": pass each shard's output once");
    if (r.notRun > 0)
      throw MergeError(where +
                       " stopped at its first failure (--fail-fast): " + std::to_string(r.notRun) +
                       " of its cases were not run; rerun it without "
                       "--fail-fast");
    std::vector<std::string> names;
    for (const auto& c : r.cases) names.push_back(c.name);
    if (names != casesOfShard(suite, r.suite.shardIndex, r.suite.shardCount))
      throw MergeError(where + "/results.json lists other cases than shard " + shardName(r.suite) +
                       " of its suite: it was edited, or not written by `run`");
  }
  for (int i = 1; i <= suite.shardCount; ++i)
    if (!byIndex.count(i))
      throw MergeError(
          "shard " + std::to_string(i) + "/" + std::to_string(suite.shardCount) +
          " is missing (its cases: " + someNames(casesOfShard(suite, i, suite.shardCount)) +
          "): pass its output folder too");

  RunResults out;
  out.device = first.results.device;
  out.fingerprint = first.results.fingerprint;
  // Frames of several environments are no one environment's positive: bless --from refuses a
  // merged folder whose environment is left empty.
  out.environment = first.results.environment;
  for (const auto& s : shards)
    if (s.results.environment.fingerprint() != out.environment.fingerprint()) out.environment = {};
  out.commit = first.results.commit;
  out.build = first.results.build;
  out.suite = suite;
  out.suite.shardIndex = out.suite.shardCount = 1;
  // Case k of the suite is case k / N of shard k % N + 1.
  for (size_t k = 0; k < suite.cases.size(); ++k) {
    const int n = suite.shardCount;
    out.cases.push_back(byIndex.at(int(k % size_t(n)) + 1)->results.cases[k / size_t(n)]);
  }
  return out;
}

}  // namespace taa::run
