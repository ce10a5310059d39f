#include "run/case_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "api/renderer.h"
#include "case/case_loader.h"
#include "compare/metrics.h"
#include "golden/environment.h"
#include "run/golden_check.h"
#include "run/invariant_run.h"
#include "run/reference_key.h"
#include "run/timing.h"
#include "scene/build_scene.h"
#include "user/user_resolve.h"

namespace taa::run {

namespace fs = std::filesystem;

fs::path defaultGoldensRoot(const fs::path& caseFile) {
  return fs::absolute(caseFile).parent_path().parent_path() / "goldens";
}

namespace {

// Renders the case once, handing every frame to `each`; images are read for checked frames
// and for the frames the invariants judge with them.
void replay(Device& device, const spec::CaseSpec& spec, const scene::Scene& scene,
            const InvariantRun& checks, const RunOptions& options, bool hashEveryFrame,
            const std::function<void(FrameRecord&)>& each, std::vector<std::string>* log) {
  RenderOptions ro;
  ro.hashEveryFrame = hashEveryFrame;
  ro.captures = checks.needs().captures;
  if (ro.captures.has(Capture::Reference) && options.references) {
    ro.referenceCache = options.references;
    ro.referenceKey = referenceKey(spec);
  }
  Renderer renderer(device, spec, scene, ro);
  if (log) *log = renderer.log();
  const auto& checked = spec.output.frames;
  for (int f = 0; f < spec.script.frames; ++f) {
    if (options.progress) options.progress(f, spec.script.frames);
    // Long warm-ups cost no read-back (nor reference renders, which run only for frames
    // read back).
    const bool wanted =
        checks.readsImages(f) || std::binary_search(checked.begin(), checked.end(), f);
    FrameRecord r = renderer.renderFrame(f, wanted);
    each(r);
  }
}

double rmseAgainst(const Image& a, const Image& b) { return compare::computeMetrics(a, b).rmse; }

// report.ab: the B side (the case with the preset merged in, checked when the case loaded)
// replayed over the same frames; its outputs of the checked frames, for the report only.
std::map<int, Image> renderAbSide(Device& device, const cases::LoadedCase& loaded,
                                  const RunOptions& options) {
  const cases::LoadedCase b = cases::parseCase(loaded.abCase, loaded.spec.file);
  const scene::Scene scene = scene::buildScene(b.spec);
  Renderer renderer(device, b.spec, scene, RenderOptions{});
  const auto& checked = loaded.spec.output.frames;
  std::map<int, Image> out;
  for (int f = 0; f < b.spec.script.frames; ++f) {
    if (options.progress) options.progress(f, b.spec.script.frames);
    const bool wanted = std::binary_search(checked.begin(), checked.end(), f);
    FrameRecord r = renderer.renderFrame(f, wanted);
    if (wanted) out[f] = std::move(r.color);
  }
  return out;
}

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
  result.description = spec.description;
  result.resolve = describeUserShader(spec);
  result.status = CaseStatus::Pass;
  const auto env = golden::currentEnvironment(device.identity());
  result.fingerprint = env.fingerprint();
  fs::create_directories(options.outDir / spec.name);

  const scene::Scene scene = scene::buildScene(spec);
  InvariantRun checks(spec);
  // Goldens are loaded and verified before rendering, so every frame can be checked as it comes.
  std::optional<GoldenCheck> golden;
  if (spec.checks.golden) golden.emplace(spec, env, options);
  std::map<int, Image> outputs;
  TimingLog timing;
  const auto& checked = spec.output.frames;
  // Every frame's output is hashed for the goldens, and read for invariants that judge
  // warm-up frames too.
  replay(
      device, spec, scene, checks, options, golden.has_value() || checks.judgesWarmUp(),
      [&](FrameRecord& r) {
        timing.add(r.gpuMs);
        result.frameMs.push_back(frameMilliseconds(r.gpuMs));
        for (const auto& [name, value] : r.stats) result.frameStats[name].push_back(value);
        if (r.hasImages && r.hasReference)
          result.referenceRmse.push_back(rmseAgainst(r.reference, r.color));
        if (golden) golden->observe(r);
        checks.observe(invariants::FrameView::of(r));
        if (std::binary_search(checked.begin(), checked.end(), r.frame))
          outputs[r.frame] = std::move(r.color);
      },
      &result.log);
  result.framesRendered += spec.script.frames;
  if (checks.needs().secondRun) {
    replay(
        device, spec, scene, checks, options, checks.judgesWarmUp(),
        [&](FrameRecord& r) { checks.observeRepeat(invariants::FrameView::of(r)); }, nullptr);
    result.framesRendered += spec.script.frames;
  }
  result.timings = timing.summary();
  std::map<int, Image> abOutputs;
  if (!loaded.abCase.empty() && options.writeImages) {
    abOutputs = renderAbSide(device, loaded, options);
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
        writeAbImages(options.outDir / spec.name, spec.name, fc, it->second,
                      "preset " + spec.report.ab);
  } else if (options.writeImages) {
    for (const auto& [frame, image] : outputs) {
      FrameComparison fc;
      fc.frame = frame;
      fc.status = FrameStatus::MissingGolden;
      writeFrameImages(options.outDir / spec.name, spec.name, fc, image, nullptr, nullptr,
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
