// Joining the outputs of `run --shard I/N` into the results of one run: the cases of every
// shard in case order, as the unsharded run would have listed them. Shards must come from one
// commit, one environment and one case set, each present once and run to the end.
#pragma once

#include <filesystem>
#include <vector>

#include "run/results.h"
#include "run/run_folder.h"

namespace taa::run {

// Why shards cannot be merged, naming the shard folders and the fix: bad input (exit 2), the
// shards' folders being the command's arguments.
class MergeError : public RunFolderError {
 public:
  using RunFolderError::RunFolderError;
};

struct ShardOutput {
  std::filesystem::path dir;  // the shard's --out folder
  RunResults results;         // its results.json
};

// Every image path a case's results give (relative to the run's output folder), empty ones
// left out: what the merged report links to, so each must be a file of the shard's own folder.
std::vector<std::string> imagePathsOf(const CaseResult& c);

// The shards' cases in case order, with the suite's record of an unsharded run (shard 1/1).
// Throws MergeError when the shards differ in commit, build, device, environment or case set,
// when a shard is given twice, stopped early (--fail-fast) or missing.
RunResults mergeShards(const std::vector<ShardOutput>& shards);

}  // namespace taa::run
