#include "run/case_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "compare/metrics.h"
#include "golden/environment.h"
#include "invariants/invariant.h"
#include "renderer.h"
#include "run/golden_check.h"
#include "run/timing.h"
#include "scene/build_scene.h"

namespace taa::run {

namespace fs = std::filesystem;

fs::path defaultGoldensRoot(const fs::path& caseFile) {
  return fs::absolute(caseFile).parent_path().parent_path() / "goldens";
}

namespace {

const Image* findAux(const FrameRecord& r, const char* name) {
  for (const auto& a : r.aux)
    if (a.name == name) return &a.image;
  return nullptr;
}

invariants::FrameView viewOf(const FrameRecord& r) {
  invariants::FrameView v;
  v.frame = r.frame;
  v.historyReset = r.historyReset;
  v.output = r.hasImages ? &r.color : nullptr;
  v.reference = r.hasReference ? &r.reference : nullptr;
  v.current = findAux(r, "current");
  v.ids = findAux(r, "material_id");
  v.velocity = findAux(r, "velocity");
  v.resolved = findAux(r, "taa_resolve");
  v.segmentation = findAux(r, "segmentation");
  v.cmaa = findAux(r, "cmaa");
  v.edgeMask = findAux(r, "tscmaa_mask");
  v.sha256 = r.colorSha256;
  return v;
}

struct Plan {
  std::vector<std::unique_ptr<invariants::Invariant>> invariants;
  invariants::Needs needs;
  bool everyFrame = false;
};

Plan planChecks(const spec::CaseSpec& spec) {
  Plan p;
  for (auto kind : spec.checks.invariants) {
    const auto n = invariants::needsOf(kind);
    p.needs.reference |= n.reference;
    p.needs.current |= n.current;
    p.needs.ids |= n.ids;
    p.needs.velocity |= n.velocity;
    p.needs.tscmaa |= n.tscmaa;
    p.needs.secondRun |= n.secondRun;
    p.needs.adaptive |= n.adaptive;
    p.invariants.push_back(invariants::makeInvariant(kind, spec));
  }
  p.everyFrame = !p.invariants.empty();
  return p;
}

// Renders the case once, handing every frame to `each`; images are read for checked
// frames and, when invariants look at the sequence, for every frame.
void replay(vk::Context& ctx, const spec::CaseSpec& spec, const scene::Scene& scene,
            const Plan& plan, const RunOptions& options, bool hashEveryFrame,
            const std::function<void(FrameRecord&)>& each, std::vector<std::string>* log) {
  RenderOptions ro;
  ro.hashEveryFrame = hashEveryFrame;
  ro.reference = plan.needs.reference;
  ro.captureCurrent = plan.needs.current;
  ro.captureIds = plan.needs.ids;
  ro.captureVelocity = plan.needs.velocity;
  ro.captureAdaptive = plan.needs.adaptive;
  ro.captureTscmaa = plan.needs.tscmaa;
  Renderer renderer(ctx, spec, scene, ro);
  if (log) *log = renderer.log();
  const auto& checked = spec.output.frames;
  for (int f = 0; f < spec.script.frames; ++f) {
    if (options.progress) options.progress(f, spec.script.frames);
    // Invariants look at frames from checks.from_frame on; long warm-ups cost no read-back
    // (nor reference renders, which run only for frames read back).
    const bool wanted = (plan.everyFrame && f >= spec.checks.from_frame) ||
                        std::binary_search(checked.begin(), checked.end(), f);
    FrameRecord r = renderer.renderFrame(f, wanted);
    each(r);
  }
}

double rmseAgainst(const Image& a, const Image& b) { return compare::computeMetrics(a, b).rmse; }

}  // namespace

CaseResult runCase(vk::Context& ctx, const cases::LoadedCase& loaded, const RunOptions& options,
                   std::map<int, Image>* keep) {
  const auto start = std::chrono::steady_clock::now();
  const auto& spec = loaded.spec;
  CaseResult result;
  result.name = spec.name;
  result.file = spec.file.string();
  result.description = spec.description;
  result.status = CaseStatus::Pass;
  const auto env = golden::currentEnvironment(ctx.info());
  result.fingerprint = env.fingerprint();
  fs::create_directories(options.outDir / spec.name);

  const scene::Scene scene = scene::buildScene(spec);
  Plan plan = planChecks(spec);
  // Goldens are loaded and verified before rendering, so every frame can be checked as it comes.
  std::optional<GoldenCheck> golden;
  if (spec.checks.golden) golden.emplace(spec, env, options);
  std::map<int, Image> outputs;
  TimingLog timing;
  const auto& checked = spec.output.frames;
  replay(
      ctx, spec, scene, plan, options, golden.has_value(),
      [&](FrameRecord& r) {
        timing.add(r.gpuMs);
        result.frameMs.push_back(frameMilliseconds(r.gpuMs));
        for (const auto& [name, value] : r.stats) result.frameStats[name].push_back(value);
        if (r.hasImages && r.hasReference)
          result.referenceRmse.push_back(rmseAgainst(r.reference, r.color));
        if (golden) golden->observe(r);
        const auto view = viewOf(r);
        if (r.frame >= spec.checks.from_frame)
          for (auto& inv : plan.invariants) inv->observe(view);
        if (std::binary_search(checked.begin(), checked.end(), r.frame))
          outputs[r.frame] = std::move(r.color);
      },
      &result.log);
  if (plan.needs.secondRun) {
    replay(
        ctx, spec, scene, plan, options, false,
        [&](FrameRecord& r) {
          const auto view = viewOf(r);
          if (r.frame >= spec.checks.from_frame)
            for (auto& inv : plan.invariants) inv->observeRepeat(view);
        },
        nullptr);
  }
  result.timings = timing.summary();

  // The case's status is the worst of its checks: a failed invariant fails the case whether
  // its goldens are missing, stale or match.
  for (auto& inv : plan.invariants) {
    const auto o = inv->finish();
    result.invariants.push_back({o.name, o.passed, o.detail, o.values});
    if (!o.passed) result.status = CaseStatus::Fail;
  }
  if (golden) {
    result.status = worse(result.status, golden->finish(outputs, loaded.sha256, result));
  } else if (options.writeImages) {
    for (const auto& [frame, image] : outputs) {
      FrameComparison fc;
      fc.frame = frame;
      fc.status = FrameStatus::MissingGolden;
      writeFrameImages(options.outDir / spec.name, spec.name, fc, image, nullptr, nullptr);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (keep) *keep = std::move(outputs);
  return result;
}

}  // namespace taa::run
