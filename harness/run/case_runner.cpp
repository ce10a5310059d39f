#include "run/case_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "api/scene_loading.h"
#include "api/user_shader.h"
#include "case/case_loader.h"
#include "compare/metrics.h"
#include "golden/environment.h"
#include "lanes/lane_runner.h"
#include "run/build_identity.h"
#include "run/golden_check.h"
#include "run/invariant_run.h"
#include "run/reference_key.h"
#include "run/timing.h"

namespace taa::run {

namespace fs = std::filesystem;

fs::path defaultGoldensRoot(const fs::path& caseFile) {
  return fs::absolute(caseFile).parent_path().parent_path() / "goldens";
}

std::string goldensDigest(const spec::CheckedCase& spec, const fs::path& goldensRoot) {
  if (!spec.checks.golden) return "";
  return folderDigest((goldensRoot.empty() ? defaultGoldensRoot(spec.file) : goldensRoot) / spec.name);
}

namespace {

// The case's own lane: images are read for checked frames and for the frames the invariants
// judge with them (long warm-ups cost no read-back, nor reference renders, which run only for
// frames read back).
lanes::LaneSetup caseLane(Device& device, const spec::CaseSpec& spec, const scene::Scene& scene,
                          const InvariantRun& checks, const RunOptions& options,
                          bool hashEveryFrame) {
  lanes::LaneSetup lane{&spec, &scene, {}, {}};
  lane.options.hashEveryFrame = hashEveryFrame;
  lane.options.captures = checks.needs().captures;
  if (lane.options.captures.has(Capture::Reference))
    shareReferences(lane.options, options.references, spec, device.identity());
  const auto& checked = spec.output.frames;
  lane.reads = [&checks, &checked](int f) {
    return checks.readsImages(f) || std::binary_search(checked.begin(), checked.end(), f);
  };
  return lane;
}

double rmseAgainst(const Image& a, const Image& b) { return compare::computeMetrics(a, b).rmse; }

}  // namespace

CaseResult runCase(Device& device, const cases::LoadedCase& loaded, const RunOptions& options,
                   std::map<int, Image>* keep) {
  const auto start = std::chrono::steady_clock::now();
  const ShaderUseRecord shaders;  // every renderer of the case: replays and the A/B side
  const auto& spec = loaded.spec;
  CaseResult result;
  result.name = spec.name;
  result.file = spec.file.string();
  result.caseSha256 = loaded.sha256;
  result.goldensSha256 = goldensDigest(spec, options.goldensRoot);
  result.description = spec.description;
  result.resolve = describeUserShader(spec);
  result.status = CaseStatus::Pass;
  const auto env = golden::currentEnvironment(device.identity());
  result.fingerprint = env.fingerprint();
  fs::create_directories(RunFolder(options.outDir).caseFolder(spec.name));

  const auto scene = buildCaseScene(spec);
  InvariantRun checks(spec);
  // Goldens are loaded and verified before rendering, so every frame can be checked as it comes.
  std::optional<GoldenCheck> golden;
  if (spec.checks.golden) golden.emplace(spec, env, options);
  std::map<int, Image> outputs, abOutputs;
  const auto& checked = spec.output.frames;
  const auto isChecked = [&](int f) { return std::binary_search(checked.begin(), checked.end(), f); };
  // report.ab's B side (the case with the preset merged in, checked when the case loaded) is a
  // second lane of the same replay; its outputs of the checked frames are for the report only.
  cases::LoadedCase abSide;
  // Every frame's output is hashed for the goldens, and read for invariants that judge
  // warm-up frames too.
  std::vector<lanes::LaneSetup> sides{
      caseLane(device, spec, *scene, checks, options, golden.has_value() || checks.judgesWarmUp())};
  if (!loaded.abCase.empty() && options.writeImages) {
    abSide = cases::parseCase(loaded.abCase, spec.file);
    sides.push_back({&abSide.spec, nullptr, {}, isChecked});
  }
  const auto progress = [&](size_t lane, int f) {
    if (options.progress && lane == 0) options.progress(f, spec.script.frames);
  };
  {
    lanes::LaneRunner runner(device, std::move(sides));
    result.log = runner.log(0);
    runner.run(
        [&](lanes::LaneFrame& lf) {
          FrameRecord& r = lf.record;
          if (lf.lane == 1) {
            if (isChecked(r.frame)) abOutputs[r.frame] = std::move(r.color);
            return;
          }
          for (const auto& [name, value] : r.stats) result.frameStats[name].push_back(value);
          if (r.hasImages && r.hasReference)
            result.referenceRmse.push_back(rmseAgainst(r.reference, r.color));
          if (golden) golden->observe(r);
          checks.observe(invariants::FrameView::of(r));
          if (isChecked(r.frame)) outputs[r.frame] = std::move(r.color);
        },
        0, progress);
    result.frameMs = runner.cost(0).frameMs;
    result.timings = runner.cost(0).passes.summary();
    result.framesRendered += spec.script.frames * int(runner.size());
  }
  if (checks.needs().secondRun) {
    lanes::LaneRunner repeat(
        device, {caseLane(device, spec, *scene, checks, options, checks.judgesWarmUp())});
    repeat.run([&](lanes::LaneFrame& lf) { checks.observeRepeat(invariants::FrameView::of(lf.record)); }, 0,
               progress);
    result.framesRendered += spec.script.frames;
  }

  // The case's status is the worst of its checks: a failed invariant fails the case whether
  // its goldens are missing, stale or match.
  for (const auto& o : checks.finish()) {
    result.invariants.push_back({o.name, o.passed, o.detail, o.values});
    if (!o.passed) result.status = CaseStatus::Fail;
  }
  if (golden) {
    result.goldenStatus = golden->finish(outputs, loaded.sha256, result);
    result.status = worse(result.status, result.goldenStatus);
    for (auto& fc : result.frames)
      if (const auto it = abOutputs.find(fc.frame);
          it != abOutputs.end() && !fc.images.actual.empty())
        writeAbImages(RunFolder(options.outDir), spec.name, fc, it->second,
                      "preset " + spec.report.ab);
  } else if (options.writeImages) {
    for (const auto& [frame, image] : outputs) {
      FrameComparison fc;
      fc.frame = frame;
      fc.status = FrameStatus::MissingGolden;
      writeFrameImages(RunFolder(options.outDir), spec.name, fc, image, nullptr, nullptr,
                       spec.report.zoom);
    }
  }
  std::string used = "shaders:";
  for (const auto& name : shaders.names()) used += " " + name;
  result.log.push_back(used);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (keep) *keep = std::move(outputs);
  return result;
}

}  // namespace taa::run
