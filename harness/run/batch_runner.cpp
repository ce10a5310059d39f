#include "run/batch_runner.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>

#include "api/device.h"
#include "api/reference_cache.h"
#include "api/reference_store.h"
#include "core/cpu_cores.h"
#include "core/errors.h"
#include "golden/bless.h"
#include "golden/golden_store.h"
#include "run/build_identity.h"
#include "run/console.h"
#include "run/ordered_run.h"
#include "run/run_folder.h"

namespace taa::run {

namespace fs = std::filesystem;

namespace {

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
  CaseResult result;
  bool regression = false;
  bool badInput = false;
  std::map<int, Image> outputs;  // when keepOutputs
};

CaseSlot runOne(Device& device, const cases::LoadedCase& loaded, const RunOptions& ro,
                bool keepOutputs) {
  CaseSlot slot;
  CaseResult& result = slot.result;
  auto failWith = [&](const std::string& message) {
    result.name = loaded.spec.name;
    result.file = loaded.spec.file.string();
    result.caseSha256 = loaded.sha256;
    result.status = CaseStatus::Error;
    result.message = message;
  };
  try {
    const int before = device.validationMessages();
    result = runCase(device, loaded, ro, keepOutputs ? &slot.outputs : nullptr);
    if (device.validationMessages() > before) {
      result.status = CaseStatus::Fail;
      result.message += std::string(result.message.empty() ? "" : "; ") +
                        std::to_string(device.validationMessages() - before) +
                        " validation message(s) (see stderr)";
    }
  } catch (const InputError& e) {
    // The case must change (a bad scene or image, a setting this device lacks): its result
    // says so and the batch goes on. Anything else (the machine, the disk, a bug) ends the
    // batch and reaches the dispatcher, the one place that turns an error into an exit code.
    failWith(e.what());
    slot.badInput = true;
  }
  slot.regression = caseFailed(result);
  return slot;
}

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
                      const std::function<void(const CaseResult&)>& onCase, bool keepOutputs) {
  std::set<fs::path> roots;
  for (const auto& c : batch.cases)
    roots.insert(options.run.goldensRoot.empty() ? defaultGoldensRoot(c.spec.file)
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
      buildIdentity(options.device, options.run.missingGoldenFails, options.run.requireExact);
  out.results.suite = batch.suite;
  out.workers = workers;
  TerminalProgress progress(workers, count);
  // --no-reference-cache: a cache that holds nothing and reads nothing from disk, so every
  // reference renders and the closing line still counts them.
  const auto store = options.shareReferences ? ReferenceStore::fromEnvironment(std::cerr) : nullptr;
  ReferenceCache references(options.shareReferences ? kDefaultReferenceMemoryBytes : 0, store.get());
  std::vector<CaseSlot> slots(count);
  bool regression = false, badInput = false;
  StagingFolder staging;
  if (!options.run.outDir.empty()) {
    staging.path = RunFolder(options.run.outDir).stagingFolder();
    fs::remove_all(staging.path);  // a run killed before its end
  }
  runOrdered(
      count, workers,
      [&](size_t w, size_t k) {
        RunOptions ro = options.run;
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
  out.verdict = badInput ? BatchVerdict::BadInput : regression ? BatchVerdict::Regression : BatchVerdict::Pass;
  return out;
}

}  // namespace taa::run
