#include "run/case_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "compare/heatmap.h"
#include "compare/metrics.h"
#include "compare/tolerance.h"
#include "core/image_io.h"
#include "golden/environment.h"
#include "golden/golden_store.h"
#include "invariants/invariant.h"
#include "renderer.h"
#include "run/timing.h"
#include "scene/build_scene.h"

namespace taa::run {

namespace fs = std::filesystem;

fs::path defaultGoldensRoot(const fs::path& caseFile) {
  return fs::absolute(caseFile).parent_path().parent_path() / "goldens";
}

namespace {

std::string frameBase(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "frame_%04d", frame);
  return buf;
}

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
void replay(vk::Context& ctx, const spec::CaseSpec& spec, const scene::Scene& scene, const Plan& plan,
            const RunOptions& options, const std::function<void(FrameRecord&)>& each, std::vector<std::string>* log) {
  RenderOptions ro;
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

void writeFrameImages(const fs::path& caseDir, const std::string& rel, FrameComparison& fc, const Image& actual,
                      const Image* golden, const Image* errorMap) {
  const std::string base = frameBase(fc.frame);
  writeExr(caseDir / (base + ".exr"), actual);
  writePng(caseDir / (base + ".png"), actual);
  fc.images.actual = rel + "/" + base + ".png";
  if (!golden) return;
  writePng(caseDir / (base + ".golden.png"), *golden);
  fc.images.golden = rel + "/" + base + ".golden.png";
  if (!errorMap) return;
  writePngLinear8(caseDir / (base + ".diff.png"), compare::heatmap(*errorMap));
  fc.images.diff = rel + "/" + base + ".diff.png";
  // The worst tenth of the frame, magnified so single pixels are visible.
  const int w = std::max(1, std::min(actual.width, std::max(8, actual.width / 10)));
  const int h = std::max(1, std::min(actual.height, std::max(8, actual.height / 10)));
  const auto region = compare::worstRegion(*errorMap, w, h);
  const int zoom = std::max(1, 256 / w);
  auto zoomed = [&](const Image& img) {
    return compare::upscaleNearest(compare::crop(img, region.x, region.y, region.width, region.height), zoom);
  };
  writePng(caseDir / (base + ".zoom_golden.png"), zoomed(*golden));
  writePng(caseDir / (base + ".zoom_actual.png"), zoomed(actual));
  writePngLinear8(caseDir / (base + ".zoom_diff.png"), zoomed(compare::heatmap(*errorMap)));
  fc.images.zoomGolden = rel + "/" + base + ".zoom_golden.png";
  fc.images.zoomActual = rel + "/" + base + ".zoom_actual.png";
  fc.images.zoomDiff = rel + "/" + base + ".zoom_diff.png";
  fc.images.zoomX = region.x;
  fc.images.zoomY = region.y;
  fc.images.zoomW = region.width;
  fc.images.zoomH = region.height;
}

std::string blessCommandFor(const spec::CaseSpec& spec) {
  return "taa-harness bless " + spec.file.string() + " --reason \"<why the image changed>\"";
}

void compareWithGoldens(const spec::CaseSpec& spec, const std::map<int, Image>& outputs,
                        const std::map<int, std::string>& hashes, const golden::Environment& env,
                        const RunOptions& options, const std::string& caseSha, CaseResult& result) {
  const fs::path root = options.goldensRoot.empty() ? defaultGoldensRoot(spec.file) : options.goldensRoot;
  const fs::path caseDir = options.outDir / spec.name;
  const auto goldens = golden::loadGoldens(root, spec.name);
  result.blessCommand = blessCommandFor(spec);
  if (!goldens) {
    result.status = CaseStatus::NoGolden;
    result.message = "no goldens in " + (root / spec.name).string() + "; look at the frames, then bless them";
    for (const auto& [frame, image] : outputs) {
      FrameComparison fc;
      fc.frame = frame;
      fc.status = FrameStatus::MissingGolden;
      fc.actualSha256 = hashes.at(frame);
      if (options.writeImages) writeFrameImages(caseDir, spec.name, fc, image, nullptr, nullptr);
      result.frames.push_back(std::move(fc));
    }
    return;
  }
  const auto& m = goldens->manifest;
  result.goldenFingerprint = m.environment.fingerprint();
  const bool sameEnvironment = result.goldenFingerprint == env.fingerprint();
  bool anyFailed = false;
  for (const auto& [frame, image] : outputs) {
    FrameComparison fc;
    fc.frame = frame;
    fc.actualSha256 = hashes.at(frame);
    fc.toleranceMode = !sameEnvironment;
    const golden::GoldenFrame* gf = m.find(frame);
    if (!gf) {
      fc.status = FrameStatus::MissingGolden;
      fc.failures.push_back("frame " + std::to_string(frame) + " is checked but was never blessed");
      anyFailed = true;
      if (options.writeImages) writeFrameImages(caseDir, spec.name, fc, image, nullptr, nullptr);
      result.frames.push_back(std::move(fc));
      continue;
    }
    fc.goldenSha256 = gf->sha256;
    const bool exact = fc.actualSha256 == gf->sha256;
    const Image goldenImage = goldens->load(*gf);
    if (!goldenImage.sameShape(image)) {
      fc.status = FrameStatus::Failed;
      fc.failures.push_back("size " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                            " differs from the golden's " + std::to_string(goldenImage.width) + "x" +
                            std::to_string(goldenImage.height));
      anyFailed = true;
      result.frames.push_back(std::move(fc));
      continue;
    }
    const auto measured = compare::measureAgainstGolden(goldenImage, image, spec.checks.tolerance.pixel_threshold);
    fc.metrics = measured.metrics;
    if (exact) {
      fc.status = FrameStatus::Exact;
    } else if (sameEnvironment) {
      // Same driver and CPU level: lavapipe reproduces bytes, so any change is real.
      fc.status = FrameStatus::Failed;
      fc.failures.push_back("pixels differ from the golden in the same environment (sha256 " +
                            fc.actualSha256.substr(0, 12) + " != " + gf->sha256.substr(0, 12) + ")");
    } else {
      fc.failures = compare::toleranceViolations(fc.metrics, spec.checks.tolerance);
      fc.status = fc.failures.empty() ? FrameStatus::WithinTolerance : FrameStatus::Failed;
    }
    anyFailed |= fc.status == FrameStatus::Failed;
    if (options.writeImages) writeFrameImages(caseDir, spec.name, fc, image, &goldenImage, &measured.errorMap);
    result.frames.push_back(std::move(fc));
  }
  const bool stale = m.caseSha256 != caseSha;
  if (stale) {
    result.message = "the case file (or a file it references) changed since its goldens were blessed (" +
                     m.bless.date + ", \"" +
                     m.bless.reason + "\")";
    if (anyFailed) result.status = CaseStatus::Stale;
  }
  if (anyFailed && !stale) result.status = CaseStatus::Fail;
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
  std::map<int, Image> outputs;
  std::map<int, std::string> hashes;
  TimingLog timing;
  const auto& checked = spec.output.frames;
  replay(ctx, spec, scene, plan, options, [&](FrameRecord& r) {
    timing.add(r.gpuMs);
    result.frameMs.push_back(frameMilliseconds(r.gpuMs));
    for (const auto& [name, value] : r.stats) result.frameStats[name].push_back(value);
    if (r.hasImages && r.hasReference) result.referenceRmse.push_back(rmseAgainst(r.reference, r.color));
    if (r.hasImages) hashes[r.frame] = r.colorSha256;
    const auto view = viewOf(r);
    if (r.frame >= spec.checks.from_frame)
      for (auto& inv : plan.invariants) inv->observe(view);
    if (std::binary_search(checked.begin(), checked.end(), r.frame)) outputs[r.frame] = std::move(r.color);
  }, &result.log);
  if (plan.needs.secondRun) {
    replay(ctx, spec, scene, plan, options, [&](FrameRecord& r) {
      const auto view = viewOf(r);
      if (r.frame >= spec.checks.from_frame)
        for (auto& inv : plan.invariants) inv->observeRepeat(view);
    }, nullptr);
  }
  result.timings = timing.summary();

  for (auto& inv : plan.invariants) {
    const auto o = inv->finish();
    result.invariants.push_back({o.name, o.passed, o.detail, o.values});
    if (!o.passed) result.status = CaseStatus::Fail;
  }
  if (spec.checks.golden) {
    const CaseStatus before = result.status;
    compareWithGoldens(spec, outputs, hashes, env, options, loaded.sha256, result);
    if (before == CaseStatus::Fail && result.status == CaseStatus::Pass) result.status = CaseStatus::Fail;
  } else if (options.writeImages) {
    for (const auto& [frame, image] : outputs) {
      FrameComparison fc;
      fc.frame = frame;
      fc.status = FrameStatus::MissingGolden;
      fc.actualSha256 = hashes[frame];
      writeFrameImages(options.outDir / spec.name, spec.name, fc, image, nullptr, nullptr);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (keep) *keep = std::move(outputs);
  return result;
}

}  // namespace taa::run
