#include "cli/run_cases.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "api/device.h"
#include "api/reference_cache.h"
#include "api/reference_store.h"
#include "case/case_error.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/contained_file.h"
#include "core/cpu_cores.h"
#include "core/errors.h"
#include "core/input_file.h"
#include "core/json_guard.h"
#include "core/sha256.h"
#include "golden/bless.h"
#include "golden/environment.h"
#include "golden/golden_store.h"
#include "run/build_identity.h"
#include "run/console.h"
#include "run/ordered_run.h"

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

// "\r[3/99] fence frame 12/24 | open_area frame 3/32" on a terminal: what each worker renders.
class TerminalProgress {
 public:
  TerminalProgress(size_t workers, size_t count)
      : on_(isatty(STDERR_FILENO) != 0), lanes_(workers), count_(count) {}

  std::function<void(int, int)> forCase(size_t worker, const std::string& name) {
    if (!on_) return {};
    return [this, worker, name](int f, int frames) {
      std::lock_guard<std::mutex> lock(mutex_);
      lanes_[worker] = f + 1 == frames ? "" : name + " frame " + std::to_string(f + 1) + "/" +
                                                  std::to_string(frames);
      draw();
    };
  }
  void caseDone() {
    if (!on_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    if (done_ == count_)
      std::cerr << "\r\033[K" << std::flush;
    else
      draw();
  }
  // Before a console line: the progress line goes, and comes back with the next frame.
  void clear() {
    if (!on_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    std::cerr << "\r\033[K" << std::flush;
  }

 private:
  void draw() {
    std::string line = "[" + std::to_string(done_) + "/" + std::to_string(count_) + "]";
    for (const auto& l : lanes_)
      if (!l.empty()) line += " " + l + " |";
    if (line.back() == '|') line.pop_back();
    std::cerr << "\r" << line << "\033[K" << std::flush;
  }
  bool on_;
  std::mutex mutex_;
  std::vector<std::string> lanes_;
  size_t count_, done_ = 0;
};

// One case's outcome as the batch keeps it until its turn in case order.
struct CaseSlot {
  run::CaseResult result;
  bool regression = false;
  bool badInput = false;
  std::map<int, Image> outputs;  // when keepOutputs
};

CaseSlot runOne(Device& device, const cases::LoadedCase& loaded, const run::RunOptions& ro,
                bool keepOutputs) {
  CaseSlot slot;
  run::CaseResult& result = slot.result;
  auto failWith = [&](const std::string& message) {
    result.name = loaded.spec.name;
    result.file = loaded.spec.file.string();
    result.caseSha256 = loaded.sha256;
    result.status = run::CaseStatus::Error;
    result.message = message;
  };
  try {
    const int before = device.validationMessages();
    result = run::runCase(device, loaded, ro, keepOutputs ? &slot.outputs : nullptr);
    if (device.validationMessages() > before) {
      result.status = run::CaseStatus::Fail;
      result.message += std::string(result.message.empty() ? "" : "; ") +
                        std::to_string(device.validationMessages() - before) +
                        " validation message(s) (see stderr)";
    }
  } catch (const InputError& e) {
    // The case must change (a bad scene or image, a setting this device lacks): exit 2.
    failWith(e.what());
    slot.badInput = true;
  } catch (const EnvironmentError&) {
    throw;  // the machine or the disk, not the case: exit 3, not a regression
  } catch (const fs::filesystem_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    failWith(e.what());
    slot.regression = true;
  }
  slot.regression |= run::caseFailed(result);
  return slot;
}

// Where a worker writes a case's images until the case's turn in case order comes: a case
// that --fail-fast drops after it started (with -j N) then leaves nothing in OUT, as with -j 1.
constexpr const char* kStagingFolder = ".taa-harness-in-progress";

// Moves every file under `from` to the same place under `to`, replacing a file there (as a
// case's writes into OUT/NAME/ replace an earlier run's), then removes `from`.
void moveInto(const fs::path& from, const fs::path& to) {
  if (!fs::exists(from)) return;
  fs::create_directories(to);
  for (const auto& e : fs::directory_iterator(from)) {
    const fs::path target = to / e.path().filename();
    if (e.is_directory() && !fs::is_symlink(e.path())) {
      moveInto(e.path(), target);
    } else {
      if (fs::is_directory(target)) fs::remove_all(target);
      fs::rename(e.path(), target);
    }
  }
  fs::remove(from);
}

// Removes the staging folder however the batch ends (a stop, an exception).
struct StagingFolder {
  fs::path path;
  ~StagingFolder() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

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

CaseBatch loadBatch(const std::vector<std::string>& paths, const std::string& shard) {
  CaseBatch batch;
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
    CaseBatch mine;
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

std::string readResultsText(const fs::path& results, const std::string& fix) {
  try {
    // Another run's folder: its results.json inside it after resolving links, regular, bounded.
    return readContainedFile(results.parent_path(), results.filename(), kMaxResultsFileBytes,
                             "the results file");
  } catch (const InputFileError& e) {
    throw UsageError(std::string(e.what()) + "; " + fix);
  }
}

run::RunResults parseResultsText(const std::string& text, const fs::path& results,
                                 const std::string& fix) {
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw UsageError(results.string() + ": " + problem);
  try {
    return run::runResultsFromJson(nlohmann::json::parse(text));
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(results.string() + ": not the results.json of a run (" +
                     jsonErrorWithoutContent(e.what()) + "); " + fix);
  } catch (const std::runtime_error& e) {
    throw UsageError(results.string() + ": " + e.what() + "; " + fix);
  }
}

run::RunResults readResultsFile(const fs::path& results, const std::string& fix) {
  return parseResultsText(readResultsText(results, fix), results, fix);
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

CpuTimes cpuTimes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
  return {seconds(u.ru_utime), seconds(u.ru_stime)};
}

std::string throughputLine(const BatchOutcome& outcome, double wallSeconds, const CpuTimes& before) {
  const CpuTimes now = cpuTimes();
  const double user = now.user - before.user, system = now.system - before.system;
  long frames = 0;
  for (const auto& c : outcome.results.cases) frames += c.framesRendered;
  char buf[400];
  std::snprintf(buf, sizeof(buf),
                "run: %ld frames in %.1f s (%.1f frames/s); CPU %.1f s (user %.1f, system %.1f), "
                "CPU/wall %.2f with %zu worker%s; pipelines: %zu compiled, %zu reused; "
                "references: %zu rendered, %zu from disk, %zu reused",
                frames, wallSeconds, wallSeconds > 0 ? double(frames) / wallSeconds : 0.0,
                user + system, user, system, wallSeconds > 0 ? (user + system) / wallSeconds : 0.0,
                outcome.workers, outcome.workers == 1 ? "" : "s", outcome.pipelinesCreated,
                outcome.pipelinesReused, outcome.referencesRendered, outcome.referencesFromDisk,
                outcome.referencesReused);
  return buf;
}

BatchOutcome runBatch(const CaseBatch& batch, const BatchOptions& options,
                      const std::function<void(const run::CaseResult&)>& onCase, bool keepOutputs) {
  std::set<fs::path> roots;
  for (const auto& c : batch.cases)
    roots.insert(options.run.goldensRoot.empty() ? run::defaultGoldensRoot(c.spec.file)
                                                 : options.run.goldensRoot);
  for (const auto& root : roots)
    for (const auto& note : golden::removeStaleStaging(root)) std::cerr << "note: " << note << "\n";
  BatchOutcome out;
  const size_t count = batch.cases.size();
  const size_t workers = std::max<size_t>(1, std::min(options.jobs ? options.jobs : availableCores(), count));
  // One device per worker: lavapipe runs a device's one queue on one thread, so cases on one
  // device would render one after another. Each device's pipeline cache serves every case
  // its worker runs.
  DeviceOptions co;
  co.device = options.device;
  co.validate = options.validate;
  co.devicesAtOnce = int(workers);
  std::vector<std::unique_ptr<Device>> devices;
  for (size_t w = 0; w < workers; ++w) devices.push_back(std::make_unique<Device>(co));
  out.results.device = devices[0]->identity().name;
  out.environment = golden::currentEnvironment(devices[0]->identity());
  out.results.fingerprint = out.environment.fingerprint();
  out.results.environment = out.environment;
  out.results.commit = golden::rendererCommit();
  out.results.build =
      run::buildIdentity(options.device, options.run.missingGoldenFails, options.run.requireExact);
  out.results.suite = batch.suite;
  out.workers = workers;
  TerminalProgress progress(workers, count);
  // --no-reference-cache: a cache that holds nothing and reads nothing from disk, so every
  // reference renders and the closing line still counts them.
  const auto store = options.shareReferences ? ReferenceStore::fromEnvironment(std::cerr) : nullptr;
  ReferenceCache references(options.shareReferences ? size_t(128) << 20 : 0, store.get());
  std::vector<CaseSlot> slots(count);
  bool regression = false, badInput = false;
  StagingFolder staging;
  if (!options.run.outDir.empty()) {
    staging.path = options.run.outDir / kStagingFolder;
    fs::remove_all(staging.path);  // a run killed before its end
  }
  run::runOrdered(
      count, workers,
      [&](size_t w, size_t k) {
        run::RunOptions ro = options.run;
        if (!staging.path.empty()) ro.outDir = staging.path;
        ro.references = &references;
        ro.progress = progress.forCase(w, batch.cases[k].spec.name);
        slots[k] = runOne(*devices[w], batch.cases[k], ro, keepOutputs);
        progress.caseDone();
      },
      [&](size_t k) {
        CaseSlot slot = std::move(slots[k]);
        regression |= slot.regression;
        badInput |= slot.badInput;
        progress.clear();
        if (!staging.path.empty())
          moveInto(staging.path / slot.result.name, options.run.outDir / slot.result.name);
        if (onCase) onCase(slot.result);
        if (keepOutputs) out.outputs[slot.result.name] = std::move(slot.outputs);
        out.results.cases.push_back(std::move(slot.result));
        if (options.failFast && (regression || badInput)) {
          out.notRun = out.results.notRun = count - k - 1;
          return false;
        }
        return true;
      });
  for (const auto& d : devices) {
    const auto p = d->pipelineCounts();
    out.pipelinesCreated += p.created;
    out.pipelinesReused += p.reused;
  }
  out.referencesRendered = references.stats().rendered;
  out.referencesFromDisk = references.stats().fromDisk;
  out.referencesReused = references.stats().reused;
  if (store) store->trim();
  out.exitCode = badInput ? kBadInput : regression ? kRegression : kPass;
  return out;
}

}  // namespace taa::cli
