#include "cli/run_cases.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>

#include "case/case_error.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/image_io.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "device.h"
#include "device_error.h"
#include "golden/environment.h"
#include "golden/golden_store.h"
#include "run/console.h"
#include "scene/scene_error.h"

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

std::function<void(int, int)> terminalProgress(const std::string& name, size_t index, size_t count) {
  if (!isatty(STDERR_FILENO)) return {};
  return [name, index, count](int f, int frames) {
    std::cerr << "\r[" << index + 1 << "/" << count << "] " << name << " frame " << f + 1 << "/" << frames
              << "\033[K" << std::flush;
    if (f + 1 == frames) std::cerr << "\r\033[K" << std::flush;
  };
}

}  // namespace

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
  if (!problems.empty()) throw cases::CaseError(problems);
  if (batch.cases.empty()) throw UsageError("no case files found in the given paths");
  if (!shard.empty()) {
    const auto [i, n] = parseShard(shard);
    CaseBatch mine;
    for (size_t k = 0; k < batch.cases.size(); ++k)
      if (int(k % size_t(n)) == i - 1) mine.cases.push_back(std::move(batch.cases[k]));
    return mine;
  }
  return batch;
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
  DeviceOptions co;
  co.device = options.device;
  co.validate = options.validate;
  Device device(co);
  out.results.device = device.identity().name;
  out.environment = golden::currentEnvironment(device.identity());
  out.results.fingerprint = out.environment.fingerprint();
  bool regression = false, badInput = false;
  for (size_t k = 0; k < batch.cases.size(); ++k) {
    const auto& loaded = batch.cases[k];
    run::RunOptions ro = options.run;
    ro.progress = terminalProgress(loaded.spec.name, k, batch.cases.size());
    run::CaseResult result;
    try {
      const int before = device.validationMessages();
      std::map<int, Image>* keep = keepOutputs ? &out.outputs[loaded.spec.name] : nullptr;
      result = run::runCase(device, loaded, ro, keep);
      if (device.validationMessages() > before) {
        result.status = run::CaseStatus::Fail;
        result.message += std::string(result.message.empty() ? "" : "; ") +
                          std::to_string(device.validationMessages() - before) +
                          " validation message(s) (see stderr)";
      }
    } catch (const scene::SceneError& e) {
      result.name = loaded.spec.name;
      result.file = loaded.spec.file.string();
      result.status = run::CaseStatus::Error;
      result.message = e.what();
      badInput = true;
    } catch (const UnsupportedSettingError& e) {
      // A setting this device lacks (render.msaa): the case must change, as for a bad scene.
      result.name = loaded.spec.name;
      result.file = loaded.spec.file.string();
      result.status = run::CaseStatus::Error;
      result.message = e.what();
      badInput = true;
    } catch (const ImageWriteError&) {
      throw;  // the disk, not the case: exit 3, not a regression
    } catch (const OutputError&) {
      throw;
    } catch (const fs::filesystem_error&) {
      throw;
    } catch (const ImageIoError& e) {
      result.name = loaded.spec.name;
      result.file = loaded.spec.file.string();
      result.status = run::CaseStatus::Error;
      result.message = e.what();
      regression = true;
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const EnvironmentError*>(&e) || dynamic_cast<const DeviceError*>(&e)) throw;
      result.name = loaded.spec.name;
      result.file = loaded.spec.file.string();
      result.status = run::CaseStatus::Error;
      result.message = e.what();
      regression = true;
    }
    regression |= run::caseFailed(result);
    if (onCase) onCase(result);
    out.results.cases.push_back(std::move(result));
    if (options.failFast && (regression || badInput)) {
      out.notRun = batch.cases.size() - k - 1;
      break;
    }
  }
  out.exitCode = badInput ? kBadInput : regression ? kRegression : kPass;
  return out;
}

}  // namespace taa::cli
